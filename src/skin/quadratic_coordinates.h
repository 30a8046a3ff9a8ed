// Where a point sits in a 10-node tet: the barycentric coordinates L of the element's own
// (isoparametric) map x(L) = sum_a N_a(L) X_a that reach it. A straight-sided element's map is
// the affine one of its corners, so the corners' coordinates are already the answer; a curved
// element (mid-edge nodes off their edges, as Gmsh puts them on a curved boundary) needs
// Newton's iterations from them.
#pragma once

#include "common/math.h"
#include "common/quadratic_tet_nodes.h"

namespace lfem {

// L (4 barycentric coordinates, summing to 1) such that sum_a N_a(L) X_a = p, by Newton's
// method from the guess in L (the coordinates among the corners). True when the iterations
// reach p to 1e-12 of the element's size (in practice to round-off); false when they do not
// (a point far outside a strongly curved element, or a folded one), L then left as it was.
bool quadratic_coordinates(const Vec3 X[kQuadraticTetNodes], const Vec3& p, double L[4]);

}  // namespace lfem
