/* Scaling benchmark (issue 4, "O(n) and memory"): time per step against tet count, with contact
 * active on a boundary that grows with the mesh.
 *
 * Scene: a slab of n x n x 4 cells (1 cm cubes, 6 tets each: 24 n^2 tets) resting on a static
 * floor made of a triangle mesh of the same resolution, so the contact area (the slab's
 * (n+1)^2 bottom nodes) grows in proportion to the tets. The cell size is fixed, so the stable
 * step is the same at every size and each call of lfem_world_step takes one sub-step.
 *
 * For each size, in a child process of its own (so peak memory is that size's alone): build,
 * 3 warm-up steps, then `steps` timed steps. Printed: time per step, the per-phase time per tet
 * per step from lfem_world_get_profile, peak memory per tet (VmHWM of /proc/self/status after
 * the run minus VmRSS before the mesh and world were built; it includes the mesh builder's
 * copy of the mesh, freed after lfem_body_add_mesh), and the least-squares slope of
 * log(time per step) against log(tets). Writes tests/bench/results/scaling.csv.
 *
 *   bench_scaling            full run: 6 sizes from ~1.2e3 to ~1.0e6 tets (a few minutes)
 *   bench_scaling --quick    two tiny sizes, no CSV (the ctest smoke test; no timing asserts)
 *   bench_scaling --csv P    write the CSV to P instead
 */
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

#ifndef LFEM_BENCH_RESULTS_DIR
#define LFEM_BENCH_RESULTS_DIR "."
#endif

#define LAYERS 4       /* cells through the slab's thickness */
#define CELL 0.01      /* m, edge of a cell */
#define PHASES 8

typedef struct Result {
    double tets, nodes, steps, contacts;
    double seconds_per_step;
    double phase_ns[PHASES];   /* per tet per step */
    double shape_tests, ccd_queries;
    double peak_bytes;         /* VmHWM after the run minus VmRSS before building */
    int ok;
} Result;

static const char* phase_names[PHASES] = {"internal", "predictor", "broad", "narrow",
                                          "normal", "friction", "rotation", "commit"};

