/* BASELINE: explicit node-to-surface penalty contact through the public API (see
 * penalty_baseline.h for what it is and why it exists). */
#include "penalty_baseline.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"

struct penalty_contact {
    lfem_body master, slave;
    uint32_t master_nodes, slave_nodes; /* node counts of the whole bodies */
    double* x_master;                   /* 3 * master_nodes, positions read each step */
    double* x_slave;                    /* 3 * slave_nodes */
    /* One pair per slave face node that lies over the master face. */
    uint32_t pair_count;
    uint32_t* pair_node;       /* slave node index */
    double* pair_stiffness;    /* N/m, its share of the total by tributary area */
    uint32_t* pair_face_node;  /* 3 per pair: indices into face_node of the master triangle */
    double* pair_weight;       /* 3 per pair: barycentric weights of the touched point */
    double* pair_force;        /* 3 per pair, the forces handed to lfem */
    /* The master face's nodes and their forces. */
    uint32_t face_count;
    uint32_t* face_node;       /* master node index */
    double* face_force;        /* 3 per face node */
};

/* Boundary triangles of a body whose three nodes all lie on the plane x = face_x. Returns the
 * count (written to tris[3 * count]), or -1. */
static int face_triangles(lfem_world* world, lfem_body body, const double* x, double face_x,
                          uint32_t** out) {
    uint32_t count = 0, kept = 0;
    uint32_t* tris = NULL;
    BENCH_TRY(lfem_body_get_boundary_triangle_count(world, body, &count));
    tris = (uint32_t*)malloc(sizeof(uint32_t) * 3 * (count ? count : 1));
    if (!tris) goto fail;
    BENCH_TRY(lfem_body_get_boundary_triangles(world, body, tris, count));
    for (uint32_t t = 0; t < count; ++t) {
        int on_face = 1;
        for (int k = 0; k < 3; ++k) on_face &= fabs(x[3 * tris[3 * t + k]] - face_x) < 1e-9;
        if (!on_face) continue;
        for (int k = 0; k < 3; ++k) tris[3 * kept + k] = tris[3 * t + k];
        ++kept;
    }
    *out = tris;
    return (int)kept;
fail:
    free(tris);
    return -1;
}

/* Barycentric weights of point (y, z) in the triangle (a, b, c) projected on the y-z plane;
 * 1 when the point lies inside (with a hair of tolerance for points on an edge). */
static int inside_yz(const double* a, const double* b, const double* c, double y, double z,
                     double w[3]) {
    const double ub = b[1] - a[1], vb = b[2] - a[2], uc = c[1] - a[1], vc = c[2] - a[2];
    const double det = ub * vc - uc * vb, py = y - a[1], pz = z - a[2];
    if (det == 0) return 0;
    w[1] = (py * vc - uc * pz) / det;
    w[2] = (ub * pz - py * vb) / det;
    w[0] = 1 - w[1] - w[2];
    const double tol = -1e-9;
    return w[0] >= tol && w[1] >= tol && w[2] >= tol;
}

void penalty_contact_destroy(penalty_contact* p) {
    if (!p) return;
    free(p->x_master);
    free(p->x_slave);
    free(p->pair_node);
    free(p->pair_stiffness);
    free(p->pair_face_node);
    free(p->pair_weight);
    free(p->pair_force);
    free(p->face_node);
    free(p->face_force);
    free(p);
}

