/* Game scenes (issue 16): what a game engine sees when it calls lfem_world_step(w, 1/60) once
 * per frame. Each scene settles for `settle` seconds, then `frames` frames are timed (wall
 * clock around the step calls only): ms per frame (mean and worst), sub-steps per frame,
 * tet-steps per second, and where the time goes (lfem_world_get_profile over the timed frames,
 * as shares of the stepping time). Every scene runs on 1 and on 2 threads, each in a child
 * process of its own (fork), so no run inherits another's caches; with `repeats` > 1 the
 * fastest run of each is kept (other load only ever slows a run down).
 *
 *   bench_game_scenes [--frames N] [--settle S] [--repeats R] [--only NAME] [--threads T]
 *                     [--reference CELLS]
 *
 * --only NAME runs the scenes whose names begin with NAME (`--only cubes32` the three 32-cube
 * scenes). --threads T runs only that thread count (default: 1 and 2).
 *
 * --reference CELLS adds the contact-free reference: a cube of CELLS^3 cells (6 tets each, 55
 * gives about 1e6 tets) floating and spinning without gravity, stepped for a few sub-steps,
 * whose tet-steps per second the game scenes are compared with (the last column). Scenes:
 *   cubes32_box4    32 soft cubes (10 cm, 3^3 cells, E 1e5 Pa, nu 0.45) on a static box-mesh
 *                   floor of 4 x 4 x 1 cells (4 m x 4 m)
 *   cubes32_box64   the same on a floor of 64 x 64 x 1 cells
 *   cubes32_plane   the same on a plane shape
 *   cubes8_tri2     8 cubes of 6^3 cells (E 1e5) on a 2-triangle floor
 *   cubes8_terrain  the same on a static terrain of 180,000 triangles
 *   cubes8_stiff    8 cubes of 6^3 cells, E 1e6, on the 2-triangle floor
 *   cubes8_plane    the same stiff cubes on a plane shape
 *   cubes16_bullet  16 cubes of 162 tets (the Bullet benchmark's --edge 0.1 --cells 3 scene:
 *                   neo-Hookean, nu 0.3, 0.5 m apart) on a plane shape
 *   cube1_bullet    one such cube
 *   cubes100_apart  100 cubes of 3^3 cells (16,200 tets) 0.5 m apart, floating (no gravity)
 *   cube_one_big    one cube of 15^3 cells (20,250 tets) of the same cell size, floating:
 *                   what 100 small bodies cost against one of as many tets (tet-steps/s,
 *                   printed as their ratio)
 *   pile50_awake    50 cubes of 3^3 cells (E 1e5, damping 20) in 25 stacks of 2 on the
 *                   box-mesh floor, settled, sleeping off
 *   pile50_asleep   the same with sleeping on: settled, the pile is asleep (issue 17's target:
 *                   under 5 % of its awake cost; the ratio is printed)
 * Timings are only meaningful as ratios within one run on an otherwise quiet machine. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "bench_common.h"
#include "lfem.h"

enum floor_kind { FLOOR_BOX4, FLOOR_BOX64, FLOOR_PLANE, FLOOR_TRI2, FLOOR_TERRAIN, FLOOR_NONE };

typedef struct scene {
    const char* name;
    int cubes, per_row;  /* cubes, on a grid of per_row columns */
    uint32_t cells;
    double young, poisson, spacing;
    lfem_model model;
    enum floor_kind floor;
    int layers;       /* cubes stacked per place (0 = 1) */
    int sleep;        /* lfem_world_def.enable_sleep */
    double damping;   /* 0 = 5 */
    double edge;      /* m, 0 = 0.1 */
} scene;