#define CHECK(call)                                                                          \
    do {                                                                                     \
        lfem_status s_ = (call);                                                             \
        if (s_ != LFEM_OK) {                                                                 \
            fprintf(stderr, "%s failed: %s\n", #call, lfem_last_error());                     \
            return r;                                                                        \
        }                                                                                    \
    } while (0)

/* The floor: a static triangle mesh of (n+2) x (n+2) squares of one cell each at z = 0, a cell
 * wider than the slab on every side, facing up. */
static lfem_status add_floor(lfem_world* w, unsigned n) {
    const unsigned m = n + 2, verts = (m + 1) * (m + 1);
    double* x = malloc(3 * sizeof(double) * verts);
    uint32_t* tri = malloc(6 * sizeof(uint32_t) * m * m);
    lfem_body_def d = lfem_body_def_default();
    lfem_body floor_body;
    lfem_status s;
    unsigned i, j, t = 0;
    if (!x || !tri) return LFEM_OUT_OF_MEMORY;
    for (j = 0; j <= m; ++j)
        for (i = 0; i <= m; ++i) {
            double* p = x + 3 * (j * (m + 1) + i);
            p[0] = (double)i * CELL - CELL, p[1] = (double)j * CELL - CELL, p[2] = 0.0;
        }
    for (j = 0; j < m; ++j)
        for (i = 0; i < m; ++i) {
            const uint32_t a = j * (m + 1) + i, b = a + 1, c = a + m + 2, e = a + m + 1;
            tri[t++] = a, tri[t++] = b, tri[t++] = c;  /* counter-clockwise seen from +z */
            tri[t++] = a, tri[t++] = c, tri[t++] = e;
        }
    d.type = LFEM_BODY_STATIC;
    s = lfem_body_create(w, &d, &floor_body);
    if (s == LFEM_OK) s = lfem_body_add_triangle_mesh(w, floor_body, x, verts, tri, 2 * m * m);
    free(x);
    free(tri);
    return s;
}

static Result run_size(unsigned n, unsigned steps) {
    Result r;
    lfem_world* w = NULL;
    lfem_mesh* mesh = NULL;
    lfem_body slab;
    lfem_world_def wd = lfem_world_def_default();
    lfem_body_def bd = lfem_body_def_default();
    lfem_world_stats st;
    lfem_profile p;
    const double size[3] = {n * CELL, n * CELL, LAYERS * CELL};
    const uint32_t cells[3] = {n, n, LAYERS};
    double baseline, h, t0, t1, per;
    unsigned k;
    memset(&r, 0, sizeof r);
    baseline = bench_status_bytes("VmRSS:");

    CHECK(lfem_world_create(&wd, &w));
    CHECK(add_floor(w, n));
    CHECK(lfem_mesh_create_box(size, cells, &mesh));
    bd.young_modulus = 1e7;
    bd.density = 1000.0;
    bd.damping = 5.0;
    bd.friction = 0.5;
    CHECK(lfem_body_create(w, &bd, &slab));
    CHECK(lfem_body_add_mesh(w, slab, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                             lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh)));
    r.tets = lfem_mesh_get_tet_count(mesh);
    r.nodes = lfem_mesh_get_node_count(mesh);
    lfem_mesh_destroy(mesh);

    /* One sub-step per call: just below the automatic step. */
    CHECK(lfem_world_get_stable_step(w, &h));
    h *= 0.9 * (1.0 - 1e-9);
    for (k = 0; k < 3; ++k) CHECK(lfem_world_step(w, h));
    CHECK(lfem_world_reset_profile(w));
    t0 = bench_now();
    for (k = 0; k < steps; ++k) CHECK(lfem_world_step(w, h));
    t1 = bench_now();
    CHECK(lfem_world_get_profile(w, &p));
    CHECK(lfem_world_get_stats(w, &st));
    r.steps = steps;
    r.contacts = st.contact_count;
    r.seconds_per_step = (t1 - t0) / steps;
    per = 1e9 / (r.tets * steps);
    r.phase_ns[0] = p.internal_forces.seconds * per;
    r.phase_ns[1] = p.predictor.seconds * per;
    r.phase_ns[2] = p.broad_phase.seconds * per;
    r.phase_ns[3] = (p.narrow_phase.seconds + p.shape_queries.seconds) * per;
    r.phase_ns[4] = p.normal_solve.seconds * per;
    r.phase_ns[5] = p.friction.seconds * per;
    r.phase_ns[6] = p.global_rotation.seconds * per;
    r.phase_ns[7] = p.commit.seconds * per;
    r.shape_tests = (double)p.shape_tests;
    r.ccd_queries = (double)p.ccd_queries;
    r.peak_bytes = bench_status_bytes("VmHWM:") - baseline;
    lfem_world_destroy(w);
    r.ok = p.substeps == steps && baseline > 0.0;
    return r;
}

/* Runs one size in a child process; its result comes back through a pipe. */
static Result run_size_isolated(unsigned n, unsigned steps) {
    Result r;
    int fd[2];
    pid_t pid;
    memset(&r, 0, sizeof r);
    if (pipe(fd) != 0) return r;
    fflush(stdout);
    pid = fork();
    if (pid == 0) {
        Result c;
        close(fd[0]);
        c = run_size(n, steps);
        if (write(fd[1], &c, sizeof c) != (ssize_t)sizeof c) _exit(1);
        _exit(0);
    }
    close(fd[1]);
    if (pid < 0 || read(fd[0], &r, sizeof r) != (ssize_t)sizeof r) memset(&r, 0, sizeof r);
    close(fd[0]);
    if (pid > 0) waitpid(pid, NULL, 0);
    return r;
}

