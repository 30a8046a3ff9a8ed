/* Hertz impact as one timed benchmark run (hertz_scene.h). */
#include "hertz_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"

/* A steel ball: the contact lasts about 20 R / c_d or more, long against the sphere's lowest
 * vibration period (about 2 R / c), as Hertz's quasi-static theory assumes. */
static const double kRadius = 0.05;    /* m */
static const double kYoung = 200e9;    /* Pa */
static const double kPoisson = 0.3;
static const double kDensity = 7800.0; /* kg/m^3 */

double hertz_radius(void) { return kRadius; }

hertz_exact hertz_exact_solution(double m, double R, double E, double nu, double v) {
    hertz_exact h;
    h.effective_modulus = E / (1 - nu * nu);
    h.approach = pow(15 * m * v * v / (16 * h.effective_modulus * sqrt(R)), 0.4);
    h.force = 4.0 / 3.0 * h.effective_modulus * sqrt(R) * pow(h.approach, 1.5);
    /* int_0^1 (1 - x^p)^-1/2 dx = B(1/p, 1/2) / p with p = 5/2 (the approach against time). */
    const double p = 2.5, integral = tgamma(1 / p) * tgamma(0.5) / tgamma(1 / p + 0.5) / p;
    h.duration = 2 * h.approach / v * integral;
    return h;
}

/* The summed contact force on the sphere along +z in the last step (N). */
static int contact_force(lfem_world* world, lfem_contact** contacts, uint32_t* capacity, double* force) {
    uint32_t count = 0;
    if (bench_contacts(world, contacts, capacity, &count) != 0) return -1;
    double f = 0;
    for (uint32_t c = 0; c < count; ++c) f += (*contacts)[c].force[2];
    *force = f;
    return 0;
}

int hertz_run(const hertz_config* config, hertz_result* r) {
    const double start_wall = bench_now();
    lfem_world* world = NULL;
    lfem_mesh* mesh = NULL;
    uint32_t capacity = 256;
    lfem_contact* contacts = (lfem_contact*)malloc(sizeof(lfem_contact) * capacity);
    if (!contacts) return -1;
    *r = (hertz_result){0};
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0; /* Hertz's impact has none */
    BENCH_TRY(lfem_world_create(&wd, &world));
    BENCH_TRY(lfem_mesh_load_gmsh(config->mesh_path, &mesh));
    r->tets = lfem_mesh_get_tet_count(mesh);
    r->nodes = lfem_mesh_get_node_count(mesh);
    r->nodes_per_tet = lfem_mesh_get_nodes_per_tet(mesh);
    lfem_body_def def = lfem_body_def_default();
    def.model = config->model;
    def.composite_tets = (uint8_t)config->composite;
    def.young_modulus = kYoung;
    def.poisson_ratio = kPoisson;
    def.density = kDensity;
    def.friction = 0.0; /* Hertz's contact is frictionless */
    def.linear_velocity[2] = -config->speed; /* straight down */
    lfem_body sphere, floor_body;
    BENCH_TRY(lfem_body_create(world, &def, &sphere));
    BENCH_TRY(bench_add_mesh(world, sphere, mesh));
    /* The plane just below the lowest node: contact starts within a step or two. */
    double lowest = 0;
    const double* x = lfem_mesh_get_positions(mesh);
    for (uint32_t i = 0; i < r->nodes; ++i)
        if (x[3 * i + 2] < lowest) lowest = x[3 * i + 2];
    lfem_body_def floor_def = lfem_body_def_default();
    floor_def.type = LFEM_BODY_STATIC;
    floor_def.friction = 0.0;
    BENCH_TRY(lfem_body_create(world, &floor_def, &floor_body));
    lfem_shape_def plane = lfem_shape_def_default();
    plane.type = LFEM_SHAPE_PLANE;
    plane.center[2] = lowest - 1e-7;
    BENCH_TRY(lfem_body_add_shape(world, floor_body, &plane, NULL));
    BENCH_TRY(lfem_body_get_mass(world, sphere, &r->mass));
    r->exact = hertz_exact_solution(r->mass, kRadius, kYoung, kPoisson, config->speed);

    double limit = 0;
    BENCH_TRY(lfem_world_get_stable_step(world, &limit));
    r->step = config->step_ratio * limit;
    BENCH_TRY(lfem_world_set_time_step(world, r->step));
    /* One sub-step a call, each a sample of the force; until the sphere has left the plane
     * (no force for a tenth of the expected contact time after some), at most 2 contact times. */
    const uint64_t max_steps = (uint64_t)ceil(2 * r->exact.duration / r->step);
    double first = -1, last = -1;
    for (uint64_t k = 0; k < max_steps; ++k) {
        BENCH_TRY(lfem_world_step(world, r->step));
        lfem_world_stats s;
        BENCH_TRY(lfem_world_get_stats(world, &s));
        double force = 0;
        if (contact_force(world, &contacts, &capacity, &force) != 0) goto fail;
        ++r->steps;
        if (s.max_penetration > r->max_penetration) r->max_penetration = s.max_penetration;
        if (force > r->peak_force) r->peak_force = force;
        if (force > 0) {
            if (first < 0) first = s.time - r->step;
            last = s.time;
        } else if (last > 0 && s.time - last > 0.1 * r->exact.duration) {
            break;
        }
    }
    r->duration = first >= 0 ? last - first : 0;
    lfem_mesh_destroy(mesh);
    lfem_world_destroy(world);
    free(contacts);
    r->wall = bench_now() - start_wall;
    return 0;
fail:
    lfem_mesh_destroy(mesh);
    lfem_world_destroy(world);
    free(contacts);
    return -1;
}
