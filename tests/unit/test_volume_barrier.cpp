// The volume barrier (src/fem/volume_barrier.h): its derivatives are those of its energy, it is
// C1 where it starts and where its continuation takes over, it grows as a tet is crushed, and
// the stiffness bound it gives the stable step is never below the true largest eigenvalue of
// the stiffness it adds. Derivatives are checked by central differences: with a step of 1e-6
// relative, the truncation error is ~1e-12 relative and the rounding error ~1e-10 (energies of
// order 1, divided by 2e-6): 1e-6 relative is far above both and far below any real mistake
// (a missing factor or a wrong sign is an O(1) error).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "fem/tet_element.h"
#include "fem/volume_barrier.h"

namespace lfem {
namespace {

double barrier_energy(double J, double k) {
    double psi, d1, d2;
    volume_barrier(J, k, psi, d1, d2);
    return psi;
}

TEST(VolumeBarrier, DerivativesAreThoseOfItsEnergy) {
    const double k = 3.0;
    for (double J : {0.19, 0.15, 0.1, 0.06, 0.04, 0.0, -0.3}) {
        double psi, d1, d2;
        volume_barrier(J, k, psi, d1, d2);
        const double e = 1e-6;
        const double fd1 = (barrier_energy(J + e, k) - barrier_energy(J - e, k)) / (2 * e);
        double p, a, b, c;
        volume_barrier(J + e, k, p, a, c);
        volume_barrier(J - e, k, p, b, c);
        const double fd2 = (a - b) / (2 * e);
        EXPECT_NEAR(d1, fd1, 1e-6 * std::fabs(d1)) << J;
        EXPECT_NEAR(d2, fd2, 1e-6 * std::fabs(d2)) << J;
    }
}

TEST(VolumeBarrier, StartsSmoothlyAndGrowsAsTheTetIsCrushed) {
    const double k = 1.0;
    double psi, d1, d2;
    volume_barrier(kBarrierJ, k, psi, d1, d2);  // value and slope zero where it starts: C1
    EXPECT_EQ(psi, 0.0);
    EXPECT_EQ(d1, 0.0);
    volume_barrier(kBarrierJ - 1e-9, k, psi, d1, d2);
    EXPECT_LT(std::fabs(d1), 1e-7);
    volume_barrier(1.0, k, psi, d1, d2);  // untouched above
    EXPECT_EQ(psi + d1 + d2, 0.0);
    // At its continuation point the two pieces agree in value and slope.
    double below[3], above[3];
    volume_barrier(kBarrierFloorJ - 1e-12, k, below[0], below[1], below[2]);
    volume_barrier(kBarrierFloorJ + 1e-12, k, above[0], above[1], above[2]);
    EXPECT_NEAR(below[0], above[0], 1e-9);
    EXPECT_NEAR(below[1], above[1], 1e-8);
    // The pressure -psi' rises steeply: k (r^2 - 1) with r = J_b / J, 15 k at J_f; an inverted
    // tet is pushed back harder still.
    double previous = 0.0;
    for (double J : {0.18, 0.12, 0.08, kBarrierFloorJ, 0.0, -0.5}) {
        volume_barrier(J, k, psi, d1, d2);
        EXPECT_GT(-d1, previous) << J;
        previous = -d1;
    }
    volume_barrier(kBarrierFloorJ, k, psi, d1, d2);
    EXPECT_NEAR(-d1, 15.0 * k, 1e-12);
}

// A deformation gradient crushed to volume ratio J (with some shear and rotation).
Mat3 crushed(double J, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    Mat3 F;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) F(i, j) = (i == j ? 1.0 : 0.0) + u(rng);
    const double s = std::cbrt(J / F.determinant());  // det(s F) = s^3 det F
    return s * F;
}

// P = d psi / dF of the stress functions, by central differences over the 9 entries.
template <class Energy>
Mat3 numeric_stress(const Mat3& F, const Energy& energy) {
    Mat3 P;
    const double e = 1e-7;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            Mat3 Fp = F, Fm = F;
            Fp(i, j) += e, Fm(i, j) -= e;
            P(i, j) = (energy(Fp) - energy(Fm)) / (2 * e);
        }
    return P;
}

TEST(VolumeBarrier, AddedStressIsTheGradientOfTheAddedEnergy) {
    std::mt19937 rng(7);
    const double k = 2.0;
    auto added = [&](const Mat3& F) {
        const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Fr = F;
        double P[9] = {}, psi = 0.0;
        add_volume_barrier(Fr.data(), k, P, psi);
        return psi;
    };
    for (double J : {0.15, 0.07, 0.02}) {
        const Mat3 F = crushed(J, rng);
        const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Fr = F;
        double P[9] = {}, psi = 0.0;
        add_volume_barrier(Fr.data(), k, P, psi);
        const Mat3 expected = numeric_stress(F, added);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                EXPECT_NEAR(P[3 * i + j], expected(i, j), 1e-6 * expected.norm()) << J;
    }
}

TEST(VolumeBarrier, NeoHookeanStressCarriesIt) {
    std::mt19937 rng(11);
    const Lame lame{1.0, 4.0};
    auto energy = [&](const Mat3& F) {
        double psi = 0.0;
        neo_hookean_stress(F, lame, &psi);
        return psi;
    };
    for (double J : {0.5, 0.15, 0.03}) {
        const Mat3 F = crushed(J, rng);
        const Mat3 P = neo_hookean_stress(F, lame, nullptr);
        const Mat3 expected = numeric_stress(F, energy);
        EXPECT_LT((P - expected).norm(), 1e-6 * expected.norm()) << J;
    }
}

// The bound add_volume_barrier returns against the largest eigenvalue of the barrier's 9 x 9
// Hessian in F, by central differences of its stress.
TEST(VolumeBarrier, StiffnessBoundIsNeverBelowTheTrueLargestEigenvalue) {
    std::mt19937 rng(3);
    const double k = 1.0;
    for (int trial = 0; trial < 20; ++trial) {
        const double J = 0.19 - 0.2 * trial / 20.0;  // into the continuation and inverted
        const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> F = crushed(std::fabs(J) < 1e-3 ? 1e-3 : J, rng);
        double P0[9] = {}, psi = 0.0;
        const double bound = add_volume_barrier(F.data(), k, P0, psi);
        Eigen::Matrix<double, 9, 9> H;
        const double e = 1e-7;
        for (int c = 0; c < 9; ++c) {
            Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Fp = F, Fm = F;
            Fp.data()[c] += e, Fm.data()[c] -= e;
            double Pp[9] = {}, Pm[9] = {}, unused = 0.0;
            add_volume_barrier(Fp.data(), k, Pp, unused);
            add_volume_barrier(Fm.data(), k, Pm, unused);
            for (int r = 0; r < 9; ++r) H(r, c) = (Pp[r] - Pm[r]) / (2 * e);
        }
        const Eigen::Matrix<double, 9, 9> Hs = 0.5 * (H + H.transpose());
        const double largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>(Hs).eigenvalues().maxCoeff();
        EXPECT_GE(bound, largest * (1 - 1e-6)) << "J " << F.determinant();
    }
}

}  // namespace
}  // namespace lfem
