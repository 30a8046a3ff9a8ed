// The 10-node (quadratic) tetrahedron: shape functions, quadrature and lumped mass, element by
// element as for the linear tet (tet_element.h); no global matrix exists.
//
// In barycentric coordinates L0..L3 (natural coordinates xi = (L1, L2, L3), L0 = 1 - L1 - L2 -
// L3) the corners carry N_i = L_i (2 L_i - 1) and the mid-edge node of edge (i, j)
// (common/quadratic_tet_nodes.h) N_ij = 4 L_i L_j. At a quadrature point q the reference
// Jacobian J_q = sum_a X_a dN_a/dxi^T plays the part of the linear tet's edge matrix Dm: with
// Ds_q = sum_a x_a dN_a/dxi^T the deformation gradient is F_q = Ds_q J_q^-1, and node a
// receives f_a = -sum_q V_q P_q J_q^-T dN_a/dxi, V_q = w_q det J_q. The mid-edge nodes may sit
// off the straight edge (a Gmsh mesh puts them on a curved boundary): J_q then varies over the
// element, which is why J_q^-1 is kept per quadrature point.
//
// Quadrature: the 4-point rule at L = (a, b, b, b) and its permutations, a = (5 + 3 sqrt 5)/20,
// b = (5 - sqrt 5)/20, each of weight 1/24 (the reference tet's volume 1/6 over four), exact for
// polynomials of degree 2. For a straight-sided element grad N is linear, so the stiffness
// integrand grad N_a . C grad N_b is quadratic: 4 points integrate it exactly, with full rank
// (one point, exact only for the linear tet, leaves spurious zero-energy modes: 6 strains at one
// point cannot control the 24 deformation modes of 30 degrees of freedom).
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/quadratic_tet_nodes.h"

namespace lfem {

constexpr int kQuadraturePoints = 4;  // per quadratic tet
constexpr double kQuadratureA = 0.58541019662496845446;  // (5 + 3 sqrt 5) / 20
constexpr double kQuadratureB = 0.13819660112501051518;  // (5 - sqrt 5) / 20
constexpr double kQuadratureWeight = 1.0 / 24.0;

// dN_a/dxi at each quadrature point.
struct QuadraticGradients {
    double g[kQuadraturePoints][kQuadraticTetNodes][3];
};

constexpr QuadraticGradients quadratic_gradients() {
    QuadraticGradients t{};
    for (int q = 0; q < kQuadraturePoints; ++q) {
        double L[4] = {kQuadratureB, kQuadratureB, kQuadratureB, kQuadratureB};
        L[q] = kQuadratureA;
        quadratic_gradients_at(L, t.g[q]);
    }
    return t;
}

inline constexpr QuadraticGradients kQuadraticGradients = quadratic_gradients();

inline double determinant3(const double J[9]) {
    return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
           J[2] * (J[3] * J[7] - J[4] * J[6]);
}

// The smallest det J of a 10-node tet over its quadrature points and corners (6 times the
// volume of the reference element's map there; a straight-sided tet has det J = 6 V
// everywhere). X: 3 per node; tet: 10 node indices. A curved element whose map folds over has
// det J <= 0 somewhere.
inline double smallest_jacobian(const double* X, const uint32_t* tet) {
    const double* p[kQuadraticTetNodes];
    for (uint32_t a = 0; a < kQuadraticTetNodes; ++a) p[a] = X + 3 * std::size_t(tet[a]);
    double smallest = 0.0, J[9];
    for (int k = 0; k < kQuadraturePoints + 4; ++k) {
        double g[kQuadraticTetNodes][3];
        if (k < kQuadraturePoints) {
            natural_jacobian(p, kQuadraticGradients.g[k], J);
        } else {
            double L[4] = {0, 0, 0, 0};
            L[k - kQuadraturePoints] = 1.0;
            quadratic_gradients_at(L, g);
            natural_jacobian(p, g, J);
        }
        const double d = determinant3(J);
        smallest = k == 0 ? d : (d < smallest ? d : smallest);
    }
    return smallest;
}

// The lumped mass (eq. 1) of a 10-node tet of mass rho V. Row sums of its consistent mass give
// the corners -rho V / 20 and the mid-edge nodes rho V / 5: a negative mass, which central
// differences cannot integrate. The element is lumped instead as the modified tetrahedra of the
// explicit codes (C3D10M of Abaqus/Explicit and its kin) see it: as its natural subdivision into
// eight 4-node sub-tets, one at each corner (the corner and its three mid-edge neighbours) and
// four filling the inner octahedron of mid-edge nodes, each an eighth of the volume and each
// lumped as a linear tet, a quarter of its mass to each of its nodes. Each corner so receives
// rho V / 32 and each mid-edge node 7 rho V / 48: positive, summing to rho V, centred on the
// centroid. (The diagonal scaling of HRZ gives 1/36 and 4/27, positive too; the sub-tet lumping
// is the modified element's own, it is the split the contact surface uses (each 6-node face as
// the 4 faces of its sub-tets, mesh/surface.h), and its heavier corners allow a longer step.)
constexpr double kCornerMassFraction = 1.0 / 32.0;
constexpr double kMidEdgeMassFraction = 7.0 / 48.0;

}  // namespace lfem
