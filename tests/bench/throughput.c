/* Throughput of the step on a large cube (issue 7): tet-steps per second for each material
 * model on 1 and 2 threads, the 1 -> 2 thread speed-up, bytes of memory per tet (growth of the
 * peak resident set, VmHWM), and the cost of contact: the same cube resting on a static floor,
 * as a ratio of its step time to the contact-free step.
 *
 *   bench_throughput [cells] [steps] [model] [order] [repeats]
 *
 * cells: cube cells per edge (6 tets per cell; 55 gives 998,250 tets), default 55.
 * steps: timed sub-steps per run, default 20.
 * model: linear, paper, neo_hookean or corotational to run only that one ("all": every one).
 * order: "ordered" (default) gives the box builder's mesh as it is, numbered plane by plane;
 *        "shuffled" numbers its nodes and tets in a random order (fixed seed) first, as a mesh
 *        generator that numbers in no spatial order would. The library reorders every mesh
 *        for locality (src/mesh/node_ordering.h), so the two should run alike. "quadratic":
 *        the builder's mesh made of 10-node tets (lfem_mesh_make_quadratic), as ordered.
 * repeats: runs of each configuration, default 1; the fastest is reported (other load on a
 *        shared machine only ever slows a run down).
 *
 * Columns: wall-clock Mtet-steps/s; its ratio to the 1-thread run (speed-up); Mtet-steps per
 * second of CPU time summed over threads (the work done, less sensitive to other load on the
 * machine); bytes per tet; wall time of a step with the cube resting on the floor over that of
 * the contact-free step (same model and threads).
 *
 * Every configuration runs in a child process of its own (fork), so that each peak resident
 * set starts from the same point and no run inherits another's caches or allocations. Timings
 * are wall-clock and only meaningful as ratios within one run on an otherwise quiet machine. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bench_common.h"
#include "lfem.h"

typedef struct result {
    double seconds;        /* wall time of the timed sub-steps */
    double cpu_seconds;    /* CPU time of the process (all threads) over the same sub-steps */
    double steps;          /* sub-steps taken in them */
    double tets;
    double bytes_per_tet;  /* VmHWM growth from before the world to after the timed steps */
    int ok;
} result;

