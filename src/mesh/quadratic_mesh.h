// Meshes of 10-node tets (node numbering in common/quadratic_tet_nodes.h): made from any linear
// mesh by adding a node at the middle of every edge, checked for conformity (neighbouring tets
// share their edges' mid-edge nodes), and re-labelled without losing which mid-edge node sits on
// which edge.
#pragma once

#include <cstdint>

#include "mesh/tet_mesh.h"

namespace lfem {

// The mesh with a node added at the middle of every edge (straight edges: the midpoint), each
// tet listing its 4 corners and 6 mid-edge nodes. Corner nodes keep their indices; the new nodes
// follow, ordered by their edges' (lower, higher) corner indices, so the result depends only on
// the linear mesh. One piece for every builder (and any linear mesh). Throws
// Error(Status::invalid_argument) for a mesh that is already quadratic or would pass 2^32 nodes.
TetMesh make_quadratic(const TetMesh& linear);

// Re-labels the corners of one tet (nodes_per_tet 4 or 10 indices, in place): new corner k is
// old corner from[k], and a quadratic tet's mid-edge nodes follow their edges.
void permute_corners(uint32_t* tet, uint32_t nodes_per_tet, const int from[4]);

// The topology of a quadratic mesh whose indices are in range and whose tets repeat no node:
// every edge (a pair of corners) has one mid-edge node in all the tets that share it, a mid-edge
// node belongs to one edge only, and no node is both a corner and a mid-edge node. Throws
// Error(Status::invalid_mesh) naming the first offence. O(t log t).
void check_quadratic_topology(const uint32_t* tets, uint32_t tet_count, uint32_t node_count);

}  // namespace lfem
