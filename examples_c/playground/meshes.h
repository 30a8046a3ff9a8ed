/* Triangle meshes the playground draws: the render meshes bound to the soft bodies as skins (a
 * rounded box, finer than the tets) and the surfaces of the rigid shapes (box, sphere,
 * capsule, a floor tile grid). Plain C99; functions return 0, or -1 when out of memory. */
#ifndef LFEM_PLAYGROUND_MESHES_H
#define LFEM_PLAYGROUND_MESHES_H

#include <stdint.h>

/* Vertices interleaved as OpenGL's GL_N3F_V3F wants them: normal (3 floats), then position
 * (3 floats). Triangles counter-clockwise seen from outside. */
typedef struct pg_mesh {
    float* vertices;      /* 6 per vertex */
    uint32_t* triangles;  /* 3 per triangle */
    uint32_t vertex_count, triangle_count;
} pg_mesh;

void pg_mesh_destroy(pg_mesh* mesh);

/* The box [0, size] rounded by radius (<= half the smallest side) at its edges and corners,
 * every face cut into `cells` x `cells` squares (welded: one vertex where faces meet). Every
 * vertex lies inside the box, so it binds to a box mesh's tets. positions: 3 doubles a vertex,
 * the rest frame the skin is given in. */
int pg_rounded_box(const double size[3], double radius, uint32_t cells, double** positions,
                   uint32_t** triangles, uint32_t* vertex_count, uint32_t* triangle_count);

/* Shapes as drawn: centred on the origin, in the shape's local frame. */
int pg_mesh_box(pg_mesh* mesh, const double half_extents[3]);
int pg_mesh_sphere(pg_mesh* mesh, double radius, uint32_t segments);
/* Along local z from -half_length to +half_length, swept by radius. */
int pg_mesh_capsule(pg_mesh* mesh, double radius, double half_length, uint32_t segments);
/* A flat grid of cells x cells squares on z = 0 facing +z, [-half, half]^2; parity 0 keeps the
 * squares whose (i + j) is even, 1 the odd ones, 2 all (a checkerboard is two meshes). */
int pg_mesh_grid(pg_mesh* mesh, double half_x, double half_y, uint32_t cells, int parity);

/* Move the mesh by the rigid motion (unit quaternion rotation (w, x, y, z), then offset). */
void pg_mesh_transform(pg_mesh* mesh, const double rotation[4], const double offset[3]);

#endif