static const scene kScenes[] = {
    {"cubes32_box4", 32, 8, 3, 1e5, 0.45, 0.4, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 0, 0},
    {"cubes32_box64", 32, 8, 3, 1e5, 0.45, 0.4, LFEM_MODEL_PAPER, FLOOR_BOX64, 0, 0, 0, 0},
    {"cubes32_plane", 32, 8, 3, 1e5, 0.45, 0.4, LFEM_MODEL_PAPER, FLOOR_PLANE, 0, 0, 0, 0},
    {"cubes8_tri2", 8, 4, 6, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_TRI2, 0, 0, 0, 0},
    {"cubes8_terrain", 8, 4, 6, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_TERRAIN, 0, 0, 0, 0},
    {"cubes8_stiff", 8, 4, 6, 1e6, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_TRI2, 0, 0, 0, 0},
    {"cubes8_plane", 8, 4, 6, 1e6, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_PLANE, 0, 0, 0, 0},
    {"cubes16_bullet", 16, 4, 3, 1e5, 0.3, 0.5, LFEM_MODEL_NEO_HOOKEAN, FLOOR_PLANE, 0, 0, 0, 0},
    {"cube1_bullet", 1, 1, 3, 1e5, 0.3, 0.5, LFEM_MODEL_NEO_HOOKEAN, FLOOR_PLANE, 0, 0, 0, 0},
    {"cubes100_apart", 100, 10, 3, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_NONE, 0, 0, 0, 0},
    {"cube_one_big", 1, 1, 15, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_NONE, 0, 0, 0, 0.5},
    {"pile50_awake", 50, 5, 3, 1e5, 0.45, 0.3, LFEM_MODEL_PAPER, FLOOR_BOX4, 2, 0, 20, 0},
    {"pile50_asleep", 50, 5, 3, 1e5, 0.45, 0.3, LFEM_MODEL_PAPER, FLOOR_BOX4, 2, 1, 20, 0},
};

typedef struct result {
    int ok;
    double seconds, worst_frame;  /* wall time of the timed frames, of the slowest one */
    double substeps, tets;
    lfem_profile profile;
} result;

static int add_floor(lfem_world* w, enum floor_kind kind) {
    if (kind == FLOOR_NONE) return 0;  /* floating, without gravity */
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    lfem_body floor_body;
    lfem_mesh* m = NULL;
    double* p = NULL;
    uint32_t* t = NULL;
    BENCH_TRY(lfem_body_create(w, &fd, &floor_body));
    if (kind == FLOOR_BOX4 || kind == FLOOR_BOX64) {
        const uint32_t n = kind == FLOOR_BOX4 ? 4 : 64;
        const double size[3] = {4.0, 4.0, 0.2}, offset[3] = {-2.0, -2.0, -0.2};
        const uint32_t cells[3] = {n, n, 1};
        BENCH_TRY(lfem_mesh_create_box(size, cells, &m));
        BENCH_TRY(lfem_mesh_translate(m, offset));
        BENCH_TRY(lfem_body_add_mesh(w, floor_body, lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                                     lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)));
        lfem_mesh_destroy(m);
    } else if (kind == FLOOR_PLANE) {
        lfem_shape_def s = lfem_shape_def_default();
        BENCH_TRY(lfem_body_add_shape(w, floor_body, &s, NULL));
    } else {
        /* A grid of g x g squares over 4 m x 4 m, two triangles each: g = 1 is the 2-triangle
         * floor, g = 300 the 180,000-triangle terrain, whose heights wave by 2 mm (gentle
         * enough that the cubes rest on it). */
        const uint32_t g = kind == FLOOR_TRI2 ? 1 : 300;
        p = malloc(sizeof(double) * 3 * (g + 1) * (g + 1));
        t = malloc(sizeof(uint32_t) * 6 * g * g);
        if (!p || !t) goto fail;
        for (uint32_t j = 0; j <= g; ++j)
            for (uint32_t i = 0; i <= g; ++i) {
                double* q = &p[3 * (j * (g + 1) + i)];
                q[0] = -2.0 + 4.0 * i / g, q[1] = -2.0 + 4.0 * j / g;
                q[2] = g > 1 ? 0.002 * sin(5.0 * q[0]) * cos(4.0 * q[1]) : 0.0;
            }
        for (uint32_t j = 0, k = 0; j < g; ++j)
            for (uint32_t i = 0; i < g; ++i) {
                const uint32_t a = j * (g + 1) + i, b = a + 1, c = a + g + 1, d = c + 1;
                t[k++] = a, t[k++] = b, t[k++] = d;
                t[k++] = a, t[k++] = d, t[k++] = c;
            }
        BENCH_TRY(lfem_body_add_triangle_mesh(w, floor_body, p, (g + 1) * (g + 1), t, 2 * g * g));
        free(p);
        free(t);
    }
    return 0;
