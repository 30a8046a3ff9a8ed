/* skin: see skin.h.
 * TEMPORARY until lfem_body_add_skin is on this branch: the "skin" is the body's boundary
 * triangles, its normals summed here. */
#include "skin.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pg_math.h"

int pg_skin_bind(lfem_world* world, lfem_body body, const double size[3], const double at[3],
                 double rounding, uint32_t cells, pg_mesh* out) {
    (void)size, (void)at, (void)rounding, (void)cells;
    uint32_t nodes = 0, triangles = 0;
    if (lfem_body_get_node_count(world, body, &nodes) != LFEM_OK ||
        lfem_body_get_boundary_triangle_count(world, body, &triangles) != LFEM_OK)
        return -1;
    out->vertices = (float*)calloc((size_t)nodes * 6, sizeof(float));
    out->triangles = (uint32_t*)malloc(sizeof(uint32_t) * 3 * triangles);
    if (!out->vertices || !out->triangles) return -1;
    out->vertex_count = nodes;
    out->triangle_count = triangles;
    return lfem_body_get_boundary_triangles(world, body, out->triangles, triangles) == LFEM_OK ? 0 : -1;
}

int pg_skin_read(const lfem_world* world, lfem_body body, pg_mesh* mesh) {
    double* p = (double*)malloc(sizeof(double) * 3 * mesh->vertex_count);
    double* n = (double*)calloc(3 * (size_t)mesh->vertex_count, sizeof(double));
    if (!p || !n || lfem_body_get_positions(world, body, p, mesh->vertex_count) != LFEM_OK) {
        free(p), free(n);
        return -1;
    }
    for (uint32_t t = 0; t < mesh->triangle_count; ++t) {
        const uint32_t* tri = mesh->triangles + 3 * t;
        double e1[3], e2[3], c[3];
        v3_sub(p + 3 * tri[1], p + 3 * tri[0], e1);
        v3_sub(p + 3 * tri[2], p + 3 * tri[0], e2);
        v3_cross(e1, e2, c);
        for (int k = 0; k < 3; ++k) v3_add_scaled(n + 3 * tri[k], 1, c, n + 3 * tri[k]);
    }
    for (uint32_t i = 0; i < mesh->vertex_count; ++i) {
        v3_normalize(n + 3 * i);
        for (int k = 0; k < 3; ++k) mesh->vertices[6 * i + k] = (float)n[3 * i + k], mesh->vertices[6 * i + 3 + k] = (float)p[3 * i + k];
    }
    free(p), free(n);
    return 0;
}
