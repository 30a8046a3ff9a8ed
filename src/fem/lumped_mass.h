// The reference data of each tet and the lumped (diagonal) mass matrix M of eq. (1): every
// tet gives a quarter of its mass rho V to each of its nodes. With it the central difference
// (eq. 3) needs no global matrix: M is a number per node.
#pragma once

#include <cstdint>

namespace lfem {

// For tets [first, end) of `tets` (4 node indices each into X, 3 per node): the inverse
// reference edge matrix Dm^-1 (9 per tet, column-major, Dm = [X1-X0, X2-X0, X3-X0]) and the
// reference volume det(Dm)/6, indexed by tet like the input.
void add_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end, double* Dm_inv,
                        double* volume);

// rho V / 4 of each of the tets [first, end) added to the mass of each of its nodes, in tet order.
void add_lumped_mass(const uint32_t* tets, const double* volume, uint32_t first, uint32_t end, double density,
                     double* mass);

}  // namespace lfem
