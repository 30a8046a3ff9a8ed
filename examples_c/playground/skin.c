/* skin: see skin.h. */
#include "skin.h"

#include <stdio.h>
#include <stdlib.h>

int pg_skin_bind(lfem_world* world, lfem_body body, const double size[3], const double at[3],
                 double rounding, uint32_t cells, pg_mesh* out) {
    double* positions = NULL;
    uint32_t *triangles = NULL, vertex_count = 0, triangle_count = 0;
    if (pg_rounded_box(size, rounding, cells, &positions, &triangles, &vertex_count, &triangle_count) != 0) {
        fprintf(stderr, "playground: out of memory for a skin\n");
        return -1;
    }
    for (uint32_t i = 0; i < vertex_count; ++i)
        for (int k = 0; k < 3; ++k) positions[3 * i + k] += at[k];
    const lfem_status s =
        lfem_body_add_skin(world, body, positions, vertex_count, triangles, triangle_count, NULL);
    free(positions);
    out->vertices = s == LFEM_OK ? (float*)calloc((size_t)vertex_count * 6, sizeof(float)) : NULL;
    if (!out->vertices) {
        fprintf(stderr, "playground: lfem_body_add_skin: %s\n",
                s == LFEM_OK ? "out of memory for its vertex buffer" : lfem_last_error());
        free(triangles);
        return -1;
    }
    out->triangles = triangles; /* the skin keeps the caller's triangles as given */
    out->vertex_count = vertex_count;
    out->triangle_count = triangle_count;
    return 0;
}

int pg_skin_read(const lfem_world* world, lfem_body body, pg_mesh* mesh) {
    /* GL_N3F_V3F: the normal at floats 0..2 of each 6, the position at 3..5. The body's one
     * skin is its skin 0. */
    const lfem_status s = lfem_body_get_skin_vertices_f32(world, body, 0, mesh->vertices + 3, 6,
                                                          mesh->vertices, 6, mesh->vertex_count);
    if (s == LFEM_OK) return 0;
    fprintf(stderr, "playground: lfem_body_get_skin_vertices_f32: %s\n", lfem_last_error());
    return -1;
}