static double clock_seconds(clockid_t id) {
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#define CHECK(call)                                                                   \
    do {                                                                              \
        lfem_status s_ = (call);                                                      \
        if (s_ != LFEM_OK) {                                                          \
            fprintf(stderr, "%s failed: %s\n", #call, lfem_last_error());             \
            exit(1);                                                                  \
        }                                                                             \
    } while (0)

/* One configuration, run in the calling (child) process. The cube [0,1]^3 (m) has E = 1e7 Pa,
 * nu = 0.3, rho = 1000. Without contact it floats without gravity, spinning (0.5 rad/s about
 * z) and breathing (radial velocity 0.01 m/s per m): free vibration with a large rotation, so
 * every model does its full work. With contact it rests on a static floor plane at z = 0 under
 * gravity, every bottom node touching it. */
/* A random permutation of 0..n-1 (Fisher-Yates on a fixed xorshift sequence). */
static uint32_t* random_permutation(uint32_t n, uint64_t* state) {
    uint32_t* p = malloc(sizeof(uint32_t) * (n ? n : 1));
    if (!p) exit(1);
    for (uint32_t i = 0; i < n; ++i) p[i] = i;
    for (uint32_t i = n; i > 1; --i) {
        *state ^= *state << 13, *state ^= *state >> 7, *state ^= *state << 17;
        const uint32_t j = (uint32_t)(*state % i), t = p[i - 1];
        p[i - 1] = p[j], p[j] = t;
    }
    return p;
}

/* Renumbers a mesh in place: node i becomes node_perm[i], tet e is moved to tet_perm[e]. */
static void shuffle_mesh(double* x, uint32_t node_count, uint32_t* tets, uint32_t tet_count) {
    uint64_t state = 0x9E3779B97F4A7C15ull;
    uint32_t* node_perm = random_permutation(node_count, &state);
    uint32_t* tet_perm = random_permutation(tet_count, &state);
    double* x_new = malloc(3 * sizeof(double) * node_count);
    uint32_t* t_new = malloc(4 * sizeof(uint32_t) * tet_count);
    if (!x_new || !t_new) exit(1);
    for (uint32_t i = 0; i < node_count; ++i)
        for (int k = 0; k < 3; ++k) x_new[3 * node_perm[i] + k] = x[3 * i + k];
    for (uint32_t e = 0; e < tet_count; ++e)
        for (int a = 0; a < 4; ++a) t_new[4 * tet_perm[e] + a] = node_perm[tets[4 * e + a]];
    memcpy(x, x_new, 3 * sizeof(double) * node_count);
    memcpy(tets, t_new, 4 * sizeof(uint32_t) * tet_count);
    free(x_new), free(t_new), free(node_perm), free(tet_perm);
}

/* shuffled: 1 to renumber the mesh at random, 2 for 10-node tets. */
static result run_config(lfem_model model, unsigned threads, int contact, unsigned cells,
                         unsigned steps, int shuffled) {
    result r;
    memset(&r, 0, sizeof r);
    const double size[3] = {1.0, 1.0, 1.0};
    const uint32_t n[3] = {cells, cells, cells};
    lfem_mesh* mesh = NULL;
    CHECK(lfem_mesh_create_box(size, n, &mesh));
    if (shuffled == 2) CHECK(lfem_mesh_make_quadratic(mesh));
    const uint32_t node_count = lfem_mesh_get_node_count(mesh);
    const uint32_t tet_count = lfem_mesh_get_tet_count(mesh);
    const uint32_t per_tet = lfem_mesh_get_nodes_per_tet(mesh);
    double* x = malloc(3 * sizeof(double) * node_count);
    uint32_t* tets = malloc(per_tet * sizeof(uint32_t) * tet_count);
    double* v = malloc(3 * sizeof(double) * node_count);
    if (!x || !tets || !v) exit(1);
    /* The box builder centres nothing: find its extent to place it. */
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    for (uint32_t i = 0; i < node_count; ++i)
        for (int k = 0; k < 3; ++k)
            if (x[3 * i + k] < lo[k]) lo[k] = x[3 * i + k];
    const double shift[3] = {-lo[0], -lo[1], -lo[2]};
    CHECK(lfem_mesh_translate(mesh, shift));
    memcpy(x, lfem_mesh_get_positions(mesh), 3 * sizeof(double) * node_count);
    memcpy(tets, lfem_mesh_get_tets(mesh), per_tet * sizeof(uint32_t) * tet_count);
    lfem_mesh_destroy(mesh);
    if (shuffled == 1) shuffle_mesh(x, node_count, tets, tet_count);
    for (uint32_t i = 0; i < node_count; ++i) {
        const double dx = x[3 * i] - 0.5, dy = x[3 * i + 1] - 0.5, dz = x[3 * i + 2] - 0.5;
        v[3 * i + 0] = -0.5 * dy + 0.01 * dx;
        v[3 * i + 1] = 0.5 * dx + 0.01 * dy;
        v[3 * i + 2] = 0.01 * dz;
    }
    const double base = bench_status_bytes("VmHWM:");

    lfem_world_def wd = lfem_world_def_default();
    if (!contact) wd.gravity[2] = 0.0;
    wd.thread_count = threads;
    lfem_world* w = NULL;
    CHECK(lfem_world_create(&wd, &w));
    if (contact) {
        lfem_body_def fd = lfem_body_def_default();
        fd.type = LFEM_BODY_STATIC;
        fd.friction = 0.5;
        lfem_body floor_body;
        CHECK(lfem_body_create(w, &fd, &floor_body));
        lfem_shape_def sd = lfem_shape_def_default(); /* plane through 0 facing +z */
        CHECK(lfem_body_add_shape(w, floor_body, &sd, NULL));
    }
    lfem_body_def bd = lfem_body_def_default();
    bd.model = model;
    bd.young_modulus = 1e7;
    bd.poisson_ratio = 0.3;
    bd.density = 1000.0;
    bd.friction = 0.5;
    lfem_body body;
    CHECK(lfem_body_create(w, &bd, &body));
    CHECK((per_tet == 10 ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh)(w, body, x, node_count, tets, tet_count));
    if (!contact) CHECK(lfem_body_set_velocities(w, body, v, node_count));

    double limit = 0.0;
    CHECK(lfem_world_get_stable_step(w, &limit));
    const double h = wd.step_safety * limit;
    CHECK(lfem_world_step(w, 2.0 * h)); /* warm-up: first touches of every buffer */
    const double t0 = clock_seconds(CLOCK_MONOTONIC), c0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID);
    CHECK(lfem_world_step(w, steps * h));
    r.seconds = clock_seconds(CLOCK_MONOTONIC) - t0;
    r.cpu_seconds = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
    lfem_world_stats st;
    CHECK(lfem_world_get_stats(w, &st));
    r.steps = st.substeps_last_call;
    r.tets = tet_count;
    r.bytes_per_tet = (bench_status_bytes("VmHWM:") - base) / tet_count;
    r.ok = 1;
    lfem_world_destroy(w);
    free(x), free(tets), free(v);
    return r;
}

/* Runs a configuration in a child process and reads its result back through a pipe. */
static result run_isolated(lfem_model model, unsigned threads, int contact, unsigned cells,
                           unsigned steps, int shuffled) {
    result r;
    memset(&r, 0, sizeof r);
    int fd[2];
    if (pipe(fd) != 0) return r;
    fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        const result c = run_config(model, threads, contact, cells, steps, shuffled);
        const ssize_t written = write(fd[1], &c, sizeof c);
        _exit(written == (ssize_t)sizeof c ? 0 : 1);
    }
    close(fd[1]);
    if (pid > 0) {
        if (read(fd[0], &r, sizeof r) != (ssize_t)sizeof r) r.ok = 0;
        waitpid(pid, NULL, 0);
    }
    close(fd[0]);
    return r;
}

