/* Spinning body, cantilever and incline as timed benchmark runs (see validation_cases.h). */
#include "validation_cases.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A box mesh of the given size and cells (10-node tets when quadratic), moved by offset, added
 * to a new body; its tets and nodes are added to *r (nullable). */
static int add_box_body(lfem_world* world, const lfem_body_def* def, const double size[3],
                        const uint32_t cells[3], const double offset[3], int quadratic, lfem_body* body,
                        case_result* r) {
    lfem_mesh* mesh = NULL;
    BENCH_TRY(lfem_mesh_create_box(size, cells, &mesh));
    BENCH_TRY(lfem_mesh_translate(mesh, offset));
    if (quadratic) BENCH_TRY(lfem_mesh_make_quadratic(mesh));
    BENCH_TRY(lfem_body_create(world, def, body));
    BENCH_TRY(bench_add_mesh(world, *body, mesh));
    if (r) {
        r->tets += lfem_mesh_get_tet_count(mesh);
        r->nodes += lfem_mesh_get_node_count(mesh);
    }
    lfem_mesh_destroy(mesh);
    return 0;
fail:
    lfem_mesh_destroy(mesh);
    return -1;
}

/* Sum of signed tet volumes (m^3) of positions x; of the corners' tets of 10-node tets
 * (nodes_per_tet 10). */
