/* The paper's two-bar impact (Fig. 3) as one timed benchmark run. */
#include "two_bar_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench_common.h"
#include "penalty_baseline.h"

/* The paper's Fig. 3. */
static const double kLength = 0.254;                      /* m, both bars */
static const double kWidth = 0.0254;                      /* m, along y */
static const double kHeight1 = 0.0254, kHeight2 = 0.0224; /* m, along z */
static const double kGap = 2.54e-4;                       /* m */
static const double kSpeed = 5.1359;                      /* m/s, each bar towards the other */
static const double kDensity = 7844.0;                    /* kg/m^3 */
static const double kYoung = 206.82e9;                    /* Pa */

two_bar_exact two_bar_exact_solution(void) {
    two_bar_exact a;
    const double area1 = kWidth * kHeight1, area2 = kWidth * kHeight2;
    a.wave_speed = sqrt(kYoung / kDensity);
    const double z1 = kDensity * a.wave_speed * area1, z2 = kDensity * a.wave_speed * area2;
    a.start = kGap / (2 * kSpeed);
    a.duration = 2 * kLength / a.wave_speed;
    a.force = z1 * z2 / (z1 + z2) * 2 * kSpeed;
    a.impulse = a.force * a.duration;
    a.v1 = kSpeed - a.impulse / (kDensity * area1 * kLength);
    a.v2 = -kSpeed + a.impulse / (kDensity * area2 * kLength);
    return a;
}

/* The contact force on bar 2 along +x in the last step: its nodes' multipliers, and the
 * opposite of bar 1's nodes' (whose reaction lands on bar 2's triangles). */
static int multiplier_force(lfem_world* world, lfem_body bar2, lfem_contact** contacts,
                            uint32_t* capacity, double* force) {
    uint32_t count = 0;
    if (bench_contacts(world, contacts, capacity, &count) != 0) return -1;
    double f = 0;
    for (uint32_t c = 0; c < count; ++c)
        f += ((*contacts)[c].body_a.index == bar2.index ? 1.0 : -1.0) * (*contacts)[c].force[0];
    *force = f;
    return 0;
}

