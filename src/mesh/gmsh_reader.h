// Gmsh .msh import (ASCII 2.2 and 4.1): tetrahedra only (4-node, type 4, or 10-node, type 11,
// one kind per file), other cells skipped.
#pragma once

#include <string>

#include "mesh/tet_mesh.h"

namespace lfem {

// Throws Error(Status::io_error, "<path>:<line>: <what is wrong>") for a missing or malformed
// file. Unused nodes are dropped and nodes renumbered densely; negatively oriented tets get
// two corners swapped (a 10-node tet's mid-edge nodes follow); zero-volume tets are an error.
// 10-node tets come in lfem's node order (common/quadratic_tet_nodes.h), nodes_per_tet 10.
TetMesh read_gmsh(const std::string& path);

}  // namespace lfem
