// The 10-node tet's kernels against closed forms (src/fem/quadratic_tet.h): the patch tests (a
// linear and a quadratic displacement field are reproduced exactly: the interior nodes are in
// equilibrium, the stress and the strain energy are the field's), the lumped masses, rigid
// motions that strain nothing, the stiffness operator's symmetry, and the stable step estimate
// against the eigenvalues of the assembled M^-1 K. Through the static archive: the kernels
// themselves, on a box of 10-node tets.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include <Eigen/Dense>

#include "fem/stable_step.h"
#include "fem/tet_element.h"
#include "quadratic_box.h"

namespace lfem {
namespace {

using namespace test;

TEST(QuadraticElement, MassesArePositiveAndSumToRhoV) {
    const QuadraticBox box(3, 2, 4);
    double total = 0.0;
    std::vector<double> expected(box.nodes(), 0.0);
    for (uint32_t t = 0; t < box.mesh.tet_count(); ++t)
        for (int a = 0; a < 10; ++a)  // the sub-tet lumping: V/32 at corners, 7V/48 mid-edge
            expected[box.mesh.tets[10 * t + a]] += kRho * box.volume[t] * (a < 4 ? 1.0 / 32.0 : 7.0 / 48.0);
    for (uint32_t i = 0; i < box.nodes(); ++i) {
        EXPECT_GT(box.mass[i], 0.0) << "node " << i;
        EXPECT_NEAR(box.mass[i], expected[i], 1e-15 * kRho);
        total += box.mass[i];
    }
    const double V = kSize[0] * kSize[1] * kSize[2];
    EXPECT_NEAR(total, kRho * V, 1e-12 * kRho * V);
    for (uint32_t t = 0; t < box.mesh.tet_count(); ++t)  // straight sides: four equal points
        for (int q = 0; q < 4; ++q) EXPECT_NEAR(box.qp_volume[4 * t + q], box.volume[t] / 4, 1e-15 * box.volume[t]);
}

// x = F X + c, any F: a constant stress; the interior nodes are in equilibrium whatever the
// model (relative to the forces on the boundary nodes, round-off: 1e-12).
// The composite element (composite_tet.h) passes it too: a linear field is its own projection.
void homogeneous_deformation_is_reproduced(bool composite);
TEST(QuadraticElement, HomogeneousDeformationIsReproducedByEveryModel) {
    for (bool composite : {false, true}) homogeneous_deformation_is_reproduced(composite);
}

void homogeneous_deformation_is_reproduced(bool composite) {
    SCOPED_TRACE(composite ? "composite" : "quadratic");
    const QuadraticBox box(2, 2, 2, 64, composite);
    const Lame lame = lame_from_young_poisson(1e6, 0.3);
    Mat3 F;
    F << 1.05, 0.02, -0.01, 0.03, 0.97, 0.04, -0.02, 0.01, 1.08;
    const std::vector<double> x = deformed(box, [&](const double* X, double* u) {
        const Vec3 d = (F - Mat3::Identity()) * Vec3(X) + Vec3(0.1, -0.2, 0.3);
        for (int k = 0; k < 3; ++k) u[k] = d[k];
    });
    for (Model model : {Model::linear, Model::paper, Model::corotational, Model::neo_hookean}) {
        const Forces r = forces_at(box, model, lame, x);
        double interior = 0, any = 0;
        largest_forces(box, r.f, interior, any);
        EXPECT_GT(any, 0.0);
        EXPECT_LT(interior, 1e-12 * any) << "model " << int(model);
        // Every tet has the same stress: its von Mises value is the field's.
        std::vector<double> vm(box.mesh.tet_count());
        std::vector<float> rotations(16 * std::size_t(box.mesh.tet_count()), 0.0f);
        for (std::size_t k = 0; k < rotations.size(); k += 4) rotations[k] = 1.0f;
        const double frame[4] = {1, 0, 0, 0};
        compute_von_mises(box.view(), Material{model, lame}, x.data(), rotations.data(), frame, vm.data());
        for (double v : vm) EXPECT_NEAR(v, vm[0], 1e-9 * vm[0]);
    }
    // The linear model's energy and stress: Hooke's law of F - I over the whole volume.
    const Forces r = forces_at(box, Model::linear, lame, x);
    double psi = 0;
    const Mat3 sigma = hooke_stress(F - Mat3::Identity(), lame, &psi);
    EXPECT_NEAR(r.result.strain_energy, psi * kSize[0] * kSize[1] * kSize[2], 1e-12 * r.result.strain_energy);
    std::vector<double> vm(box.mesh.tet_count());
    compute_von_mises(box.view(), Material{Model::linear, lame}, x.data(), nullptr, nullptr, vm.data());
    EXPECT_NEAR(vm[0], von_mises(sigma), 1e-12 * von_mises(sigma));
}

// Pure bending, u = (kappa x z, 0, -kappa x^2 / 2) with nu = 0: a quadratic field whose stress
// sigma_xx = E kappa z is in equilibrium without body forces. 10-node tets hold it exactly:
// zero force on every interior node, the stress of each tet the field's at its centroid (the
// mean of a linear field), the energy E kappa^2 / 2 times the integral of z^2.
TEST(QuadraticElement, QuadraticBendingFieldIsReproducedExactly) {
    const QuadraticBox box(3, 2, 4);
    const double E = 2e8, kappa = 1e-3;
    const Lame lame = lame_from_young_poisson(E, 0.0);
    const std::vector<double> x = deformed(box, [&](const double* X, double* u) {
        u[0] = kappa * X[0] * X[2], u[1] = 0.0, u[2] = -0.5 * kappa * X[0] * X[0];
    });
    const Forces r = forces_at(box, Model::linear, lame, x);
    double interior = 0, any = 0;
    largest_forces(box, r.f, interior, any);
    EXPECT_LT(interior, 1e-10 * any);
    const double z3 = kSize[2] * kSize[2] * kSize[2];
    const double energy = 0.5 * E * kappa * kappa * kSize[0] * kSize[1] * z3 / 3.0;
    EXPECT_NEAR(r.result.strain_energy, energy, 1e-10 * energy);
    std::vector<double> vm(box.mesh.tet_count());
    compute_von_mises(box.view(), Material{Model::linear, lame}, x.data(), nullptr, nullptr, vm.data());
    for (uint32_t t = 0; t < box.mesh.tet_count(); ++t) {
        double z = 0;
        for (int a = 0; a < 4; ++a) z += box.X(box.mesh.tets[10 * t + a])[2] / 4;
        EXPECT_NEAR(vm[t], E * kappa * z, 1e-8 * E * kappa * kSize[2]) << "tet " << t;
    }
}

// u = (c x^2, 0, 0), nu = 0: sigma_xx = 2 E c x, div sigma = (2 E c, 0, 0). The elastic force
// on an interior node is the consistent load of that divergence, 2 E c times the integral of
// its shape function: -V/20 from each tet a corner belongs to, +V/5 from each a mid-edge node
// belongs to (which is why these elements cannot be lumped by row sums).
TEST(QuadraticElement, QuadraticFieldLoadsItsNodesConsistently) {
    const QuadraticBox box(2, 2, 3);
    const double E = 1e7, c = 1e-3;
    const Lame lame = lame_from_young_poisson(E, 0.0);
    const std::vector<double> x = deformed(box, [&](const double* X, double* u) {
        u[0] = c * X[0] * X[0], u[1] = u[2] = 0.0;
    });
    const Forces r = forces_at(box, Model::linear, lame, x);
    std::vector<double> integral(box.nodes(), 0.0);
    for (uint32_t t = 0; t < box.mesh.tet_count(); ++t)
        for (int a = 0; a < 10; ++a) integral[box.mesh.tets[10 * t + a]] += box.volume[t] * (a < 4 ? -1.0 / 20 : 1.0 / 5);
    int checked = 0;
    for (uint32_t i = 0; i < box.nodes(); ++i) {
        if (box.boundary[i]) continue;
        const double expected = 2 * E * c * integral[i];
        EXPECT_NEAR(r.f[3 * i], expected, 1e-9 * std::fabs(expected)) << "node " << i;
        EXPECT_NEAR(r.f[3 * i + 1], 0.0, 1e-9 * std::fabs(expected));
        EXPECT_NEAR(r.f[3 * i + 2], 0.0, 1e-9 * std::fabs(expected));
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

// A rigid rotation strains nothing: no force, no energy, for the models that separate rotation
// (corotational and neo-Hookean by themselves, paper with the rotation as its frame).
TEST(QuadraticElement, RigidRotationStrainsNothing) {
    const QuadraticBox box(2, 1, 2);
    const Lame lame = lame_from_young_poisson(1e6, 0.3);
    const Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    const Mat3 R = q.toRotationMatrix();
    const std::vector<double> x = deformed(box, [&](const double* X, double* u) {
        const Vec3 d = R * Vec3(X) - Vec3(X) + Vec3(1, 2, 3);
        for (int k = 0; k < 3; ++k) u[k] = d[k];
    });
    const double frame[4] = {q.w(), q.x(), q.y(), q.z()};
    // What a strain of 1e-3 would give, for scale.
    const std::vector<double> strained = deformed(box, [&](const double* X, double* u) {
        u[0] = 1e-3 * X[0], u[1] = u[2] = 0.0;
    });
    double unused = 0, scale = 0;
    largest_forces(box, forces_at(box, Model::linear, lame, strained).f, unused, scale);
    for (Model model : {Model::paper, Model::corotational, Model::neo_hookean}) {
        const Forces r = forces_at(box, model, lame, x, frame);
        double interior = 0, any = 0;
        largest_forces(box, r.f, interior, any);
        // The polar rotation is iterated to 1e-8 rad from its float start; round-off elsewhere.
        EXPECT_LT(any, 1e-6 * scale) << "model " << int(model);
        EXPECT_LT(std::fabs(r.result.strain_energy), 1e-12 * lame.mu * kSize[0] * kSize[1] * kSize[2]);
    }
}

// The stiffness operator K u of the stable step (element by element) is symmetric, annihilates
// rigid motions, and u.K u is twice the linear model's strain energy at u.
// The composite element's too.
void stiffness_operator_is_symmetric(bool composite);
TEST(QuadraticElement, StiffnessOperatorIsSymmetricAndRigidMotionsFree) {
    for (bool composite : {false, true}) stiffness_operator_is_symmetric(composite);
}

void stiffness_operator_is_symmetric(bool composite) {
    SCOPED_TRACE(composite ? "composite" : "quadratic");
    const QuadraticBox box(2, 1, 2, 64, composite);
    const Lame lame = lame_from_young_poisson(1e6, 0.3);
    const std::size_t n = 3 * std::size_t(box.nodes());
    std::vector<double> u(n), v(n), Ku(n), Kv(n), rigid(n), Kr(n);
    uint64_t seed = 12345;
    for (std::size_t i = 0; i < n; ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        u[i] = double(seed >> 11) / double(1ull << 53) - 0.5;
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        v[i] = double(seed >> 11) / double(1ull << 53) - 0.5;
    }
    for (uint32_t i = 0; i < box.nodes(); ++i) {  // a small rotation about z and a translation
        const double* X = box.X(i);
        rigid[3 * i] = -X[1] + 0.5, rigid[3 * i + 1] = X[0] - 0.2, rigid[3 * i + 2] = 0.3;
    }
    const ElementMesh m = box.view();
    apply_reference_stiffness(m, lame, u.data(), Ku.data());
    apply_reference_stiffness(m, lame, v.data(), Kv.data());
    apply_reference_stiffness(m, lame, rigid.data(), Kr.data());
    double uKv = 0, vKu = 0, uKu = 0, norm = 0, rigid_norm = 0;
    for (std::size_t i = 0; i < n; ++i) {
        uKv += u[i] * Kv[i], vKu += v[i] * Ku[i], uKu += u[i] * Ku[i];
        norm = std::max(norm, std::fabs(Ku[i])), rigid_norm = std::max(rigid_norm, std::fabs(Kr[i]));
    }
    EXPECT_NEAR(uKv, vKu, 1e-12 * std::fabs(uKu));
    EXPECT_LT(rigid_norm, 1e-12 * norm);
    // The strain energy of the linear model is u^T K u / 2, as long as no tet is crushed below
    // the volume barrier's J = 0.2 (volume_barrier.h): a small multiple of u.
    const double s = 1e-3;
    std::vector<double> x(box.mesh.positions);
    for (std::size_t i = 0; i < n; ++i) x[i] += s * u[i];
    EXPECT_NEAR(s * s * uKu, 2 * forces_at(box, Model::linear, lame, x).result.strain_energy, 1e-10 * s * s * uKu);
}

// The stable step estimate holds: omega_max used is at least the largest eigenvalue of the
// assembled M^-1 K (dense, here, from the operator column by column), and within the 2 %
// margin the Lanczos estimate adds; below the Gershgorin bound.
// For the composite element too (softer: a lower omega_max on the same masses).
TEST(QuadraticElement, StableStepEstimateBoundsTheTrueFrequency) {
    for (bool composite : {false, true}) {
        for (const uint32_t* cells : {(const uint32_t[]){1, 1, 1}, (const uint32_t[]){2, 1, 2}}) {
            const QuadraticBox box(cells[0], cells[1], cells[2], 64, composite);
            const Lame lame = lame_from_young_poisson(2e9, 0.3);
            const ElementMesh m = box.view();
            const int n = 3 * int(box.nodes());
            Eigen::MatrixXd A(n, n);
            std::vector<double> e(n, 0.0), Ke(n);
            for (int j = 0; j < n; ++j) {
                e[j] = 1.0;
                apply_reference_stiffness(m, lame, e.data(), Ke.data());
                for (int i = 0; i < n; ++i) A(i, j) = Ke[i] / std::sqrt(box.mass[i / 3] * box.mass[j / 3]);
                e[j] = 0.0;
            }
            const double lambda_max = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (A + A.transpose()))
                                          .eigenvalues()
                                          .maxCoeff();
            const StableStepEstimate s = estimate_stable_step(m, lame);
            const double omega = std::sqrt(lambda_max);
            std::printf("10-node%s box %ux%ux%u: omega_max %.6g (dense), used %.6g, Lanczos %.6g, Gershgorin %.6g\n",
                        composite ? " composite" : "", cells[0], cells[1], cells[2], omega, s.omega_max, s.omega_power, s.omega_gershgorin);
            EXPECT_GE(s.omega_max, omega);
            EXPECT_LE(s.omega_max, omega * std::sqrt(1.02) * (1 + 1e-9));
            EXPECT_GE(s.omega_gershgorin, omega);
        }
    }
}

}  // namespace
}  // namespace lfem
