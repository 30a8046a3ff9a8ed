/* The lfem side of the benchmark: the scene of scene.h through the public C API
 * (neo-Hookean cubes, a static plane as the floor), stepped frame by frame. */
#include "run_lfem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../bench_common.h"

bench_result bench_run_lfem(const bench_scene* s, lfem_profile* profile) {
    bench_result r;
    bench_meter meter;
    lfem_world_def wd = lfem_world_def_default();
    lfem_body_def floor_def = lfem_body_def_default(), cube_def = lfem_body_def_default();
    lfem_shape_def plane = lfem_shape_def_default();
    lfem_world* w = NULL;
    lfem_body floor_body, *cubes = NULL;
    lfem_world_stats st;
    double *x = NULL, *v = NULL, *placed = NULL;
    const uint32_t cube_count = s->grid * s->grid, nodes = s->node_count;
    const uint32_t frames = (uint32_t)lround(s->duration / s->frame);
    const uint32_t rest_from = frames - frames / 10; /* the last 10 % of the frames */
    uint32_t k, f, i;

    memset(&r, 0, sizeof r);
    memset(&meter, 0, sizeof meter);
    cubes = calloc(cube_count, sizeof *cubes);
    x = malloc(3 * sizeof(double) * nodes);
    v = malloc(3 * sizeof(double) * nodes);
    placed = malloc(3 * sizeof(double) * nodes);
    if (!cubes || !x || !v || !placed) goto fail;

    wd.time_step = s->lfem_step; /* gravity: default (0, 0, -9.81) m/s^2 */
    if (s->lfem_threads) wd.thread_count = s->lfem_threads;
    BENCH_TRY(lfem_world_create(&wd, &w));

    /* The floor: the half-space z < 0 (a closed-form shape query, no libccd). */
    floor_def.type = LFEM_BODY_STATIC;
    floor_def.friction = s->friction;
    BENCH_TRY(lfem_body_create(w, &floor_def, &floor_body));
    plane.type = LFEM_SHAPE_PLANE;
    BENCH_TRY(lfem_body_add_shape(w, floor_body, &plane, NULL));

    cube_def.model = LFEM_MODEL_NEO_HOOKEAN;
    cube_def.young_modulus = s->young_modulus;
    cube_def.poisson_ratio = s->poisson_ratio;
    cube_def.density = s->density;
    cube_def.damping = s->lfem_damping;
    cube_def.friction = s->friction;
    for (k = 0; k < cube_count; ++k) {
        double off[3];
        bench_scene_cube_offset(s, k, off);
        for (i = 0; i < 3 * nodes; ++i) placed[i] = s->positions[i] + off[i % 3];
        BENCH_TRY(lfem_body_create(w, &cube_def, &cubes[k]));
        BENCH_TRY(lfem_body_add_mesh(w, cubes[k], placed, nodes, s->tets, s->tet_count));
    }
    BENCH_TRY(lfem_world_reset_profile(w));

    r.step_min = HUGE_VAL;
    for (f = 0; f < frames; ++f) {
        const double t0 = bench_now();
        BENCH_TRY(lfem_world_step(w, s->frame));
        r.wall_seconds += bench_now() - t0;
        BENCH_TRY(lfem_world_get_stats(w, &st));
        if (st.step_size < r.step_min) r.step_min = st.step_size;
        if (st.step_size > r.step_max) r.step_max = st.step_size;
        if (f == 0 || st.stable_step < r.stable_limit) r.stable_limit = st.stable_step;
        if (st.max_penetration > meter.max_penetration) meter.max_penetration = st.max_penetration;
        for (k = 0; k < cube_count; ++k) {
            BENCH_TRY(lfem_body_get_positions(w, cubes[k], x, nodes));
            BENCH_TRY(lfem_body_get_velocities(w, cubes[k], v, nodes));
            bench_meter_add(&meter, x, v, nodes, f >= rest_from);
            if (f + 1 == frames)
                for (i = 0; i < nodes; ++i) {
                    const double z = x[3 * i + 2];
                    if ((k == 0 && i == 0) || z < r.lowest_final) r.lowest_final = z;
                    if ((k == 0 && i == 0) || z > r.top_final) r.top_final = z;
                }
        }
    }
    BENCH_TRY(lfem_world_get_stats(w, &st));
    if (profile) BENCH_TRY(lfem_world_get_profile(w, profile));
    r.simulated_seconds = st.time;
    r.steps = (double)st.steps;
    r.tets = (double)s->tet_count * cube_count;
    r.max_penetration = meter.max_penetration;
    r.rest_rms_velocity = sqrt(meter.rest_sum_v2 / meter.rest_samples);
    r.ok = 1;
fail:
    lfem_world_destroy(w);
    free(cubes);
    free(x);
    free(v);
    free(placed);
    return r;
}