int two_bar_run(const two_bar_config* config, two_bar_result* r) {
    const double start_wall = bench_now();
    lfem_world* world = NULL;
    penalty_contact* penalty = NULL;
    uint32_t contact_capacity = 256;
    lfem_contact* contacts = (lfem_contact*)malloc(sizeof(lfem_contact) * contact_capacity);
    if (!contacts) return -1;
    *r = (two_bar_result){0};

    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;                               /* the bars fly along x */
    wd.allow_unstable_step = config->step_ratio >= 1.0; /* finding where a step blows up */
    wd.mass_scaling_step = config->mass_scaling_step;
    BENCH_TRY(lfem_world_create(&wd, &world));

    /* Bar 1 on the left moving +x, bar 2 on the right moving -x, the gap split about x = 0.
     * With the penalty baseline (and without contact) the bars get filter groups that do not
     * collide: the springs alone keep them apart. */
    lfem_body_def def = lfem_body_def_default();
    def.model = config->model;
    def.composite_tets = config->quadratic == 2;
    def.young_modulus = kYoung;
    def.poisson_ratio = config->nu;
    def.density = kDensity;
    def.friction = 0.0; /* the faces meet head on */
    lfem_body bars[2];
    for (int b = 0; b < 2; ++b) {
        const double height = b == 0 ? kHeight1 : kHeight2;
        const double size[3] = {kLength, kWidth, height};
        const double offset[3] = {b == 0 ? -kLength - kGap / 2 : kGap / 2, -kWidth / 2, -height / 2};
        lfem_mesh* mesh = NULL;
        BENCH_TRY(lfem_mesh_create_box(size, config->cells, &mesh));
        lfem_status s = lfem_mesh_translate(mesh, offset);
        if (s == LFEM_OK && config->quadratic) s = lfem_mesh_make_quadratic(mesh);
        def.linear_velocity[0] = b == 0 ? kSpeed : -kSpeed;
        if (config->penalty_factor != 0) {
            def.category_bits = 1u << b;
            def.mask_bits = ~(3u); /* neither bar */
        }
        if (s == LFEM_OK) s = lfem_body_create(world, &def, &bars[b]);
        if (s == LFEM_OK) s = bench_add_mesh(world, bars[b], mesh);
        r->tets += lfem_mesh_get_tet_count(mesh);
        r->nodes += lfem_mesh_get_node_count(mesh);
        lfem_mesh_destroy(mesh);
        BENCH_TRY(s);
    }
    double mass[2], p0[2][3], p[2][3];
    for (int b = 0; b < 2; ++b) {
        BENCH_TRY(lfem_body_get_mass(world, bars[b], &mass[b]));
        double added = 0;
        BENCH_TRY(lfem_body_get_added_mass(world, bars[b], &added));
        r->added_mass += added;
        r->mass += mass[b];
        BENCH_TRY(lfem_body_get_momentum(world, bars[b], p0[b], NULL));
    }
    if (config->penalty_factor > 0) {
        /* k = factor * E A / l_e: the axial stiffness of one element of bar 2 (the smaller
         * face, the one that is loaded). */
        const double k = config->penalty_factor * kYoung * kWidth * kHeight2 /
                         (kLength / config->cells[0]);
        if (penalty_contact_create(world, bars[0], -kGap / 2, bars[1], kGap / 2, k, &penalty) != 0)
            goto fail;
    }

    BENCH_TRY(lfem_world_get_stable_step(world, &r->elastic_step));
    r->step = config->step_ratio * r->elastic_step;
    BENCH_TRY(lfem_world_set_time_step(world, r->step));
    lfem_world_stats s0, s;
    BENCH_TRY(lfem_world_get_stats(world, &s0));
    const double e0 = s0.kinetic_energy + s0.strain_energy;

    /* One sub-step a call: each step's contact force is one sample of the force history, and
     * the force of step n acts over [t_n, t_n+1] (the forward increment, and the penalty force
     * of x^n, both move the step from x^n to x^n+1). */
    const double h = r->step;
    const uint64_t steps = (uint64_t)ceil(config->end_time / h);
    double first = -1, last = -1, plateau_sum = 0, plateau_time = 0;
    r->stable = 1;
    for (uint64_t k = 0; k < steps; ++k) {
        double force = 0, depth = 0;
        if (penalty && penalty_contact_apply(penalty, world, &force, &depth) != 0) goto fail;
        const lfem_status status = lfem_world_step(world, h);
        if (status == LFEM_UNSTABLE) {
            r->stable = 0;
            break;
        }
        BENCH_TRY(status);
        BENCH_TRY(lfem_world_get_stats(world, &s));
        if (!penalty) {
            if (multiplier_force(world, bars[1], &contacts, &contact_capacity, &force) != 0) goto fail;
            depth = s.max_penetration;
        }
        /* A contact that adds energy is blowing up even before lfem's own test trips: a stable
         * step only ever loses some in an impact (multipliers) or stores it in the springs. */
        if (!(s.kinetic_energy + s.strain_energy <= 1.05 * e0)) {
            r->stable = 0;
            break;
        }
        ++r->steps;
        if (depth > r->max_penetration) r->max_penetration = depth;
        if (force > r->peak_force) r->peak_force = force;
        r->impulse += force * h;
        if (force > 0) {
            if (first < 0) first = s.time - h;
            last = s.time;
        }
        if (s.time - h >= 40e-6 && s.time <= 110e-6) plateau_sum += force * h, plateau_time += h;
    }
    BENCH_TRY(lfem_world_get_stats(world, &s));
    for (int b = 0; b < 2; ++b) BENCH_TRY(lfem_body_get_momentum(world, bars[b], p[b], NULL));
    r->plateau = plateau_time > 0 ? plateau_sum / plateau_time : 0;
    r->duration = first >= 0 ? last - first : 0;
    r->v1 = p[0][0] / mass[0];
    r->v2 = p[1][0] / mass[1];
    r->energy_change = (s.kinetic_energy + s.strain_energy) / e0 - 1;
    /* The run blew up if it ended with more energy than it began with (1 %: far above the
     * round-off of a closed frictionless impact, far below any growing instability). */
    if (r->energy_change > 0.01) r->stable = 0;
    penalty_contact_destroy(penalty);
    lfem_world_destroy(world);
    free(contacts);
    r->wall = bench_now() - start_wall;
    return 0;
fail:
    penalty_contact_destroy(penalty);
    lfem_world_destroy(world);
    free(contacts);
    return -1;
}
