// The composite 10-node tet (src/fem/composite_tet.h) against what its construction promises:
// the only deformations without strain energy are the six rigid motions (its projected strain
// controls all 24 deformation modes of one element, so no hourglass mode exists), and its table
// reproduces linear fields. Its patch test, stiffness symmetry and stable step run with the
// quadratic element's (test_quadratic_element.cpp); its physics (plane waves in the two bars,
// bending, rest) through the C API in tests/physics.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "common/math.h"
#include "fem/composite_tet.h"
#include "fem/stable_step.h"
#include "quadratic_box.h"

namespace lfem {
namespace {

using namespace test;

// One tet of no particular shape, its mid-edge nodes at the middle of its edges.
TetMesh one_quadratic_tet() {
    TetMesh m;
    m.positions = {0.01, -0.02, 0.0, 0.31, 0.05, 0.02, 0.07, 0.24, -0.03, 0.04, 0.06, 0.27};
    m.tets = {0, 1, 2, 3};
    return make_quadratic(m);
}

// The stiffness of one element at rest (dense, from the operator column by column): six zero
// eigenvalues (the rigid motions; round-off: 1e-10 of the largest) and 24 clearly positive ones
// (an hourglass mode would give a seventh near zero; the smallest deformation mode of this
// tet's composite element is about 1e-2 of the largest, the quadratic element's alike).
TEST(CompositeElement, OneTetHasNoZeroEnergyModeButTheRigidOnes) {
    for (bool composite : {false, true}) {
        const QuadraticBox box(one_quadratic_tet(), 64, composite);
        const Lame lame = lame_from_young_poisson(1e6, 0.3);
        const int n = 3 * int(box.nodes());
        ASSERT_EQ(n, 30);
        Eigen::MatrixXd K(n, n);
        std::vector<double> e(n, 0.0), Ke(n);
        for (int j = 0; j < n; ++j) {
            e[j] = 1.0;
            apply_reference_stiffness(box.view(), lame, e.data(), Ke.data());
            for (int i = 0; i < n; ++i) K(i, j) = Ke[i];
            e[j] = 0.0;
        }
        const Eigen::VectorXd lambda =
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (K + K.transpose())).eigenvalues();
        const double largest = lambda.maxCoeff();
        std::printf("one %s tet: eigenvalues 6 %.2e .. %.2e, 7th %.3e of the largest\n",
                    composite ? "composite" : "quadratic", lambda[0] / largest, lambda[5] / largest,
                    lambda[6] / largest);
        for (int k = 0; k < 6; ++k) EXPECT_LT(std::fabs(lambda[k]), 1e-10 * largest) << k;
        EXPECT_GT(lambda[6], 1e-3 * largest);
    }
}

// The table's gradients reproduce a linear field exactly at every quadrature point: sum_a
// bhat_qa = 0 (a translation has no gradient) and sum_a xi_a bhat_qa^T = I (the natural
// coordinates' own gradient), to round-off.
TEST(CompositeElement, TableReproducesLinearFields) {
    double xi[10][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int e = 0; e < 6; ++e)
        for (int c = 0; c < 3; ++c)
            xi[4 + e][c] = 0.5 * (xi[kQuadraticTetEdges[e][0]][c] + xi[kQuadraticTetEdges[e][1]][c]);
    for (int q = 0; q < kQuadraturePoints; ++q)
        for (int c = 0; c < 3; ++c) {
            double sum = 0.0;
            for (int a = 0; a < 10; ++a) sum += kCompositeGradients.g[q][a][c];
            EXPECT_NEAR(sum, 0.0, 1e-14);
            for (int r = 0; r < 3; ++r) {
                double grad = 0.0;
                for (int a = 0; a < 10; ++a) grad += xi[a][r] * kCompositeGradients.g[q][a][c];
                EXPECT_NEAR(grad, r == c ? 1.0 : 0.0, 1e-14) << "q " << q << " r " << r << " c " << c;
            }
        }
}

// What the element is for: a linear stress field loads the nodes in the shares of their lumped
// masses. With sigma_xx = x (the other components 0), the virtual work on node a's shape
// function, sum over its tets and their points of V_q sigma(x_q) (J_q^-T bhat_qa)_x, is for an
// interior node -int N_a d(sigma)/dx = -m_a / rho: the 4-point rule integrates the linear stress
// times the linear projected gradient exactly, and a linear field is its own projection, so
// N_a is the sub-tets' piecewise-linear function whose integral the lumped mass is. Round-off
// only: 1e-12 of the share. The quadratic shape functions give -V/20 at corners and V/5 at
// mid-edge nodes instead (QuadraticElement.QuadraticFieldLoadsItsNodesConsistently), far from
// their masses, which the same sum shows.
TEST(CompositeElement, LinearStressLoadsTheNodesAsTheyAreLumped) {
    for (bool composite : {true, false}) {
        const QuadraticBox box(3, 2, 4, 64, composite);
        const QuadraticGradients& table = element_gradients(composite);
        std::vector<double> load(box.nodes(), 0.0);
        for (uint32_t e = 0; e < box.mesh.tet_count(); ++e) {
            const uint32_t* t = &box.mesh.tets[10 * std::size_t(e)];
            for (int q = 0; q < kQuadraturePoints; ++q) {
                const std::size_t k = kQuadraturePoints * std::size_t(e) + q;
                const Eigen::Map<const Mat3> Jinv(&box.Jq_inv[9 * k]);
                double x = 0.0;  // the point's x: straight sides, the corners' barycentric mean
                for (int i = 0; i < 4; ++i) x += (i == q ? kQuadratureA : kQuadratureB) * box.X(t[i])[0];
                for (int a = 0; a < 10; ++a)
                    load[t[a]] += box.qp_volume[k] * x * (Jinv.transpose() * Vec3(table.g[q][a]))[0];
            }
        }
        int interior = 0, off = 0;
        for (uint32_t i = 0; i < box.nodes(); ++i) {
            if (box.boundary[i]) continue;
            const double share = box.mass[i] / kRho;
            ++interior;
            if (composite) {
                EXPECT_NEAR(load[i], -share, 1e-12 * share) << "node " << i;
            } else {
                off += std::fabs(load[i] + share) > 0.1 * share;
            }
        }
        EXPECT_GT(interior, 10);
        if (!composite) {
            EXPECT_GT(off, interior / 2);  // the sum does tell the elements apart
        }
    }
}

}  // namespace
}  // namespace lfem
