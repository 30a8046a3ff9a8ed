/* The soft bodies' skins: a render mesh finer than the tets, bound to them once and read back
 * deformed every frame straight into an OpenGL vertex buffer. */
#ifndef LFEM_PLAYGROUND_SKIN_H
#define LFEM_PLAYGROUND_SKIN_H

#include "lfem.h"
#include "meshes.h"

/* Binds to body the box [0, size] + at rounded by rounding, cells squares a face (the box of
 * the body's mesh, in its rest frame), and makes *out the mesh to draw it (its triangles, room
 * for its vertices). Returns 0, or -1 after printing why. */
int pg_skin_bind(lfem_world* world, lfem_body body, const double size[3], const double at[3],
                 double rounding, uint32_t cells, pg_mesh* out);

/* The skin's current vertices and smooth normals into mesh->vertices. 0, or -1 after printing
 * why. */
int pg_skin_read(const lfem_world* world, lfem_body body, pg_mesh* mesh);

#endif
