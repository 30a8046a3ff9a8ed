/* Game scenes (issue 16): what a game engine sees when it calls lfem_world_step(w, 1/60) once
 * per frame. Each scene settles for `settle` seconds, then `frames` frames are timed (wall
 * clock around the step calls only): ms per frame (mean and worst), sub-steps per frame,
 * tet-steps per second, and where the time goes (lfem_world_get_profile over the timed frames,
 * as shares of the stepping time); the contact solve's mean sweeps per sub-step (its slowest
 * group's), constraint updates per sub-step and their cost (ns per update: the solve's time over
 * them), and after the timed frames the RMS speed of every node and the active contacts. Every scene runs on 1 and on 2 threads, each in a child
 * process of its own (fork), so no run inherits another's caches; with `repeats` > 1 the
 * fastest run of each is kept (other load only ever slows a run down).
 *
 *   bench_game_scenes [--frames N] [--settle S] [--repeats R] [--only NAME] [--threads T]
 *                     [--reference CELLS] [--placements P]
 *
 * --only NAME runs the scenes whose names begin with NAME (`--only cubes32` the three 32-cube
 * scenes). --threads T runs only that thread count (default: 1 and 2).
 *
 * --placements P runs each scene P times, placed P ways: as listed (the first), then with every
 * body shifted by up to 0.5 mm in x and y (a fixed pseudo-random shift per placement and body).
 * A pile is chaotic: where its cubes come to rest, and so how many sweeps its solve takes, moves
 * with any change (the 48-cube pile at rest took 8 to 35 sweeps a sub-step over ten placements),
 * so a change to the solve is judged on the mean of several placements, which the summary line
 * after each scene's rows gives (ms per frame and sweeps, mean, least and most).
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
 * Soft bodies resting on each other (issue 34), cubes of 10 cm, 3^3 cells, E 1e5 Pa, nu 0.45,
 * rho 1100, damping 5, friction 0.5 on the 4 x 4 box-mesh floor, sleeping off:
 *   pile48_landing  48 cubes dropped in three layers of 4 x 4 (1 cm apart), each layer 12 cm
 *                   above the last and shifted by (2.5, 1.5) cm: timed from 0.25 to 1.25 s
 *   pile48_rest     the same, timed from 3 to 4 s (at rest, about 800 contacts)
 *   pyramid55       a square pyramid of 5 layers (5 x 5 cubes to 1), each cube on the four
 *                   below, 5 mm apart: one cube deep, a wall or a pyramid of these cubes 0.5 m
 *                   high buckles under its own weight (Greenhill, below), 5 cubes deep it stands
 *   column10        10 cubes stacked 1 mm apart (the longest chain for the solve), of E 5e6 Pa:
 *                   a column of the others' E 1e5 buckles under its own weight (Greenhill:
 *                   it stands up to L_c = 1.986 (E a^2 / (12 rho g))^(1/3) = 0.39 m; a 1 m
 *                   column needs E >= 1.7e6), and does, at about 2.2 s; with E 5e6, L_c = 1.44 m
 *   wall40          a wall of 40 blocks of 20 x 20 x 10 cm (6 x 6 x 3 cells) in 5 courses of 8,
 *                   every other course shifted by a quarter block: a wall of 10 cm bricks would
 *                   buckle sideways (its plate's L_c 0.42 m < 0.5 m), 20 cm thick it stands
 *                   up to 0.67 m
 * Their settling and timed frames are the scene's own unless --settle or --frames are given.
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
/* How the bodies are placed: on a grid (stacked `layers` high, 1 mm apart), or one of the piles. */
enum layout { GRID, PILE48, PYRAMID, COLUMN, WALL };

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
    enum layout layout;
    double settle;    /* s before the timed frames, 0 = --settle's (default 1) */
    int frames;       /* timed frames, 0 = --frames' (default 60) */
} scene;

