// The edges of a convex hull shape: the hull of its points (incremental, as in Clarkson and
// Shor's randomised construction but in the points' own order), and of the hull's triangles
// the edges where two faces meet at an angle (not the diagonals of a flat face), each with the
// sum of its two faces' unit normals. A body's sharp edges meet them as they meet a box's
// (contact/edge_edge.h, test_edge_box_edge): the faces' points under a hull lie at their
// borders where a hull's edge crosses a face's edge, and an edge crossing an edge needs its
// own pair.
#pragma once

#include "contact/rigid_shape.h"

namespace lfem {

// Fills shape.hull_edges and shape.hull_edge_out from shape.points (a convex hull; none for
// other shapes, or for points without volume, which the shim refuses).
void compute_hull_edges(RigidShape& shape);

}  // namespace lfem