int penalty_contact_create(lfem_world* world, lfem_body master, double master_face_x,
                           lfem_body slave, double slave_face_x, double total_stiffness,
                           penalty_contact** out) {
    uint32_t *slave_tris = NULL, *master_tris = NULL, *cell_start = NULL, *cell_tris = NULL,
             *face_index = NULL;
    double* area = NULL;
    penalty_contact* p = (penalty_contact*)calloc(1, sizeof *p);
    if (!p) return -1;
    p->master = master;
    p->slave = slave;
    BENCH_TRY(lfem_body_get_node_count(world, master, &p->master_nodes));
    BENCH_TRY(lfem_body_get_node_count(world, slave, &p->slave_nodes));
    p->x_master = (double*)malloc(sizeof(double) * 3 * p->master_nodes);
    p->x_slave = (double*)malloc(sizeof(double) * 3 * p->slave_nodes);
    area = (double*)calloc(p->slave_nodes, sizeof(double));
    face_index = (uint32_t*)malloc(sizeof(uint32_t) * p->master_nodes);
    if (!p->x_master || !p->x_slave || !area || !face_index) goto fail;
    BENCH_TRY(lfem_body_get_positions(world, master, p->x_master, p->master_nodes));
    BENCH_TRY(lfem_body_get_positions(world, slave, p->x_slave, p->slave_nodes));
    const int n_slave = face_triangles(world, slave, p->x_slave, slave_face_x, &slave_tris);
    const int n_master = face_triangles(world, master, p->x_master, master_face_x, &master_tris);
    if (n_slave <= 0 || n_master <= 0) {
        fprintf(stderr, "penalty baseline: no face at x = %g or %g\n", slave_face_x, master_face_x);
        goto fail;
    }

    /* Tributary areas of the slave face nodes: a third of each triangle to each corner. */
    double total_area = 0;
    for (int t = 0; t < n_slave; ++t) {
        const double* a = &p->x_slave[3 * slave_tris[3 * t]];
        const double* b = &p->x_slave[3 * slave_tris[3 * t + 1]];
        const double* c = &p->x_slave[3 * slave_tris[3 * t + 2]];
        const double s = 0.5 * fabs((b[1] - a[1]) * (c[2] - a[2]) - (c[1] - a[1]) * (b[2] - a[2]));
        for (int k = 0; k < 3; ++k) area[slave_tris[3 * t + k]] += s / 3;
        total_area += s;
    }

    /* The master triangles bucketed on a uniform y-z grid by centroid (counting sort), so each
     * slave node looks at a few cells only: O(n), not slaves x triangles. */
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int t = 0; t < 3 * n_master; ++t)
        for (int d = 0; d < 2; ++d) {
            lo[d] = fmin(lo[d], p->x_master[3 * master_tris[t] + 1 + d]);
            hi[d] = fmax(hi[d], p->x_master[3 * master_tris[t] + 1 + d]);
        }
    const int grid = (int)ceil(sqrt(n_master / 2.0));
    /* A face of zero extent in y or z (a degenerate strip) still gets cells of positive size. */
    const double cell[2] = {hi[0] > lo[0] ? (hi[0] - lo[0]) / grid : 1.0,
                            hi[1] > lo[1] ? (hi[1] - lo[1]) / grid : 1.0};
    cell_start = (uint32_t*)calloc((size_t)grid * grid + 1, sizeof(uint32_t));
    cell_tris = (uint32_t*)malloc(sizeof(uint32_t) * n_master);
    if (!cell_start || !cell_tris) goto fail;
    int* tri_cell = (int*)malloc(sizeof(int) * n_master);
    if (!tri_cell) goto fail;
    for (int t = 0; t < n_master; ++t) {
        double y = 0, z = 0;
        for (int k = 0; k < 3; ++k) {
            y += p->x_master[3 * master_tris[3 * t + k] + 1] / 3;
            z += p->x_master[3 * master_tris[3 * t + k] + 2] / 3;
        }
        const int iy = (int)((y - lo[0]) / cell[0]), iz = (int)((z - lo[1]) / cell[1]);
        tri_cell[t] = (iy < 0 ? 0 : iy >= grid ? grid - 1 : iy) * grid +
                      (iz < 0 ? 0 : iz >= grid ? grid - 1 : iz);
        ++cell_start[tri_cell[t] + 1];
    }
    for (int c = 0; c < grid * grid; ++c) cell_start[c + 1] += cell_start[c];
    {
        uint32_t* fill = (uint32_t*)malloc(sizeof(uint32_t) * grid * grid);
        if (!fill) {
            free(tri_cell);
            goto fail;
        }
        for (int c = 0; c < grid * grid; ++c) fill[c] = cell_start[c];
        for (int t = 0; t < n_master; ++t) cell_tris[fill[tri_cell[t]]++] = (uint32_t)t;
        free(fill);
    }
    free(tri_cell);

    /* The pairs: each slave face node over the master face, with the master triangle under it. */
    p->pair_node = (uint32_t*)malloc(sizeof(uint32_t) * p->slave_nodes);
    p->pair_stiffness = (double*)malloc(sizeof(double) * p->slave_nodes);
    p->pair_face_node = (uint32_t*)malloc(sizeof(uint32_t) * 3 * p->slave_nodes);
    p->pair_weight = (double*)malloc(sizeof(double) * 3 * p->slave_nodes);
    p->pair_force = (double*)calloc(3 * (size_t)p->slave_nodes, sizeof(double));
    p->face_node = (uint32_t*)malloc(sizeof(uint32_t) * p->master_nodes);
    if (!p->pair_node || !p->pair_stiffness || !p->pair_face_node || !p->pair_weight ||
        !p->pair_force || !p->face_node)
        goto fail;
    for (uint32_t i = 0; i < p->master_nodes; ++i) face_index[i] = UINT32_MAX;
    for (uint32_t s = 0; s < p->slave_nodes; ++s) {
        if (area[s] == 0) continue;
        const double y = p->x_slave[3 * s + 1], z = p->x_slave[3 * s + 2];
        const int iy = (int)floor((y - lo[0]) / cell[0]), iz = (int)floor((z - lo[1]) / cell[1]);
        int found = 0;
        for (int cy = iy - 1; cy <= iy + 1 && !found; ++cy)
            for (int cz = iz - 1; cz <= iz + 1 && !found; ++cz) {
                if (cy < 0 || cz < 0 || cy >= grid || cz >= grid) continue;
                const int c = cy * grid + cz;
                for (uint32_t j = cell_start[c]; j < cell_start[c + 1] && !found; ++j) {
                    const uint32_t* tri = &master_tris[3 * cell_tris[j]];
                    double w[3];
                    if (!inside_yz(&p->x_master[3 * tri[0]], &p->x_master[3 * tri[1]],
                                   &p->x_master[3 * tri[2]], y, z, w))
                        continue;
                    found = 1;
                    const uint32_t q = p->pair_count++;
                    p->pair_node[q] = s;
                    p->pair_stiffness[q] = total_stiffness * area[s] / total_area;
                    for (int k = 0; k < 3; ++k) {
                        if (face_index[tri[k]] == UINT32_MAX) {
                            face_index[tri[k]] = p->face_count;
                            p->face_node[p->face_count++] = tri[k];
                        }
                        p->pair_face_node[3 * q + k] = face_index[tri[k]];
                        p->pair_weight[3 * q + k] = w[k];
                    }
                }
            }
    }
    p->face_force = (double*)calloc(3 * (size_t)(p->face_count ? p->face_count : 1), sizeof(double));
    if (!p->face_force || p->pair_count == 0) goto fail;
    free(slave_tris);
    free(master_tris);
    free(cell_start);
    free(cell_tris);
    free(face_index);
    free(area);
    *out = p;
    return 0;