fail:
    free(p);
    free(t);
    return -1;
}

/* The scene's floor and its cubes of 10 cm edge on a grid `spacing` apart, 1 mm above the
 * floor (3 mm above the terrain, whose waves reach 2 mm). */
static int build(lfem_world* w, const scene* sc, double* tets) {
    lfem_mesh* m = NULL;
    if (add_floor(w, sc->floor) != 0) return -1;
    const double edge = sc->edge > 0 ? sc->edge : 0.1, size[3] = {edge, edge, edge};
    const uint32_t cells[3] = {sc->cells, sc->cells, sc->cells};
    const int per_row = sc->per_row, layers = sc->layers > 0 ? sc->layers : 1, places = sc->cubes / layers;
    *tets = 0;
    for (int c = 0; c < sc->cubes; ++c) {
        lfem_body_def d = lfem_body_def_default();
        d.model = sc->model;
        d.young_modulus = sc->young;
        d.poisson_ratio = sc->poisson;
        d.damping = sc->damping > 0 ? sc->damping : 5.0;
        d.friction = 0.5;
        const int place = c % places, layer = c / places;
        const double ground = (sc->floor == FLOOR_TERRAIN ? 0.003 : 0.001) + layer * (edge + 0.001);
        const double offset[3] = {sc->spacing * (place % per_row - 0.5 * (per_row - 1)) - 0.5 * edge,
                                  sc->spacing * (place / per_row - 0.5 * ((places - 1) / per_row)) - 0.5 * edge, ground};
        lfem_body b;
        BENCH_TRY(lfem_mesh_create_box(size, cells, &m));
        BENCH_TRY(lfem_mesh_translate(m, offset));
        BENCH_TRY(lfem_body_create(w, &d, &b));
        BENCH_TRY(lfem_body_add_mesh(w, b, lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                                     lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)));
        *tets += lfem_mesh_get_tet_count(m);
        lfem_mesh_destroy(m);
        m = NULL;
    }
    return 0;
fail:
    lfem_mesh_destroy(m);
    return -1;
}

static void run_scene(const scene* sc, uint32_t threads, int frames, double settle, result* out) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.enable_sleep = (uint8_t)sc->sleep;
    if (sc->floor == FLOOR_NONE) wd.gravity[2] = 0.0;
    lfem_world* w = NULL;
    memset(out, 0, sizeof *out);
    if (lfem_world_create(&wd, &w) != LFEM_OK || build(w, sc, &out->tets) != 0) goto fail;
    const double frame = 1.0 / 60.0;
    for (int f = 0; f * frame < settle; ++f) BENCH_TRY(lfem_world_step(w, frame));
    BENCH_TRY(lfem_world_reset_profile(w));
    lfem_world_stats before, after;
    BENCH_TRY(lfem_world_get_stats(w, &before));
    for (int f = 0; f < frames; ++f) {
        const double t0 = bench_now();
        BENCH_TRY(lfem_world_step(w, frame));
        const double dt = bench_now() - t0;
        out->seconds += dt;
        if (dt > out->worst_frame) out->worst_frame = dt;
    }
    BENCH_TRY(lfem_world_get_stats(w, &after));
    BENCH_TRY(lfem_world_get_profile(w, &out->profile));
    out->substeps = (double)(after.steps - before.steps);
    out->ok = 1;
fail:
    lfem_world_destroy(w);
}

