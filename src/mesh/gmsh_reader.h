// Gmsh .msh import (ASCII 2.2 and 4.1): tetrahedra only, other cells skipped.
#pragma once

#include <string>

#include "mesh/tet_mesh.h"

namespace lfem {

// Throws Error(LFEM_IO_ERROR, "<path>:<line>: <what is wrong>") for a missing or malformed
// file. Unused nodes are dropped and nodes renumbered densely; negatively oriented tets get
// two nodes swapped; zero-volume tets are an error.
TetMesh read_gmsh(const std::string& path);

}  // namespace lfem
