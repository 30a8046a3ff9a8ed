// How stiff a stable neo-Hookean tet is at its deformation F: an estimate of the largest
// eigenvalue of the material tangent dP/dF, which sets the tet's highest frequency and so the
// stable step of central differences at the current shape.
#pragma once

#include <algorithm>
#include <cmath>

#include "fem/volume_barrier.h"

namespace lfem {

// T[D, D] = mu |D|^2 + lam' (cof F : D)^2 + c d2J[D, D], c = lam' (J - 1) - mu, lam' = lambda
// + mu (tet_element.h), estimated without singular values. In the singular-value frame (Smith,
// de Goes & Kim 2019) T splits into twist and flip pairs, eigenvalues mu +- c s_k (bounded here
// with s_max^2 <= the largest Gershgorin row of F^T F), and a 3x3 scaling block dominated by
// lam' g g^T, g = cof F: its top eigenvector is close to the volumetric direction
// D = cof F / |cof F|, whose Rayleigh quotient is taken; there d2J[D, D] = 2 cof D : F and
// cof(cof F) = J F give 2 J |F|^2 / |cof F|^2. Both parts are exact at F = I (2 mu + 3 lambda)
// and under any rotation; a crushed tet (s = 2, 2, 1/4 at nu = 0.3) is estimated within 0.5 %.
// a, b, c: the columns of F. Written out by hand: the element kernel evaluates it for every
// neo-Hookean tet at every force computation (internal_forces.cpp).
inline double neo_hookean_tangent_estimate(double a0, double a1, double a2, double b0, double b1,
                                           double b2, double c0, double c1, double c2, double mu,
                                           double lam) {
    // Columns of cof F: b x c, c x a, a x b.
    const double k00 = b1 * c2 - b2 * c1, k10 = b2 * c0 - b0 * c2, k20 = b0 * c1 - b1 * c0;
    const double k01 = c1 * a2 - c2 * a1, k11 = c2 * a0 - c0 * a2, k21 = c0 * a1 - c1 * a0;
    const double k02 = a1 * b2 - a2 * b1, k12 = a2 * b0 - a0 * b2, k22 = a0 * b1 - a1 * b0;
    const double J = a0 * k00 + a1 * k10 + a2 * k20;
    // The volume barrier (volume_barrier.h) adds psi_b'' to the coefficient of (cof F : D)^2
    // and psi_b' to that of d2J[D, D].
    double barrier, barrier_d1, barrier_d2;
    volume_barrier(J, lam, barrier, barrier_d1, barrier_d2);
    const double c = lam * (J - 1.0) - mu + barrier_d1;
    const double cof2 = k00 * k00 + k10 * k10 + k20 * k20 + k01 * k01 + k11 * k11 + k21 * k21 +
                        k02 * k02 + k12 * k12 + k22 * k22;
    const double aa = a0 * a0 + a1 * a1 + a2 * a2, bb = b0 * b0 + b1 * b1 + b2 * b2,
                 cc = c0 * c0 + c1 * c1 + c2 * c2;
    const double scaling = mu + (lam + barrier_d2) * cof2 + (cof2 > 0.0 ? 2.0 * c * J * (aa + bb + cc) / cof2 : 0.0);
    // Gershgorin rows of C = F^T F, C_ij = f_i . f_j.
    const double ab = std::fabs(a0 * b0 + a1 * b1 + a2 * b2), ac = std::fabs(a0 * c0 + a1 * c1 + a2 * c2),
                 bc = std::fabs(b0 * c0 + b1 * c1 + b2 * c2);
    const double s_max2 = std::max(std::max(aa + ab + ac, bb + ab + bc), cc + ac + bc);
    return std::max(scaling, mu + std::fabs(c) * std::sqrt(s_max2));
}

}  // namespace lfem