/* The contact-free reference: tet-steps per second of a floating, spinning cube. */
static void run_reference(uint32_t cells, uint32_t threads, result* out) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.gravity[2] = 0.0;
    lfem_world* w = NULL;
    lfem_mesh* m = NULL;
    memset(out, 0, sizeof *out);
    const double size[3] = {1, 1, 1};
    const uint32_t c[3] = {cells, cells, cells};
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e7;
    d.angular_velocity[2] = 0.5;
    lfem_body b;
    double h = 0;
    BENCH_TRY(lfem_world_create(&wd, &w));
    BENCH_TRY(lfem_mesh_create_box(size, c, &m));
    BENCH_TRY(lfem_body_create(w, &d, &b));
    BENCH_TRY(lfem_body_add_mesh(w, b, lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                                 lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)));
    out->tets = lfem_mesh_get_tet_count(m);
    BENCH_TRY(lfem_world_get_stable_step(w, &h));
    BENCH_TRY(lfem_world_step(w, 0.9 * h));  /* the first step warms the caches */
    const double t0 = bench_now();
    for (int i = 0; i < 10; ++i) BENCH_TRY(lfem_world_step(w, 0.9 * h));
    out->seconds = bench_now() - t0;
    out->substeps = 10;
    out->ok = 1;
fail:
    lfem_mesh_destroy(m);
    lfem_world_destroy(w);
}

/* Runs `work` in a child process `repeats` times (its result comes back through a pipe) and
 * keeps the fastest successful result. */
static result fastest_in_child(int repeats, void (*work)(const void*, uint32_t, result*), const void* arg,
                               uint32_t threads) {
    result best;
    memset(&best, 0, sizeof best);
    for (int r = 0; r < repeats; ++r) {
        int fd[2];
        if (pipe(fd) != 0) exit(1);
        fflush(stdout);
        const pid_t pid = fork();
        if (pid == 0) {
            result mine;
            work(arg, threads, &mine);
            const ssize_t n = write(fd[1], &mine, sizeof mine);
            _exit(n == (ssize_t)sizeof mine && mine.ok ? 0 : 1);
        }
        close(fd[1]);
        result got;
        memset(&got, 0, sizeof got);
        if (read(fd[0], &got, sizeof got) != (ssize_t)sizeof got) got.ok = 0;
        close(fd[0]);
        int status = 0;
        waitpid(pid, &status, 0);
        if (got.ok && (!best.ok || got.seconds < best.seconds)) best = got;
    }
    return best;
}

static int g_frames = 60;
static double g_settle = 1.0;

static void scene_work(const void* arg, uint32_t threads, result* out) {
    run_scene((const scene*)arg, threads, g_frames, g_settle, out);
}

static void reference_work(const void* arg, uint32_t threads, result* out) {
    run_reference(*(const uint32_t*)arg, threads, out);
}

static double share(const lfem_phase_time* p, double total) { return total > 0 ? 100.0 * p->seconds / total : 0; }

