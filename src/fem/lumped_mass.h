// The reference data of each tet and the lumped (diagonal) mass matrix M of eq. (1): every
// linear tet gives a quarter of its mass rho V to each of its nodes; a 10-node tet gives rho V /
// 32 to each corner and 7 rho V / 48 to each mid-edge node (fem/quadratic_tet.h says why). With
// it the central difference (eq. 3) needs no global matrix: M is a number per node.
#pragma once

#include <cstdint>

#include "fem/quadratic_tet.h"

namespace lfem {

// For tets [first, end) of `tets` (4 node indices each into X, 3 per node): the inverse
// reference edge matrix Dm^-1 (9 per tet, column-major, Dm = [X1-X0, X2-X0, X3-X0]) and the
// reference volume det(Dm)/6, indexed by tet like the input.
void add_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end, double* Dm_inv,
                        double* volume);

// The same for 10-node tets (10 node indices each, common/quadratic_tet_nodes.h): at each of the
// 4 quadrature points the inverse reference Jacobian J_q^-1 (9 each, column-major: 36 per tet)
// and the volume w_q det J_q (4 per tet), and the tet's volume (their sum). The Jacobians must be
// positive (smallest_jacobian, checked when the mesh is added). A composite element's J_q is
// made of its own gradient table (composite_tet.h); its volumes are the quadratic map's, so
// that a curved element weighs what it holds.
void add_quadratic_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end,
                                  bool composite, double* Jq_inv, double* qp_volume, double* volume);

// The share of a tet's mass rho V that its local node a receives: 1/4 for a linear tet, 1/32 at
// a corner and 7/48 at a mid-edge node of a 10-node tet.
inline double lumped_share(uint32_t nodes_per_tet, uint32_t a) {
    return nodes_per_tet == 4 ? 0.25 : (a < 4 ? kCornerMassFraction : kMidEdgeMassFraction);
}

// The lumped mass of each of the tets [first, end) (nodes_per_tet node indices each) added to
// the mass of its nodes, in tet order: rho V / 4 each, or the 10-node tet's shares.
void add_lumped_mass(const uint32_t* tets, const double* volume, uint32_t first, uint32_t end, double density,
                     double* mass, uint32_t nodes_per_tet = 4);

}  // namespace lfem