/* The fastest of `repeats` isolated runs (per sub-step), or a failed result. */
static result fastest(lfem_model model, unsigned threads, int contact, unsigned cells,
                      unsigned steps, int shuffled, int repeats) {
    result best;
    memset(&best, 0, sizeof best);
    for (int i = 0; i < repeats; ++i) {
        const result r = run_isolated(model, threads, contact, cells, steps, shuffled);
        if (!r.ok) return r;
        if (!best.ok || r.seconds / r.steps < best.seconds / best.steps) best = r;
    }
    return best;
}

int main(int argc, char** argv) {
    const unsigned cells = argc > 1 ? (unsigned)atoi(argv[1]) : 55;
    const unsigned steps = argc > 2 ? (unsigned)atoi(argv[2]) : 20;
    const char* only = argc > 3 && strcmp(argv[3], "all") != 0 ? argv[3] : NULL;
    const int shuffled = argc > 4 ? (strcmp(argv[4], "shuffled") == 0 ? 1 : strcmp(argv[4], "quadratic") == 0 ? 2 : 0) : 0;
    const int repeats = argc > 5 ? atoi(argv[5]) : 1;
    if (cells < 1 || steps < 1 || repeats < 1 ||
        (argc > 4 && !shuffled && strcmp(argv[4], "ordered") != 0)) {
        fprintf(stderr,
                "usage: %s [cells per edge >= 1] [steps >= 1] [model|all] [ordered|shuffled|quadratic] "
                "[repeats >= 1]\n",
                argv[0]);
        return 2;
    }
    static const struct {
        lfem_model model;
        const char* name;
    } models[] = {{LFEM_MODEL_LINEAR, "linear"},
                  {LFEM_MODEL_PAPER, "paper"},
                  {LFEM_MODEL_NEO_HOOKEAN, "neo_hookean"},
                  {LFEM_MODEL_COROTATIONAL, "corotational"}};
    const unsigned thread_counts[] = {1, 2};
    const unsigned thread_options = sizeof thread_counts / sizeof thread_counts[0];
    printf("lfem %s, cube of %u^3 cells (%u %s tets), %u timed sub-steps per run, mesh given %s, "
           "fastest of %d run(s) per configuration\n",
           lfem_version_string(), cells, 6 * cells * cells * cells, shuffled == 2 ? "10-node" : "4-node", steps,
           shuffled == 1 ? "in a random node and tet order" : "as the box builder numbers it", repeats);
    printf("%-13s %7s %14s %9s %12s %10s %13s\n", "model", "threads", "Mtet-steps/s", "speed-up",
           "per CPU-s", "bytes/tet", "contact/free");
    for (unsigned m = 0; m < sizeof models / sizeof models[0]; ++m) {
        if (only && strcmp(only, models[m].name) != 0) continue;
        double first = 0.0;
        for (unsigned t = 0; t < thread_options; ++t) {
            const unsigned threads = thread_counts[t];
            const result free_run = fastest(models[m].model, threads, 0, cells, steps, shuffled, repeats);
            const result contact_run = fastest(models[m].model, threads, 1, cells, steps, shuffled, repeats);
            if (!free_run.ok || !contact_run.ok) {
                printf("%-13s %7u   failed\n", models[m].name, threads);
                continue;
            }
            const double rate = free_run.tets * free_run.steps / free_run.seconds;
            if (t == 0) first = rate;
            const double per_step_free = free_run.seconds / free_run.steps;
            const double per_step_contact = contact_run.seconds / contact_run.steps;
            const double cpu_rate = free_run.tets * free_run.steps / free_run.cpu_seconds;
            printf("%-13s %7u %14.2f %8.2fx %12.2f %10.0f %12.2fx\n", models[m].name, threads,
                   rate / 1e6, rate / first, cpu_rate / 1e6, free_run.bytes_per_tet,
                   per_step_contact / per_step_free);
            fflush(stdout);
        }
    }
    return 0;
}
