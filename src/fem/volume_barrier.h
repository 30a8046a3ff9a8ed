// A volume term that grows without bound as a tet is crushed towards zero volume, added to the
// stable neo-Hookean energy (tet_element.h), whose own volume term stays finite at J = 0: a
// body crushed at its wave speed, or squashed flat under its own weight, would otherwise pass
// tets through zero volume and leave them inverted.
//   psi_b(J) = k (J_b - J)^2 / J   for J_f <= J < J_b,  0 for J >= J_b,
// continued below J_f by its second-order Taylor polynomial at J_f (so an already inverted tet,
// J <= 0, is pushed back by a large but finite pressure, and the stiffness, which sets the
// stable step, stays bounded). C1 at J_b (value and slope zero there): a tet compressed less
// than to J_b never feels it. k = lambda + mu (the stable neo-Hookean's lambda'). The
// neo-Hookean energy carries it inside (tet_element.h); the other models add it to their stress
// with add_volume_barrier, which also estimates the stiffness it adds (for the stable step).
#pragma once

#include <cmath>

namespace lfem {

constexpr double kBarrierJ = 0.2;        // J_b: where the barrier starts
constexpr double kBarrierFloorJ = 0.05;  // J_f: where its Taylor continuation takes over

// psi_b(J) (J/m^3), d psi_b / dJ and d2 psi_b / dJ2.
inline void volume_barrier(double J, double k, double& psi, double& d1, double& d2) {
    if (!(J < kBarrierJ)) {  // (also a NaN J: nothing added)
        psi = d1 = d2 = 0.0;
        return;
    }
    const double Jc = J > kBarrierFloorJ ? J : kBarrierFloorJ;
    const double r = kBarrierJ / Jc;
    const double pc = k * (kBarrierJ - Jc) * (kBarrierJ - Jc) / Jc;
    const double d1c = k * (1.0 - r * r);
    const double d2c = 2.0 * k * r * r / Jc;
    const double dJ = J - Jc;  // < 0 only below J_f: the quadratic continuation
    psi = pc + dJ * (d1c + 0.5 * d2c * dJ);
    d1 = d1c + d2c * dJ;
    d2 = d2c;
}

// Adds the barrier of a tet at deformation F (row-major) to its first Piola-Kirchhoff stress P
// (row-major) and energy density psi: P += psi_b'(J) cof F. Returns the largest eigenvalue of
// the stiffness it adds, bounded by psi_b'' |cof F|^2 + |psi_b'| s_max (the Hessian of det F
// has eigenvalues +-s_k, the singular values of F; s_max <= |F|), 0 where J >= J_b.
inline double add_volume_barrier(const double F[9], double k, double P[9], double& psi) {
    const double a0 = F[0], a1 = F[3], a2 = F[6];  // columns of F
    const double b0 = F[1], b1 = F[4], b2 = F[7];
    const double c0 = F[2], c1 = F[5], c2 = F[8];
    const double k00 = b1 * c2 - b2 * c1, k10 = b2 * c0 - b0 * c2, k20 = b0 * c1 - b1 * c0;
    const double J = a0 * k00 + a1 * k10 + a2 * k20;
    if (!(J < kBarrierJ)) return 0.0;
    const double k01 = c1 * a2 - c2 * a1, k11 = c2 * a0 - c0 * a2, k21 = c0 * a1 - c1 * a0;
    const double k02 = a1 * b2 - a2 * b1, k12 = a2 * b0 - a0 * b2, k22 = a0 * b1 - a1 * b0;
    double b, d1, d2;
    volume_barrier(J, k, b, d1, d2);
    psi += b;
    P[0] += d1 * k00, P[1] += d1 * k01, P[2] += d1 * k02;
    P[3] += d1 * k10, P[4] += d1 * k11, P[5] += d1 * k12;
    P[6] += d1 * k20, P[7] += d1 * k21, P[8] += d1 * k22;
    double cof2 = 0.0, f2 = 0.0;
    const double cof[9] = {k00, k01, k02, k10, k11, k12, k20, k21, k22};
    for (int i = 0; i < 9; ++i) cof2 += cof[i] * cof[i], f2 += F[i] * F[i];
    return d2 * cof2 + std::fabs(d1) * std::sqrt(f2);
}

}  // namespace lfem