fail:
    free(slave_tris);
    free(master_tris);
    free(cell_start);
    free(cell_tris);
    free(face_index);
    free(area);
    penalty_contact_destroy(p);
    return -1;
}

int penalty_contact_apply(penalty_contact* p, lfem_world* world, double* force,
                          double* penetration) {
    BENCH_TRY(lfem_body_get_positions(world, p->master, p->x_master, p->master_nodes));
    BENCH_TRY(lfem_body_get_positions(world, p->slave, p->x_slave, p->slave_nodes));
    for (uint32_t f = 0; f < 3 * p->face_count; ++f) p->face_force[f] = 0;
    double total = 0, deepest = 0;
    for (uint32_t q = 0; q < p->pair_count; ++q) {
        /* The master face's x under the slave node, and how far the node is behind it. */
        double face_x = 0;
        for (int k = 0; k < 3; ++k)
            face_x += p->pair_weight[3 * q + k] *
                      p->x_master[3 * p->face_node[p->pair_face_node[3 * q + k]]];
        const double d = face_x - p->x_slave[3 * p->pair_node[q]];
        const double f = d > 0 ? p->pair_stiffness[q] * d : 0.0;
        p->pair_force[3 * q] = f;
        for (int k = 0; k < 3; ++k)
            p->face_force[3 * p->pair_face_node[3 * q + k]] -= p->pair_weight[3 * q + k] * f;
        total += f;
        if (d > deepest) deepest = d;
    }
    BENCH_TRY(lfem_body_set_node_forces(world, p->slave, p->pair_node, p->pair_count, p->pair_force));
    BENCH_TRY(lfem_body_set_node_forces(world, p->master, p->face_node, p->face_count, p->face_force));
    *force = total;
    *penetration = deepest;
    return 0;
fail:
    return -1;
}
