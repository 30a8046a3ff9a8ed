/* Queries against scene size (issue 17): what a ray cast, an all-hits cast and a box overlap
 * cost in a scene of 4, 32 and 256 floating soft cubes (2^3 cells, 48 tets, 0.1 m, 0.3 m apart,
 * drifting so that every step moves them), always aimed at the same two cubes, and what the
 * step pays to keep the queries' cache current once they are in use (against an equal world
 * never queried, stepped in turn with it). The cost of a query should
 * follow what it meets, not the scene: the time per ray at 256 cubes over that at 4 is printed
 * as a ratio, beside the profile's counts (bodies reached and triangles tested per query), which
 * are exact. Each figure is the fastest of `repeats` runs (other load only slows a run down).
 *
 *   bench_queries [--rays N] [--repeats R] [--quick]
 *
 * Timings are only meaningful as ratios within one run on an otherwise quiet machine. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "lfem.h"

typedef struct figures {
    double ray_us, all_us, box_us;      /* per query, fastest run */
    double step_ms, step_queries_ms;    /* per step without and with queries in use */
    double bodies, primitives;          /* per ray, from the profile */
} figures;

/* n cubes on a square grid 0.3 m apart, all drifting along +x at 0.1 m/s. */
static int build(lfem_world** out, int n) {
    lfem_world_def wd = lfem_world_def_default();
    lfem_world* w = NULL;
    lfem_mesh* cube = NULL;
    const double size[3] = {0.1, 0.1, 0.1};
    const uint32_t cells[3] = {2, 2, 2};
    const int per_row = (int)ceil(sqrt((double)n));
    wd.gravity[2] = 0.0;
    BENCH_TRY(lfem_world_create(&wd, &w));
    for (int i = 0; i < n; ++i) {
        lfem_body_def d = lfem_body_def_default();
        lfem_body b;
        const double at[3] = {0.3 * (i % per_row), 0.3 * (i / per_row), 0.0};
        d.linear_velocity[0] = 0.1;
        BENCH_TRY(lfem_mesh_create_box(size, cells, &cube));
        BENCH_TRY(lfem_mesh_translate(cube, at));
        BENCH_TRY(lfem_body_create(w, &d, &b));
        BENCH_TRY(bench_add_mesh(w, b, cube));
        lfem_mesh_destroy(cube);
        cube = NULL;
    }
    *out = w;
    return 0;
fail:
    lfem_mesh_destroy(cube);
    lfem_world_destroy(w);
    return -1;
}

/* Rays down the z axis through the first row's first two cubes, in turn (every ray meets one,
 * within 3 cm of its sides at rest: they drift by 2 cm over the run), and boxes about them. */
static void ray_of(int k, double origin[3], double dir[3]) {
    const double u = (double)((k * 7919) % 1000) / 1000.0, v = (double)((k * 104729) % 1000) / 1000.0;
    origin[0] = 0.3 * (k % 2) + 0.03 + 0.04 * u, origin[1] = 0.03 + 0.04 * v, origin[2] = 1.0;
    dir[0] = 0.0, dir[1] = 0.0, dir[2] = -1.0;
}

/* The fastest of `repeats` steps of w, in ms. */
static int time_step(lfem_world* w, double* best) {
    const double t0 = bench_now();
    BENCH_TRY(lfem_world_step(w, 1.0 / 60.0));
    if (1e3 * (bench_now() - t0) < *best) *best = 1e3 * (bench_now() - t0);
    return 0;
fail:
    return -1;
}

/* Two equal worlds stepped in turn, so that other load disturbs both alike: `plain` never
 * queried, `queried` asked rays and boxes after every step (so its step keeps the cache). */