int main(int argc, char** argv) {
    static const unsigned full_n[] = {7, 13, 26, 51, 102, 204};
    static const unsigned quick_n[] = {3, 5};
    const unsigned* sizes = full_n;
    unsigned count = sizeof full_n / sizeof full_n[0], i, q;
    int quick = 0;
    const char* csv_path = LFEM_BENCH_RESULTS_DIR "/scaling.csv";
    Result res[8];
    double sx = 0, sy = 0, sxx = 0, sxy = 0, slope;
    FILE* csv;
    for (i = 1; i < (unsigned)argc; ++i) {
        if (strcmp(argv[i], "--quick") == 0) quick = 1;
        else if (strcmp(argv[i], "--csv") == 0 && i + 1 < (unsigned)argc) csv_path = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--quick] [--csv path]\n", argv[0]);
            return 2;
        }
    }
    if (quick) sizes = quick_n, count = 2, csv_path = NULL;

    printf("lfem %s scaling: slab of n x n x %d cells (%.0f cm cubes, 6 tets each) resting on a "
           "static triangle-mesh floor, friction 0.5, one sub-step per call\n",
           lfem_version_string(), LAYERS, CELL * 100);
    printf("%8s %9s %8s %6s %9s %12s %10s |", "tets", "nodes", "contacts", "steps", "ms/step",
           "ns/tet/step", "bytes/tet");
    for (q = 0; q < PHASES; ++q) printf(" %9s", phase_names[q]);
    printf("   (ns per tet per step)\n");
    for (i = 0; i < count; ++i) {
        const double tets = 24.0 * sizes[i] * sizes[i];
        /* About 2e7 tet-steps per size (0.1 to 2 s of stepping), 5 to 2000 steps. */
        unsigned steps = quick ? 5 : (unsigned)fmin(2000.0, fmax(5.0, 2e7 / tets));
        res[i] = run_size_isolated(sizes[i], steps);
        if (!res[i].ok) {
            fprintf(stderr, "size n = %u failed\n", sizes[i]);
            return 1;
        }
        printf("%8.0f %9.0f %8.0f %6.0f %9.3f %12.1f %10.0f |", res[i].tets, res[i].nodes,
               res[i].contacts, res[i].steps, 1e3 * res[i].seconds_per_step,
               1e9 * res[i].seconds_per_step / res[i].tets, res[i].peak_bytes / res[i].tets);
        for (q = 0; q < PHASES; ++q) printf(" %9.2f", res[i].phase_ns[q]);
        printf("\n");
        fflush(stdout);
    }
    /* Least-squares slope of log(time per step) against log(tets). */
    for (i = 0; i < count; ++i) {
        const double x = log(res[i].tets), y = log(res[i].seconds_per_step);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);
    printf("log-log slope of time per step against tets (least squares, %u sizes): %.3f\n", count,
           slope);
    printf("shape queries: %.0f, libccd queries: %.0f (no rigid shapes in this scene)\n",
           res[count - 1].shape_tests, res[count - 1].ccd_queries);

    if (csv_path) {
        csv = fopen(csv_path, "w");
        if (!csv) {
            fprintf(stderr, "cannot write %s\n", csv_path);
            return 1;
        }
        fprintf(csv, "tets,nodes,contacts,steps,seconds_per_step,ns_per_tet_step,peak_bytes_per_tet");
        for (q = 0; q < PHASES; ++q) fprintf(csv, ",%s_ns_per_tet_step", phase_names[q]);
        fprintf(csv, "\n");
        for (i = 0; i < count; ++i) {
            fprintf(csv, "%.0f,%.0f,%.0f,%.0f,%.6e,%.2f,%.0f", res[i].tets, res[i].nodes,
                    res[i].contacts, res[i].steps, res[i].seconds_per_step,
                    1e9 * res[i].seconds_per_step / res[i].tets, res[i].peak_bytes / res[i].tets);
            for (q = 0; q < PHASES; ++q) fprintf(csv, ",%.3f", res[i].phase_ns[q]);
            fprintf(csv, "\n");
        }
        fprintf(csv, "# slope,%.4f\n", slope);
        fclose(csv);
        printf("wrote %s\n", csv_path);
    }
    return 0;
}