static const scene kScenes[] = {
    {"cubes32_box4", 32, 8, 3, 1e5, 0.45, 0.4, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes32_box64", 32, 8, 3, 1e5, 0.45, 0.4, LFEM_MODEL_PAPER, FLOOR_BOX64, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes32_plane", 32, 8, 3, 1e5, 0.45, 0.4, LFEM_MODEL_PAPER, FLOOR_PLANE, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes8_tri2", 8, 4, 6, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_TRI2, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes8_terrain", 8, 4, 6, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_TERRAIN, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes8_stiff", 8, 4, 6, 1e6, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_TRI2, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes8_plane", 8, 4, 6, 1e6, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_PLANE, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes16_bullet", 16, 4, 3, 1e5, 0.3, 0.5, LFEM_MODEL_NEO_HOOKEAN, FLOOR_PLANE, 0, 0, 0, 0, GRID, 0, 0},
    {"cube1_bullet", 1, 1, 3, 1e5, 0.3, 0.5, LFEM_MODEL_NEO_HOOKEAN, FLOOR_PLANE, 0, 0, 0, 0, GRID, 0, 0},
    {"cubes100_apart", 100, 10, 3, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_NONE, 0, 0, 0, 0, GRID, 0, 0},
    {"cube_one_big", 1, 1, 15, 1e5, 0.45, 0.5, LFEM_MODEL_PAPER, FLOOR_NONE, 0, 0, 0, 0.5, GRID, 0, 0},
    {"pile50_awake", 50, 5, 3, 1e5, 0.45, 0.3, LFEM_MODEL_PAPER, FLOOR_BOX4, 2, 0, 20, 0, GRID, 0, 0},
    {"pile50_asleep", 50, 5, 3, 1e5, 0.45, 0.3, LFEM_MODEL_PAPER, FLOOR_BOX4, 2, 1, 20, 0, GRID, 0, 0},
    {"pile48_landing", 48, 4, 3, 1e5, 0.45, 0, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 5, 0, PILE48, 0.25, 60},
    {"pile48_rest", 48, 4, 3, 1e5, 0.45, 0, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 5, 0, PILE48, 3.0, 60},
    {"pyramid55", 55, 5, 3, 1e5, 0.45, 0, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 5, 0, PYRAMID, 2.0, 60},
    {"column10", 10, 1, 3, 5e6, 0.45, 0, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 5, 0, COLUMN, 2.0, 60},
    {"wall40", 40, 8, 3, 1e5, 0.45, 0, LFEM_MODEL_PAPER, FLOOR_BOX4, 0, 0, 5, 0, WALL, 2.0, 60},
};

typedef struct result {
    int ok;
    double seconds, worst_frame;  /* wall time of the timed frames, of the slowest one */
    double substeps, tets;
    double rms_speed;             /* m/s, of every node of the scene after the timed frames */
    uint32_t contacts;            /* active contacts after the timed frames */
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

/* Where body c of the scene goes: the corner of its box (offset, m), its size and cells. On a
 * grid, bodies `spacing` apart, 1 mm above the floor (3 mm above the terrain, whose waves reach
 * 2 mm); the piles as the list at the top says. */
static void place(const scene* sc, int c, double offset[3], double size[3], uint32_t cells[3]) {
    const double edge = sc->edge > 0 ? sc->edge : 0.1;
    for (int k = 0; k < 3; ++k) size[k] = edge, cells[k] = sc->cells;
    const int per_row = sc->per_row;
    if (sc->layout == GRID) {
        const int layers = sc->layers > 0 ? sc->layers : 1, places = sc->cubes / layers;
        const int spot = c % places, layer = c / places;
        offset[0] = sc->spacing * (spot % per_row - 0.5 * (per_row - 1)) - 0.5 * edge;
        offset[1] = sc->spacing * (spot / per_row - 0.5 * ((places - 1) / per_row)) - 0.5 * edge;
        offset[2] = (sc->floor == FLOOR_TERRAIN ? 0.003 : 0.001) + layer * (edge + 0.001);
    } else if (sc->layout == PILE48) {  /* layers of per_row x per_row, 1 cm apart */
        const int per_layer = per_row * per_row, layer = c / per_layer, spot = c % per_layer;
        const double pitch = edge + 0.01;
        offset[0] = pitch * (spot % per_row - 0.5 * (per_row - 1)) - 0.5 * edge + 0.025 * layer;
        offset[1] = pitch * (spot / per_row - 0.5 * (per_row - 1)) - 0.5 * edge + 0.015 * layer;
        offset[2] = 0.001 + 0.12 * layer;
    } else if (sc->layout == PYRAMID) {  /* per_row^2 at the bottom, (per_row - 1)^2 next... */
        int layer = 0, first = 0;
        while (c >= first + (per_row - layer) * (per_row - layer)) first += (per_row - layer) * (per_row - layer), ++layer;
        const int n = per_row - layer, i = (c - first) % n, j = (c - first) / n;
        const double pitch = edge + 0.005;
        offset[0] = pitch * (i - 0.5 * (n - 1)) - 0.5 * edge;
        offset[1] = pitch * (j - 0.5 * (n - 1)) - 0.5 * edge;
        offset[2] = 0.001 + layer * (edge + 0.001);
    } else if (sc->layout == COLUMN) {
        offset[0] = offset[1] = -0.5 * edge;
        offset[2] = 0.001 + c * (edge + 0.001);
    } else {  /* WALL: courses of per_row blocks twice as long and deep as high, every other one
               * shifted by a quarter block */
        const int course = c / per_row, i = c % per_row;
        size[0] = size[1] = 2 * edge;
        cells[0] = cells[1] = 2 * sc->cells;
        offset[0] = (2 * edge + 0.001) * (i - 0.5 * per_row) + (course % 2 ? 0.5 * edge : 0.0);
        offset[1] = -edge;
        offset[2] = 0.001 + course * (edge + 0.001);
    }
}

/* The placement (--placements) the next run builds: 0 as listed, else every body shifted. */
static int g_placement = 0;

/* Body c's shift in x and y (m) in placement g_placement: up to 0.5 mm each way, from a small
 * linear congruential generator (the same numbers on every platform). */
static void placement_shift(int c, double offset[3]) {
    if (g_placement == 0) return;
    uint32_t state = 2654435761u * (uint32_t)g_placement + 40503u * (uint32_t)c + 1u;
    for (int k = 0; k < 2; ++k) {
        state = state * 1664525u + 1013904223u;
        offset[k] += 1e-3 * ((state >> 8) / 16777216.0 - 0.5);
    }
}

/* The scene's floor and its bodies (their handles into bodies[sc->cubes]). */
static int build(lfem_world* w, const scene* sc, double* tets, lfem_body* bodies) {
    lfem_mesh* m = NULL;
    if (add_floor(w, sc->floor) != 0) return -1;
    *tets = 0;
    for (int c = 0; c < sc->cubes; ++c) {
        lfem_body_def d = lfem_body_def_default();
        d.model = sc->model;
        d.young_modulus = sc->young;
        d.poisson_ratio = sc->poisson;
        d.damping = sc->damping > 0 ? sc->damping : 5.0;
        d.friction = 0.5;
        if (sc->layout != GRID) d.density = 1100;
        double offset[3], size[3];
        uint32_t cells[3];
        place(sc, c, offset, size, cells);
        placement_shift(c, offset);
        lfem_body b;
        BENCH_TRY(lfem_mesh_create_box(size, cells, &m));
        BENCH_TRY(lfem_mesh_translate(m, offset));
        BENCH_TRY(lfem_body_create(w, &d, &b));
        BENCH_TRY(lfem_body_add_mesh(w, b, lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                                     lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)));
        *tets += lfem_mesh_get_tet_count(m);
        bodies[c] = b;
        lfem_mesh_destroy(m);
        m = NULL;
    }
    return 0;
fail:
    lfem_mesh_destroy(m);
    return -1;
}

/* The RMS speed of every node of the scene's bodies (m/s) and the active contacts. */
static int rms_speed(lfem_world* w, const lfem_body* bodies, int count, double* rms, uint32_t* contacts) {
    lfem_world_stats st;
    BENCH_TRY(lfem_world_get_stats(w, &st));
    *contacts = st.contact_count;
    double sum = 0;
    uint64_t nodes = 0;
    for (int i = 0; i < count; ++i) {
        uint32_t n = 0;
        BENCH_TRY(lfem_body_get_node_count(w, bodies[i], &n));
        double* v = malloc(sizeof(double) * 3 * (n + 1));
        if (!v || lfem_body_get_velocities(w, bodies[i], v, n) != LFEM_OK) {
            free(v);
            return -1;
        }
        for (uint32_t k = 0; k < 3 * n; ++k) sum += v[k] * v[k];
        nodes += n;
        free(v);
    }
    *rms = nodes ? sqrt(sum / nodes) : 0.0;
    return 0;
fail:
    return -1;
}

static void run_scene(const scene* sc, uint32_t threads, int frames, double settle, result* out) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.enable_sleep = (uint8_t)sc->sleep;
    if (sc->floor == FLOOR_NONE) wd.gravity[2] = 0.0;
    lfem_world* w = NULL;
    lfem_body* bodies = malloc(sizeof(lfem_body) * (size_t)sc->cubes);
    memset(out, 0, sizeof *out);
    if (!bodies || lfem_world_create(&wd, &w) != LFEM_OK || build(w, sc, &out->tets, bodies) != 0) goto fail;
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
    if (rms_speed(w, bodies, sc->cubes, &out->rms_speed, &out->contacts) != 0) goto fail;
    out->substeps = (double)(after.steps - before.steps);
    out->ok = 1;
fail:
    lfem_world_destroy(w);
    free(bodies);
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

static int g_frames = 60, g_frames_given = 0;
static double g_settle = 1.0;
static int g_settle_given = 0;

/* The scene's own settling and timed frames, unless the command line gave them. */
static int frames_of(const scene* sc) { return sc->frames > 0 && !g_frames_given ? sc->frames : g_frames; }
static double settle_of(const scene* sc) { return sc->settle > 0 && !g_settle_given ? sc->settle : g_settle; }

static void scene_work(const void* arg, uint32_t threads, result* out) {
    const scene* sc = (const scene*)arg;
    run_scene(sc, threads, frames_of(sc), settle_of(sc), out);
}

static void reference_work(const void* arg, uint32_t threads, result* out) {
    run_reference(*(const uint32_t*)arg, threads, out);
}

static double share(const lfem_phase_time* p, double total) { return total > 0 ? 100.0 * p->seconds / total : 0; }

int main(int argc, char** argv) {
    int repeats = 1, placements = 1;
    const char* only = NULL;
    uint32_t reference_cells = 0, only_threads = 0;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--frames") && i + 1 < argc) g_frames = atoi(argv[++i]), g_frames_given = 1;
        else if (!strcmp(argv[i], "--settle") && i + 1 < argc) g_settle = atof(argv[++i]), g_settle_given = 1;
        else if (!strcmp(argv[i], "--repeats") && i + 1 < argc) repeats = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
        else if (!strcmp(argv[i], "--reference") && i + 1 < argc) reference_cells = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc) only_threads = (uint32_t)atoi(argv[++i]);
        else if (!strcmp(argv[i], "--placements") && i + 1 < argc && atoi(argv[i + 1]) > 0)
            placements = atoi(argv[++i]);
        else {
            fprintf(stderr,
                    "usage: %s [--frames N] [--settle S] [--repeats R] [--only NAME] [--threads T] [--reference CELLS] "
                    "[--placements P]\n",
                    argv[0]);
            return 2;
        }
    }
    printf("lfem %s, 60 Hz frames: %d timed after %.2f s of settling (the piles: their own), fastest of %d run(s)\n",
           lfem_version_string(), g_frames, g_settle, repeats);
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
    printf("%-15s %3s %6s %8s %8s %9s %8s %8s | %6s %6s %6s %6s %6s %6s %6s | %6s %7s %6s %8s %5s | %s\n", "scene",
           "thr", "tets", "ms/frame", "worst", "sub/frame", "searches", "Mtet-s/s", "forces", "pred", "broad", "narrow",
           "shapes", "solve", "commit", "sweeps", "upd/sub", "ns/upd", "rms m/s", "cont",
           "detect/forces, x reference");
    int failed = 0;
    double awake_ms[3] = {0, 0, 0}, small_rate[3] = {0, 0, 0};
    for (size_t s = 0; s < sizeof kScenes / sizeof kScenes[0]; ++s) {
        const scene* sc = &kScenes[s];
        if (only && strncmp(only, sc->name, strlen(only)) != 0) continue;
        double ms_by_threads[3] = {0, 0, 0}, rate_by_threads[3] = {0, 0, 0};
        for (uint32_t threads = 1; threads <= 2; ++threads) {
            if (only_threads && threads != only_threads) continue;
            double ms_sum = 0, ms_lo = HUGE_VAL, ms_hi = 0, sw_sum = 0, sw_lo = HUGE_VAL, sw_hi = 0;
            int placed = 0;
            for (g_placement = 0; g_placement < placements; ++g_placement) {
                char name[32];
                snprintf(name, sizeof name, placements > 1 ? "%s#%d" : "%s", sc->name, g_placement);
                const result r = fastest_in_child(repeats, scene_work, sc, threads);
                if (!r.ok) {
                    printf("%-15s %3u  FAILED\n", name, threads);
                    failed = 1;
                    continue;
                }
                const lfem_profile* p = &r.profile;
                const double total = r.seconds;
                const double detect = p->broad_phase.seconds + p->narrow_phase.seconds + p->shape_queries.seconds;
                const double rate = r.tets * r.substeps / r.seconds;
                const int frames = frames_of(sc);
                const double solve_s = p->normal_solve.seconds + p->friction.seconds;
                ms_by_threads[threads] = 1e3 * r.seconds / frames;
                rate_by_threads[threads] = rate;
                printf("%-15s %3u %6.0f %8.2f %8.2f %9.1f %8llu %8.2f | %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f %6.1f | %6.1f %7.0f "
                       "%6.0f %8.1e %5u | %.2f",
                       name, threads, r.tets, ms_by_threads[threads], 1e3 * r.worst_frame, r.substeps / frames,
                       (unsigned long long)p->candidate_searches, 1e-6 * rate,
                       share(&p->internal_forces, total), share(&p->predictor, total), share(&p->broad_phase, total),
                       share(&p->narrow_phase, total), share(&p->shape_queries, total),
                       share(&p->normal_solve, total) + share(&p->friction, total), share(&p->commit, total),
                       r.substeps > 0 ? (double)p->contact_sweeps / r.substeps : 0.0,
                       r.substeps > 0 ? (double)p->constraint_updates / r.substeps : 0.0,
                       p->constraint_updates ? 1e9 * solve_s / (double)p->constraint_updates : 0.0, r.rms_speed, r.contacts,
                       p->internal_forces.seconds > 0 ? detect / p->internal_forces.seconds : 0.0);
                if (reference[threads] > 0) printf(", %.2f", rate / reference[threads]);
                printf("\n");
                const double sweeps = r.substeps > 0 ? (double)p->contact_sweeps / r.substeps : 0.0;
                ms_sum += ms_by_threads[threads], sw_sum += sweeps, ++placed;
                ms_lo = fmin(ms_lo, ms_by_threads[threads]), ms_hi = fmax(ms_hi, ms_by_threads[threads]);
                sw_lo = fmin(sw_lo, sweeps), sw_hi = fmax(sw_hi, sweeps);
            }
            if (placements > 1 && placed > 0) {
                ms_by_threads[threads] = ms_sum / placed;
                printf("%-15s %3u %d placements: ms/frame mean %.2f (%.2f to %.2f), sweeps mean %.1f (%.1f to %.1f)\n",
                       sc->name, threads, placed, ms_sum / placed, ms_lo, ms_hi, sw_sum / placed, sw_lo, sw_hi);
            }
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