static int measure(int n, int rays, int repeats, figures* f) {
    lfem_world *plain = NULL, *w = NULL;
    lfem_ray_hit hits[16];
    lfem_body found[16];
    lfem_profile p;
    const lfem_query_filter filter = lfem_query_filter_default();
    memset(f, 0, sizeof *f);
    f->ray_us = f->all_us = f->box_us = f->step_ms = f->step_queries_ms = HUGE_VAL;
    if (build(&plain, n) || build(&w, n)) goto fail;
    for (int r = 0; r <= repeats; ++r) {
        double origin[3], dir[3], t0, no_time = HUGE_VAL;
        uint32_t count = 0;
        int hit = 0;
        lfem_ray_hit one;
        /* The first round only makes the queries in use: its step had no cache to keep. */
        if (time_step(plain, r > 0 ? &f->step_ms : &no_time) || time_step(w, r > 0 ? &f->step_queries_ms : &no_time))
            goto fail;
        BENCH_TRY(lfem_world_reset_profile(w));
        t0 = bench_now();
        for (int k = 0; k < rays; ++k) {
            ray_of(k, origin, dir);
            BENCH_TRY(lfem_world_cast_ray(w, origin, dir, HUGE_VAL, filter, &one, &hit));
            if (!hit) {
                fprintf(stderr, "ray %d missed the cubes\n", k);
                goto fail;
            }
        }
        if (1e6 * (bench_now() - t0) / rays < f->ray_us) f->ray_us = 1e6 * (bench_now() - t0) / rays;
        BENCH_TRY(lfem_world_get_profile(w, &p));
        f->bodies = (double)p.query_bodies / rays, f->primitives = (double)p.query_primitives / rays;
        t0 = bench_now();
        for (int k = 0; k < rays; ++k) {
            ray_of(k, origin, dir);
            BENCH_TRY(lfem_world_cast_ray_all(w, origin, dir, HUGE_VAL, filter, hits, 16, &count));
        }
        if (1e6 * (bench_now() - t0) / rays < f->all_us) f->all_us = 1e6 * (bench_now() - t0) / rays;
        t0 = bench_now();
        for (int k = 0; k < rays; ++k) {
            double lo[3], hi[3];
            ray_of(k, origin, dir);
            for (int d = 0; d < 3; ++d) lo[d] = origin[d] - 0.01, hi[d] = origin[d] + 0.01;
            lo[2] = 0.04, hi[2] = 0.06;
            BENCH_TRY(lfem_world_overlap_box(w, lo, hi, filter, found, 16, &count));
        }
        if (1e6 * (bench_now() - t0) / rays < f->box_us) f->box_us = 1e6 * (bench_now() - t0) / rays;
    }
    lfem_world_destroy(plain);
    lfem_world_destroy(w);
    return 0;
fail:
    lfem_world_destroy(plain);
    lfem_world_destroy(w);
    return -1;
}

int main(int argc, char** argv) {
    int rays = 20000, repeats = 5;
    const int sizes[3] = {4, 32, 256};
    figures f[3];
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--rays") && i + 1 < argc) rays = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--repeats") && i + 1 < argc) repeats = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--quick")) rays = 200, repeats = 1;
        else {
            fprintf(stderr, "usage: bench_queries [--rays N] [--repeats R] [--quick]\n");
            return 2;
        }
    }
    if (rays < 1 || repeats < 1) {
        fprintf(stderr, "bench_queries: --rays and --repeats >= 1\n");
        return 2;
    }
    printf("cubes  ray us  all-hits us  box us  bodies/ray  triangles/ray  step ms  step ms (queries in use)\n");
    for (int s = 0; s < 3; ++s) {
        if (measure(sizes[s], rays, repeats, &f[s])) return 1;
        printf("%5d  %6.3f  %11.3f  %6.3f  %10.2f  %13.2f  %7.3f  %7.3f\n", sizes[s], f[s].ray_us, f[s].all_us,
               f[s].box_us, f[s].bodies, f[s].primitives, f[s].step_ms, f[s].step_queries_ms);
    }
    printf("time per ray at 256 cubes over 4: %.2f (all hits %.2f, boxes %.2f); the scene is 64 times larger\n",
           f[2].ray_us / f[0].ray_us, f[2].all_us / f[0].all_us, f[2].box_us / f[0].box_us);
    printf("keeping the queries' cache: a step at 256 cubes costs %.2f times the step without queries\n",
           f[2].step_queries_ms / f[2].step_ms);
    return 0;
}
