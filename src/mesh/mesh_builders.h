// Structured tetrahedral meshes of the shapes the paper's scenes and the tests use. Every
// builder returns a conforming mesh (neighbouring tets share whole faces) with positively
// oriented tets and no unused nodes. Bad parameters throw Error(Status::invalid_argument).
#pragma once

#include <cstdint>

#include "mesh/tet_mesh.h"

namespace lfem {

// [0,size[0]] x [0,size[1]] x [0,size[2]], each hexahedral cell split into 6 tets.
TetMesh build_box(const double size[3], const uint32_t cells[3]);
// Solid cylinder along +z, z in [0, height].
TetMesh build_cylinder(double radius, double height, uint32_t segments, uint32_t rings,
                       uint32_t layers);
// Hollow cup with a bottom, open at the top, z in [0, height].
TetMesh build_cup(double outer_radius, double height, double wall, double bottom,
                  uint32_t segments, uint32_t layers);
// Square handle along +z from 0 to handle_length, head centred on the handle's top end.
TetMesh build_hammer(double handle_length, double handle_width, double head_length,
                     double head_width, double cell_size);

}  // namespace lfem