int main(int argc, char** argv) {
    int repeats = 1;
    const char* only = NULL;
    uint32_t reference_cells = 0, only_threads = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--frames") && i + 1 < argc) g_frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--settle") && i + 1 < argc) g_settle = atof(argv[++i]);
        else if (!strcmp(argv[i], "--repeats") && i + 1 < argc) repeats = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
        else if (!strcmp(argv[i], "--reference") && i + 1 < argc) reference_cells = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) only_threads = (uint32_t)atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: %s [--frames N] [--settle S] [--repeats R] [--only NAME] [--threads T] [--reference CELLS]\n",
                    argv[0]);
            return 2;
        }
    }
    printf("lfem %s, 60 Hz frames: %d timed after %.2f s of settling, fastest of %d run(s)\n", lfem_version_string(),
           g_frames, g_settle, repeats);
    double reference[3] = {0, 0, 0};
    if (reference_cells) {
        for (uint32_t threads = 1; threads <= 2; ++threads) {
            if (only_threads && threads != only_threads) continue;
            const result r = fastest_in_child(repeats, reference_work, &reference_cells, threads);
            reference[threads] = r.ok ? r.tets * r.substeps / r.seconds : 0;
            printf("reference: contact-free cube of %.0f tets, %u thread(s): %.2f Mtet-steps/s\n", r.tets, threads,
                   1e-6 * reference[threads]);
        }
    }
    printf("%-15s %3s %6s %8s %8s %9s %8s %8s | %6s %6s %6s %6s %6s %6s %6s | %s\n", "scene", "thr", "tets", "ms/frame",
           "worst", "sub/frame", "searches", "Mtet-s/s", "forces", "pred", "broad", "narrow", "shapes", "solve", "commit",
           "detect/forces, x reference");
    int failed = 0;
    double awake_ms[3] = {0, 0, 0}, small_rate[3] = {0, 0, 0};
    for (size_t s = 0; s < sizeof kScenes / sizeof kScenes[0]; ++s) {
        const scene* sc = &kScenes[s];
        if (only && strncmp(only, sc->name, strlen(only)) != 0) continue;
        double ms_by_threads[3] = {0, 0, 0}, rate_by_threads[3] = {0, 0, 0};
        for (uint32_t threads = 1; threads <= 2; ++threads) {
            if (only_threads && threads != only_threads) continue;
            const result r = fastest_in_child(repeats, scene_work, sc, threads);
            if (!r.ok) {
                printf("%-15s %3u  FAILED\n", sc->name, threads);
                failed = 1;
                continue;
            }
            const lfem_profile* p = &r.profile;
            const double total = r.seconds;
            const double detect = p->broad_phase.seconds + p->narrow_phase.seconds + p->shape_queries.seconds;
            const double rate = r.tets * r.substeps / r.seconds;
            ms_by_threads[threads] = 1e3 * r.seconds / g_frames;
            rate_by_threads[threads] = rate;
            printf("%-15s %3u %6.0f %8.2f %8.2f %9.1f %8llu %8.2f | %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f | %.2f",
                   sc->name, threads, r.tets, ms_by_threads[threads], 1e3 * r.worst_frame, r.substeps / g_frames,
                   (unsigned long long)p->candidate_searches, 1e-6 * rate,
                   share(&p->internal_forces, total), share(&p->predictor, total), share(&p->broad_phase, total),
                   share(&p->narrow_phase, total), share(&p->shape_queries, total),
                   share(&p->normal_solve, total) + share(&p->friction, total), share(&p->commit, total),
                   p->internal_forces.seconds > 0 ? detect / p->internal_forces.seconds : 0.0);
            if (reference[threads] > 0) printf(", %.2f", rate / reference[threads]);
            printf("\n");
        }
        if (ms_by_threads[1] > 0 && ms_by_threads[2] > 0)
            printf("%-15s 2 threads / 1 thread: %.2f\n", sc->name, ms_by_threads[2] / ms_by_threads[1]);
        if (!strcmp(sc->name, "pile50_awake")) memcpy(awake_ms, ms_by_threads, sizeof awake_ms);
        if (!strcmp(sc->name, "cubes100_apart")) memcpy(small_rate, rate_by_threads, sizeof small_rate);
        if (!strcmp(sc->name, "cube_one_big"))
            for (uint32_t threads = 1; threads <= 2; ++threads)
                if (small_rate[threads] > 0 && rate_by_threads[threads] > 0)
                    printf("%-15s 100 small bodies / one body, tet-steps per second, %u thread(s): %.2f\n", "cubes100",
                           threads, small_rate[threads] / rate_by_threads[threads]);
        if (!strcmp(sc->name, "pile50_asleep"))
            for (uint32_t threads = 1; threads <= 2; ++threads)
                if (awake_ms[threads] > 0 && ms_by_threads[threads] > 0)
                    printf("%-15s asleep / awake, %u thread(s): %.4f\n", "pile50", threads,
                           ms_by_threads[threads] / awake_ms[threads]);
        fflush(stdout);
    }
    return failed;
}
