// Validation of a caller's tetrahedral mesh before it becomes part of a body.
#pragma once

#include <cstdint>

namespace lfem {

// Throws Error(Status::invalid_mesh, message naming the first offending tet or node) when an
// index is out of range, a tet repeats a node, a tet (its corners) is inverted or has
// (relatively) zero volume, or a node belongs to no tet; for 10-node tets (nodes_per_tet 10)
// also when the mid-edge nodes do not conform (check_quadratic_topology). Positions are assumed
// finite (checked by the shim).
void check_tet_mesh(const double* positions, uint32_t node_count, const uint32_t* tets,
                    uint32_t tet_count, uint32_t nodes_per_tet = 4);

// Throws Error(Status::invalid_mesh) naming the first offending triangle when an index is not
// below point_count or a triangle repeats a point; with positions (3 per point), also when a
// triangle has no area (its cross product at most 1e-12 of its longest edge squared). `point`
// and `points` name the points in the message ("node" and "nodes", "vertex" and "vertices").
void check_triangles(const uint32_t* triangles, uint32_t triangle_count, uint32_t point_count,
                     const double* positions, const char* point, const char* points);

}  // namespace lfem
