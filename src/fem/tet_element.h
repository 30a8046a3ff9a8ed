// One linear tetrahedron: its reference data and the stress of each material model. Everything
// the local finite element method needs is here, element by element: no global matrix exists.
//
// With Dm = [X1-X0, X2-X0, X3-X0] (reference edges) and Ds the same for the current nodes, the
// deformation gradient is F = Ds Dm^-1, and the internal force on node a of the tet is
// f_a = V P grad(N_a) with P the first Piola-Kirchhoff stress: the columns of V P Dm^-T give
// nodes 1..3 and node 0 receives minus their sum (the element is in equilibrium by itself).
#pragma once

#include "common/math.h"
#include "fem/material.h"
#include "fem/volume_barrier.h"

namespace lfem {

// Edge matrix [x1-x0, x2-x0, x3-x0] of four nodes given by pointers to their xyz.
inline Mat3 edge_matrix(const double* x0, const double* x1, const double* x2, const double* x3) {
    Mat3 D;
    for (int r = 0; r < 3; ++r) {
        D(r, 0) = x1[r] - x0[r];
        D(r, 1) = x2[r] - x0[r];
        D(r, 2) = x3[r] - x0[r];
    }
    return D;
}

// Small-strain (Hooke) stress of the symmetric part of a displacement gradient H, and its
// energy density psi = mu eps:eps + lambda/2 tr(eps)^2.
inline Mat3 hooke_stress(const Mat3& H, const Lame& l, double* energy_density) {
    const Mat3 eps = 0.5 * (H + H.transpose());
    const double tr = eps.trace();
    if (energy_density) *energy_density = l.mu * eps.squaredNorm() + 0.5 * l.lambda * tr * tr;
    return 2.0 * l.mu * eps + l.lambda * tr * Mat3::Identity();
}

// Stable neo-Hookean (Smith, de Goes & Kim 2018, without the log term):
// psi = mu/2 (tr(F^T F) - 3) - mu (J - 1) + lambda'/2 (J - 1)^2 with lambda' = lambda + mu, so
// that its linearisation at F = I is exactly Hooke's law with (mu, lambda), plus the volume
// barrier of volume_barrier.h below J = 0.2 (its own volume term is finite at J = 0). Defined
// for inverted elements (J <= 0), which push back instead of producing NaN.
inline Mat3 neo_hookean_stress(const Mat3& F, const Lame& l, double* energy_density) {
    const double J = F.determinant();
    Mat3 cof;  // cofactor matrix dJ/dF
    cof.col(0) = F.col(1).cross(F.col(2));
    cof.col(1) = F.col(2).cross(F.col(0));
    cof.col(2) = F.col(0).cross(F.col(1));
    const double lam = l.lambda + l.mu;
    double barrier, barrier_d1, barrier_d2;  // below J_b only (volume_barrier.h)
    volume_barrier(J, lam, barrier, barrier_d1, barrier_d2);
    if (energy_density)
        *energy_density = 0.5 * l.mu * (F.squaredNorm() - 3.0) - l.mu * (J - 1.0) +
                          0.5 * lam * (J - 1.0) * (J - 1.0) + barrier;
    return l.mu * F + (lam * (J - 1.0) - l.mu + barrier_d1) * cof;
}

// Von Mises equivalent of a (symmetric) Cauchy stress.
inline double von_mises(const Mat3& s) {
    const double a = s(0, 0) - s(1, 1), b = s(1, 1) - s(2, 2), c = s(2, 2) - s(0, 0);
    const double shear = s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(2, 0) * s(2, 0);
    return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * shear);
}

}  // namespace lfem