static double mesh_volume(const double* x, const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet) {
    double v = 0;
    for (uint32_t e = 0; e < tet_count; ++e) {
        const uint32_t* t = tets + (size_t)nodes_per_tet * e;
        const double* a = &x[3 * t[0]];
        const double* b = &x[3 * t[1]];
        const double* c = &x[3 * t[2]];
        const double* d = &x[3 * t[3]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double p[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double q[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        v += (u[0] * (p[1] * q[2] - p[2] * q[1]) - u[1] * (p[0] * q[2] - p[2] * q[0]) +
              u[2] * (p[0] * q[1] - p[1] * q[0])) / 6.0;
    }
    return v;
}

static lfem_world_def world_def(double safety, double gx, double gz) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[0] = gx;
    wd.gravity[2] = gz;
    wd.step_safety = safety;
    return wd;
}

/* Fills the step, step count and wall time shared by every case. */
static int finish(lfem_world* world, double start_wall, case_result* r) {
    lfem_world_stats s;
    BENCH_TRY(lfem_world_get_stats(world, &s));
    r->steps = s.steps;
    r->step = s.step_size;
    r->wall = bench_now() - start_wall;
    return 0;
fail:
    return -1;
}

int spin_run(const case_config* c, case_result* r) {
    const double start_wall = bench_now();
    *r = (case_result){0};
    lfem_world* world = NULL;
    lfem_mesh* mesh = NULL;
    double* x = NULL;
    const lfem_world_def wd = world_def(c->safety, 0.0, 0.0);
    BENCH_TRY(lfem_world_create(&wd, &world));
    lfem_body_def def = lfem_body_def_default();
    def.model = c->model;
    def.composite_tets = c->quadratic == 2;
    def.young_modulus = 1e7;
    def.poisson_ratio = 0.3;
    def.angular_velocity[2] = 2 * M_PI; /* about z, the axis of largest inertia (stable) */
    const double size[3] = {0.2, 0.1, 0.05}, offset[3] = {-0.1, -0.05, -0.025};
    BENCH_TRY(lfem_mesh_create_box(size, c->cells, &mesh));
    BENCH_TRY(lfem_mesh_translate(mesh, offset));
    if (c->quadratic) BENCH_TRY(lfem_mesh_make_quadratic(mesh));
    lfem_body body;
    BENCH_TRY(lfem_body_create(world, &def, &body));
    const uint32_t nodes = lfem_mesh_get_node_count(mesh), tets = lfem_mesh_get_tet_count(mesh);
    const uint32_t per_tet = lfem_mesh_get_nodes_per_tet(mesh);
    BENCH_TRY(bench_add_mesh(world, body, mesh));
    r->tets = tets;
    r->nodes = nodes;
    x = (double*)malloc(sizeof(double) * 3 * nodes);
    if (!x) goto fail;
    lfem_world_stats s0, s;
    BENCH_TRY(lfem_world_get_stats(world, &s0));
    const double v0 = mesh_volume(lfem_mesh_get_positions(mesh), lfem_mesh_get_tets(mesh), tets, per_tet);
    /* Calls of 1/100 turn: their boundaries do not fall on sub-step multiples. */
    const double duration = c->duration > 0 ? c->duration : 1.0;
    const int calls = (int)ceil(duration / 0.01 - 1e-9);
    for (int k = 0; k < calls; ++k) BENCH_TRY(lfem_world_step(world, 0.01));
    BENCH_TRY(lfem_world_get_stats(world, &s));
    BENCH_TRY(lfem_body_get_positions(world, body, x, nodes));
    double dl = 0, l0 = 0;
    for (int k = 0; k < 3; ++k) {
        dl += pow(s.angular_momentum[k] - s0.angular_momentum[k], 2);
        l0 += pow(s0.angular_momentum[k], 2);
    }
    r->error = sqrt(dl / l0);
    r->second_error = s.kinetic_energy / s0.kinetic_energy - 1;
    r->third_error = mesh_volume(x, lfem_mesh_get_tets(mesh), tets, per_tet) / v0 - 1;
    if (finish(world, start_wall, r) != 0) goto fail;
    free(x);
    lfem_mesh_destroy(mesh);
    lfem_world_destroy(world);
    return 0;
fail:
    free(x);
    lfem_mesh_destroy(mesh);
    lfem_world_destroy(world);
    return -1;
}

int cantilever_run(const case_config* c, case_result* r) {
    const double start_wall = bench_now();
    *r = (case_result){0};
    lfem_world* world = NULL;
    uint32_t *clamped = NULL, *tip = NULL;
    double* x = NULL;
    const double L = 0.5, b = 0.05, E = 6e8, rho = 1000.0, g = 9.81;
    const lfem_world_def wd = world_def(c->safety, 0.0, -g);
    BENCH_TRY(lfem_world_create(&wd, &world));
    lfem_body_def def = lfem_body_def_default();
    def.model = c->model;
    def.composite_tets = c->quadratic == 2;
    def.young_modulus = E;
    def.poisson_ratio = 0.0; /* Euler-Bernoulli has no Poisson coupling */
    def.density = rho;
    const double I = b * b * b * b / 12.0, A = b * b;
    const double omega1 = 1.875104 * 1.875104 * sqrt(E * I / (rho * A * L * L * L * L));
    def.damping = 2.0 * omega1; /* critical for the first bending mode: settles fastest */
    const double size[3] = {L, b, b}, offset[3] = {0, -b / 2, -b / 2};
    lfem_body beam;
    if (add_box_body(world, &def, size, c->cells, offset, c->quadratic, &beam, r) != 0) goto fail;
    uint32_t nodes = 0, n_clamped = 0, n_tip = 0;
    BENCH_TRY(lfem_body_get_node_count(world, beam, &nodes));
    clamped = (uint32_t*)malloc(sizeof(uint32_t) * nodes);
    tip = (uint32_t*)malloc(sizeof(uint32_t) * nodes);
    x = (double*)malloc(sizeof(double) * 3 * nodes);
    if (!clamped || !tip || !x) goto fail;
    const double lo[3] = {-1e-9, -1, -1}, hi[3] = {1e-9, 1, 1};
    const double tlo[3] = {L - 1e-9, -1, -1}, thi[3] = {L + 1e-9, 1, 1};
    BENCH_TRY(lfem_body_find_nodes_in_box(world, beam, lo, hi, clamped, nodes, &n_clamped));
    BENCH_TRY(lfem_body_find_nodes_in_box(world, beam, tlo, thi, tip, nodes, &n_tip));
    BENCH_TRY(lfem_body_fix_nodes(world, beam, clamped, n_clamped));
    double z0 = 0; /* the tip's mean height before loading */
    BENCH_TRY(lfem_body_get_positions(world, beam, x, nodes));
    for (uint32_t i = 0; i < n_tip; ++i) z0 += x[3 * tip[i] + 2] / n_tip;
    /* 10 / omega1: the first mode decays like (1 + w t) e^{-w t} to ~5e-4 of its amplitude. */
    BENCH_TRY(lfem_world_step(world, c->duration > 0 ? c->duration : 10.0 / omega1));
    BENCH_TRY(lfem_body_get_positions(world, beam, x, nodes));
    double z = 0;
    for (uint32_t i = 0; i < n_tip; ++i) z += x[3 * tip[i] + 2] / n_tip;
    const double expected = rho * g * A * pow(L, 4) / (8 * E * I);
    r->error = (z0 - z) / expected - 1;
    if (finish(world, start_wall, r) != 0) goto fail;
    free(clamped);
    free(tip);
    free(x);
    lfem_world_destroy(world);
    return 0;
fail:
    free(clamped);
    free(tip);
    free(x);
    lfem_world_destroy(world);
    return -1;
}

int incline_run(const case_config* c, case_result* r) {
    const double start_wall = bench_now();
    *r = (case_result){0};
    lfem_world* world = NULL;
    /* The incline is a horizontal static floor with gravity tilted by 30 degrees: the same
     * physics without a rotated mesh. */
    const double angle = M_PI / 6, g = 9.81, mu = 0.3;
    lfem_world_def wd = world_def(c->safety, g * sin(angle), -g * cos(angle));
    wd.mass_scaling_step = c->mass_scaling_step;
    BENCH_TRY(lfem_world_create(&wd, &world));
    lfem_body_def floor_def = lfem_body_def_default();
    floor_def.type = LFEM_BODY_STATIC;
    floor_def.friction = mu;
    const double floor_size[3] = {2.0, 0.5, 0.1}, floor_offset[3] = {-0.5, -0.25, -0.1};
    const uint32_t floor_cells[3] = {8, 2, 1};
    lfem_body floor_body, block;
    if (add_box_body(world, &floor_def, floor_size, floor_cells, floor_offset, 0, &floor_body, NULL) != 0)
        goto fail;
    lfem_body_def def = lfem_body_def_default();
    def.model = c->model;
    def.composite_tets = c->quadratic == 2;
    def.young_modulus = 1e6;
    def.friction = mu;
    const double size[3] = {0.1, 0.1, 0.1}, offset[3] = {-0.05, -0.05, 0.0};
    if (add_box_body(world, &def, size, c->cells, offset, c->quadratic, &block, r) != 0) goto fail;
    double mass = 0, p0[3], p1[3];
    lfem_world_stats s0, s1;
    BENCH_TRY(lfem_body_get_mass(world, block, &mass));
    double added = 0;
    BENCH_TRY(lfem_body_get_added_mass(world, block, &added));
    r->added_mass_share = added / mass;
    /* Undamped: the normal force rings after the sudden load at the block's axial frequency
     * (~1 kHz); averaged over 0.4 s the ringing cancels. */
    BENCH_TRY(lfem_world_step(world, 0.05));
    BENCH_TRY(lfem_world_get_stats(world, &s0));
    BENCH_TRY(lfem_body_get_momentum(world, block, p0, NULL));
    BENCH_TRY(lfem_world_step(world, c->duration > 0 ? c->duration : 0.4));
    BENCH_TRY(lfem_world_get_stats(world, &s1));
    BENCH_TRY(lfem_body_get_momentum(world, block, p1, NULL));
    const double a = (p1[0] - p0[0]) / mass / (s1.time - s0.time);
    r->error = a / (g * (sin(angle) - mu * cos(angle))) - 1;
    r->second_error = s1.max_penetration;
    if (finish(world, start_wall, r) != 0) goto fail;
    lfem_world_destroy(world);
    return 0;
fail:
    lfem_world_destroy(world);
    return -1;
}
