// Boundary triangles of a tetrahedral mesh: the faces that belong to exactly one tet.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

// 3 node indices per boundary triangle, ordered counter-clockwise seen from outside (the
// normal (b-a)x(c-a) points out of the body). O(tets) with a hash of sorted face keys. Throws
// Error(Status::invalid_mesh) when a face is shared by more than two tets (non-manifold or
// duplicated tets). Output order is deterministic (order of first appearance).
std::vector<uint32_t> extract_boundary_triangles(const uint32_t* tets, uint32_t tet_count);

// The boundary of a mesh of 10-node tets (10 node indices per tet, common/quadratic_tet_nodes.h)
// as 6-node triangles: corners a, b, c (counter-clockwise seen from outside), then the mid-edge
// nodes of ab, bc and ca. The same faces, checks and order as extract_boundary_triangles.
std::vector<uint32_t> extract_quadratic_boundary(const uint32_t* tets, uint32_t tet_count);

}  // namespace lfem
