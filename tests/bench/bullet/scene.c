/* The benchmark scene's mesh, placement and per-frame measurements (see scene.h). */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lfem.h"

int bench_scene_build_mesh(bench_scene* s) {
    const double size[3] = {s->edge, s->edge, s->edge};
    const uint32_t cells[3] = {s->cells, s->cells, s->cells};
    lfem_mesh* mesh = NULL;
    uint32_t e, k;
    if (lfem_mesh_create_box(size, cells, &mesh) != LFEM_OK) {
        fprintf(stderr, "lfem_mesh_create_box: %s\n", lfem_last_error());
        return -1;
    }
    s->node_count = lfem_mesh_get_node_count(mesh);
    s->tet_count = lfem_mesh_get_tet_count(mesh);
    s->positions = malloc(3 * sizeof(double) * s->node_count);
    s->tets = malloc(4 * sizeof(uint32_t) * s->tet_count);
    s->node_mass = calloc(s->node_count, sizeof(double));
    if (!s->positions || !s->tets || !s->node_mass) {
        fprintf(stderr, "out of memory\n");
        lfem_mesh_destroy(mesh);
        bench_scene_free_mesh(s);
        return -1;
    }
    memcpy(s->positions, lfem_mesh_get_positions(mesh), 3 * sizeof(double) * s->node_count);
    memcpy(s->tets, lfem_mesh_get_tets(mesh), 4 * sizeof(uint32_t) * s->tet_count);
    lfem_mesh_destroy(mesh);
    /* Lumped masses as lfem computes them (src/DESIGN.md section 5): rho V_e / 4 to each corner,
     * so Bullet's nodes carry exactly the same mass. */
    for (e = 0; e < s->tet_count; ++e) {
        const uint32_t* t = s->tets + 4 * e;
        const double* a = s->positions + 3 * t[0];
        double d[3][3], vol;
        for (k = 0; k < 3; ++k) {
            const double* b = s->positions + 3 * t[k + 1];
            d[k][0] = b[0] - a[0], d[k][1] = b[1] - a[1], d[k][2] = b[2] - a[2];
        }
        vol = (d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
               d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
               d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0])) / 6.0;
        for (k = 0; k < 4; ++k) s->node_mass[t[k]] += s->density * fabs(vol) / 4.0;
    }
    return 0;
}

void bench_scene_free_mesh(bench_scene* s) {
    free(s->positions);
    free(s->tets);
    free(s->node_mass);
    s->positions = NULL, s->tets = NULL, s->node_mass = NULL;
}

/* Cubes on a grid centred on the origin, each `spacing` apart, bottoms `drop` above z = 0. */
void bench_scene_cube_offset(const bench_scene* s, uint32_t k, double offset[3]) {
    const double pitch = s->edge + s->spacing;
    const double half = 0.5 * (double)(s->grid - 1) * pitch + 0.5 * s->edge;
    offset[0] = (double)(k % s->grid) * pitch - half;
    offset[1] = (double)(k / s->grid) * pitch - half;
    offset[2] = s->drop;
}

void bench_meter_add(bench_meter* m, const double* x, const double* v, uint32_t nodes, int rest) {
    uint32_t i;
    for (i = 0; i < nodes; ++i) {
        if (-x[3 * i + 2] > m->max_penetration) m->max_penetration = -x[3 * i + 2];
        if (rest) {
            const double* w = v + 3 * i;
            m->rest_sum_v2 += w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        }
    }
    if (rest) m->rest_samples += nodes;
}
