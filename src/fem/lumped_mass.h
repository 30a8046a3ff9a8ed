// The reference data of each tet and the lumped (diagonal) mass matrix M of eq. (1): every
// linear tet gives a quarter of its mass rho V to each of its nodes; a 10-node tet gives rho V /
// 32 to each corner and 7 rho V / 48 to each mid-edge node (fem/quadratic_tet.h says why). With
// it the central difference (eq. 3) needs no global matrix: M is a number per node.
#pragma once

#include <cstdint>

namespace lfem {

// For tets [first, end) of `tets` (4 node indices each into X, 3 per node): the inverse
// reference edge matrix Dm^-1 (9 per tet, column-major, Dm = [X1-X0, X2-X0, X3-X0]), the
// reference volume det(Dm)/6, and rho V / 4 added to the mass of each of the tet's nodes. The
// output arrays are indexed by tet and node like the input.
void add_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end,
                        double density, double* Dm_inv, double* volume, double* mass);

// The same for 10-node tets (10 node indices each, common/quadratic_tet_nodes.h): at each of the
// 4 quadrature points the inverse reference Jacobian J_q^-1 (9 each, column-major: 36 per tet)
// and the volume w_q det J_q (4 per tet), the tet's volume (their sum), and its lumped mass added
// to its nodes. The Jacobians must be positive (smallest_jacobian, checked when the mesh is added).
void add_quadratic_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end,
                                  double density, double* Jq_inv, double* qp_volume, double* volume,
                                  double* mass);

}  // namespace lfem
