/* Error against run time (issue 4): runs the validation problems of src/DESIGN.md section 11 over
 * mesh resolutions, step safety factors, material models and element kinds (4-node and 10-node
 * tets, issue 20), plus a Hertz impact of a Gmsh sphere on a rigid plane (hertz_scene.h), and
 * records for each run the errors against the closed forms and the wall time; then the same
 * two-bar impact with the penalty-contact baseline (penalty_baseline.h) at three stiffnesses,
 * with the stable step each one needs found by bisection.
 *
 *   bench_error_vs_runtime [--quick] [--out file.csv] [--repeats n]
 *     --quick    a small subset in a few seconds (the ctest smoke test)
 *     --repeats  runs of each setting, the fastest kept (the runs are deterministic: only the
 *                wall time differs, and other load on the machine only ever slows one down)
 *     --out    the CSV, default tests/bench/results/error_vs_runtime.csv in the source tree
 *
 * Prints a line per run, then Markdown tables: for each error level the fastest setting that
 * reaches it, and the penalty baseline against the multipliers. Wall times are of one run each
 * (clock_gettime MONOTONIC), set-up included, on whatever else the machine is doing. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"
#include "hertz_scene.h"
#include "two_bar_scene.h"
#include "validation_cases.h"

#ifndef LFEM_BENCH_RESULTS_DIR
#define LFEM_BENCH_RESULTS_DIR "."
#endif
#ifndef LFEM_BENCH_DATA_DIR
#define LFEM_BENCH_DATA_DIR "."
#endif

/* One row of the CSV. Errors are relative (signed); NAN where a column does not apply (written
 * as an empty field). */
typedef struct run_row {
    const char* problem;  /* two_bar, spin, cantilever, incline, hertz (1 m/s), hertz_10 (10 m/s) */
    char contact[24];     /* multipliers, or penalty_k<factor>x (the baseline); none */
    const char* model;
    uint32_t cells[3];
    uint32_t tets;
    double safety;        /* step / elastic stable limit */
    double step;          /* s */
    uint64_t steps;
    double wall;          /* s */
    int stable;
    double error;         /* the problem's main error (see the CSV header) */
    double impulse, plateau, peak_force, duration, v1, v2; /* two_bar (peak force, duration: hertz) */
    double penetration;   /* m */
    double momentum, kinetic, volume; /* spin */
    int quadratic;        /* 1: 10-node tets, 2: 10-node composite tets, 0: 4-node tets */
    double mass_scaling;  /* requested step / the step without mass scaling (1: the series'
                             reference run); NAN outside the mass-scaling series */
    double added_mass;    /* what mass scaling added over the body's mass with it */
    uint32_t nodes;
    char mesh[32];        /* "40x1x1", or the Hertz mesh's name */
} run_row;

typedef struct row_list {
    run_row* rows;
    size_t count, capacity;
} row_list;

static run_row* new_row(row_list* list) {
    if (list->count == list->capacity) {
        const size_t capacity = list->capacity ? 2 * list->capacity : 64;
        run_row* grown = (run_row*)realloc(list->rows, sizeof(run_row) * capacity);
        if (!grown) return NULL;
        list->rows = grown;
        list->capacity = capacity;
    }
    run_row* r = &list->rows[list->count++];
    memset(r, 0, sizeof *r);
    r->impulse = r->plateau = r->peak_force = r->duration = r->v1 = r->v2 = NAN;
    r->penetration = r->momentum = r->kinetic = r->volume = NAN;
    r->mass_scaling = r->added_mass = NAN;
    r->stable = 1;
    return r;
}

static const char* model_name(lfem_model m) {
    switch (m) {
    case LFEM_MODEL_PAPER: return "paper";
    case LFEM_MODEL_COROTATIONAL: return "corotational";
    case LFEM_MODEL_NEO_HOOKEAN: return "neo_hookean";
    case LFEM_MODEL_LINEAR: return "linear";
    default: return "unknown";
    }
}

static const char* element_name(const run_row* r) {
    return r->quadratic == 2 ? "tet10c" : r->quadratic ? "tet10" : "tet4";
}

static void print_row(const run_row* r) {
    printf("%-10s %-13s %-12s %-5s %14s %6u tets %6u nodes  safety %.2f  %7llu steps  %8.3f s  error %+.3e%s\n",
           r->problem, r->contact, r->model, element_name(r), r->mesh, r->tets, r->nodes, r->safety,
           (unsigned long long)r->steps, r->wall, r->error, r->stable ? "" : "  BLEW UP");
    fflush(stdout);
}

static void set_cells(run_row* r, const uint32_t cells[3]) {
    memcpy(r->cells, cells, sizeof r->cells);
    snprintf(r->mesh, sizeof r->mesh, "%ux%ux%u", cells[0], cells[1], cells[2]);
}

/* ---- the runs ------------------------------------------------------------------------------ */

static int g_repeats = 1; /* --repeats */

static int run_two_bar(row_list* list, const two_bar_config* c, two_bar_result* out) {
    two_bar_result res, again;
    if (two_bar_run(c, &res) != 0) return -1;
    for (int k = 1; k < g_repeats; ++k) {
        if (two_bar_run(c, &again) != 0) return -1;
        res.wall = fmin(res.wall, again.wall); /* the fastest */
    }
    const two_bar_exact e = two_bar_exact_solution();
    run_row* r = new_row(list);
    if (!r) return -1;
    r->problem = "two_bar";
    if (c->penalty_factor > 0)
        snprintf(r->contact, sizeof r->contact, "penalty_k%gx", c->penalty_factor);
    else if (c->penalty_factor < 0)
        snprintf(r->contact, sizeof r->contact, "no_contact");
    else
        snprintf(r->contact, sizeof r->contact, "multipliers");
    r->model = model_name(c->model);
    set_cells(r, c->cells);
    r->quadratic = c->quadratic;
    r->tets = res.tets;
    r->nodes = res.nodes;
    r->safety = c->step_ratio;
    r->step = res.step;
    r->steps = res.steps;
    r->wall = res.wall;
    r->stable = res.stable;
    r->impulse = res.impulse / e.impulse - 1;
    r->error = r->impulse;
    r->plateau = res.plateau / e.force - 1;
    r->peak_force = res.peak_force / e.force - 1;
    r->duration = res.duration / e.duration - 1;
    r->v1 = res.v1 / e.v1 - 1;
    r->v2 = res.v2 / e.v2 - 1;
    r->penetration = res.max_penetration;
    r->added_mass = res.added_mass / res.mass;
    print_row(r);
    if (out) *out = res;
    return 0;
}

typedef int (*case_function)(const case_config*, case_result*);

static int run_case_config(row_list* list, const char* problem, case_function run, case_config c) {
    const lfem_model model = c.model;
    const uint32_t* cells = c.cells;
    const double safety = c.safety;
    const int quadratic = c.quadratic;
    case_result res, again;
    if (run(&c, &res) != 0) return -1;
    for (int k = 1; k < g_repeats; ++k) {
        if (run(&c, &again) != 0) return -1;
        res.wall = fmin(res.wall, again.wall); /* the fastest */
    }
    run_row* r = new_row(list);
    if (!r) return -1;
    r->problem = problem;
    snprintf(r->contact, sizeof r->contact, strcmp(problem, "incline") == 0 ? "multipliers" : "none");
    r->model = model_name(model);
    set_cells(r, cells);
    r->quadratic = quadratic;
    r->tets = res.tets;
    r->nodes = res.nodes;
    r->safety = safety;
    r->step = res.step;
    r->steps = res.steps;
    r->wall = res.wall;
    r->error = res.error;
    if (strcmp(problem, "spin") == 0) {
        /* A free rigid spin keeps its angular momentum, kinetic energy and volume (up to the
         * centrifugal stretch, ~1e-4): the main error is the largest of the three changes, so
         * that a model that reads rotation as strain (linear) shows, though it keeps L. */
        r->momentum = res.error;
        r->kinetic = res.second_error;
        r->volume = res.third_error;
        if (fabs(r->kinetic) > fabs(r->error)) r->error = r->kinetic;
        if (fabs(r->volume) > fabs(r->error)) r->error = r->volume;
    }
    if (strcmp(problem, "incline") == 0) {
        r->penetration = res.second_error;
        r->added_mass = res.added_mass_share;
    }
    print_row(r);
    return 0;
}

static int run_case(row_list* list, const char* problem, case_function run, lfem_model model,
                    const uint32_t cells[3], double safety, double duration, int quadratic) {
    const case_config c = {model, {cells[0], cells[1], cells[2]}, safety, duration, quadratic, 0.0};
    return run_case_config(list, problem, run, c);
}

/* Mass scaling (issue 16), what it costs in accuracy: the two bars (40 cells, paper model) and
 * the incline (3^3 cells) with the step requested at 1 (the reference: nothing added), 2, 4
 * and 8 times the automatic step without it. Every tet of these uniform meshes needs the same
 * step, so all get the added mass, (factor^2 - 1) times their own: waves run factor times
 * slower. The bars' impulse and contact time are set by their mass and wave speed, and so go
 * wrong with it; the block sliding under gravity and Coulomb friction accelerates at
 * g (sin a - mu cos a) whatever its mass, so the incline keeps its accuracy and gets cheaper. */
static int run_mass_scaling(row_list* list, int quick) {
    static const double factors[4] = {1, 2, 4, 8};
    two_bar_config bar = {LFEM_MODEL_PAPER, {40, 1, 1}, 0.0, 0.9, 0.0, 200e-6, 0, 0.0};
    two_bar_result reference;
    if (two_bar_run(&bar, &reference) != 0) return -1;
    const case_config block = {LFEM_MODEL_PAPER, {3, 3, 3}, 0.9, 0, 0, 0.0};
    case_result sliding;
    if (incline_run(&block, &sliding) != 0) return -1;
    for (int k = quick ? 1 : 0; k < (quick ? 2 : 4); ++k) {
        /* The requested step is factor times the step taken without scaling. */
        bar.mass_scaling_step = factors[k] > 1 ? factors[k] * reference.step : 0.0;
        if (run_two_bar(list, &bar, NULL) != 0) return -1;
        list->rows[list->count - 1].mass_scaling = factors[k];
        case_config c = block;
        c.mass_scaling_step = factors[k] > 1 ? factors[k] * sliding.step : 0.0;
        if (run_case_config(list, "incline", incline_run, c) != 0) return -1;
        list->rows[list->count - 1].mass_scaling = factors[k];
    }
    return 0;
}

/* A Hertz impact at `speed` of the sphere mesh tests/bench/data/<name>.msh (problem "hertz" at
 * 1 m/s, "hertz_10" at 10 m/s); the main error is the larger of the peak force's and the
 * contact time's. */
/* Whether this build reads Gmsh files (LFEM_WITH_IO): without the reader the Hertz runs are
 * left out, with a note. */
static int gmsh_reader_built(void) {
    lfem_mesh* mesh = NULL;
    const lfem_status s = lfem_mesh_load_gmsh(LFEM_BENCH_DATA_DIR "/hertz_tet10_20.msh", &mesh);
    lfem_mesh_destroy(mesh);
    return s != LFEM_UNSUPPORTED;
}

static int run_hertz(row_list* list, const char* problem, const char* name, double speed, int composite) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s.msh", LFEM_BENCH_DATA_DIR, name);
    const hertz_config c = {path, LFEM_MODEL_LINEAR, 0.9, speed, composite};
    hertz_result res, again;
    if (hertz_run(&c, &res) != 0) return -1;
    for (int k = 1; k < g_repeats; ++k) {
        if (hertz_run(&c, &again) != 0) return -1;
        res.wall = fmin(res.wall, again.wall); /* the fastest */
    }
    run_row* r = new_row(list);
    if (!r) return -1;
    r->problem = problem;
    snprintf(r->contact, sizeof r->contact, "multipliers");
    r->model = model_name(c.model);
    snprintf(r->mesh, sizeof r->mesh, "%s", name);
    r->quadratic = res.nodes_per_tet == 10 ? 1 + (composite != 0) : 0;
    r->tets = res.tets;
    r->nodes = res.nodes;
    r->safety = c.step_ratio;
    r->step = res.step;
    r->steps = res.steps;
    r->wall = res.wall;
    r->peak_force = res.peak_force / res.exact.force - 1;
    r->duration = res.duration / res.exact.duration - 1;
    r->error = fabs(r->peak_force) > fabs(r->duration) ? r->peak_force : r->duration;
    r->penetration = res.max_penetration;
    print_row(r);
    return 0;
}

/* The runs with 10-node tets (kind 1) or composite ones (kind 2): two bars (paper model) along
 * 20 to 160 cells and 2 across, the cantilever (corotational, and one mesh each with the other
 * models), spin and incline. */
static int run_quadratic_cases(row_list* list, int quick, int kind) {
    static const uint32_t bars[7][3] = {{20, 1, 1}, {40, 1, 1}, {80, 1, 1}, {160, 1, 1},
                                        {20, 2, 2}, {40, 2, 2}, {80, 2, 2}};
    for (int i = 0; i < (quick ? 1 : 7); ++i) {
        const two_bar_config bar = {LFEM_MODEL_PAPER, {bars[i][0], bars[i][1], bars[i][2]}, 0.0, 0.9, 0.0, 200e-6, kind, 0.0};
        if (run_two_bar(list, &bar, NULL) != 0) return -1;
    }
    static const uint32_t beams[5][3] = {{10, 1, 1}, {20, 1, 1}, {20, 1, 2}, {30, 1, 3}, {40, 1, 4}};
    for (int i = 0; i < (quick ? 1 : 5); ++i)
        if (run_case(list, "cantilever", cantilever_run, LFEM_MODEL_COROTATIONAL, beams[i], 0.9, 0, kind) != 0)
            return -1;
    if (quick) return 0;
    static const lfem_model others[3] = {LFEM_MODEL_PAPER, LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_LINEAR};
    for (int m = 0; m < 3; ++m)
        if (run_case(list, "cantilever", cantilever_run, others[m], beams[0], 0.9, 0, kind) != 0) return -1;
    static const uint32_t spins[2][3] = {{2, 1, 1}, {4, 2, 2}};
    static const uint32_t blocks[2][3] = {{2, 2, 2}, {3, 3, 3}};
    for (int i = 0; i < 2; ++i)
        if (run_case(list, "spin", spin_run, LFEM_MODEL_COROTATIONAL, spins[i], 0.9, 0, kind) != 0 ||
            run_case(list, "spin", spin_run, LFEM_MODEL_NEO_HOOKEAN, spins[i], 0.9, 0, kind) != 0 ||
            run_case(list, "incline", incline_run, LFEM_MODEL_PAPER, blocks[i], 0.9, 0, kind) != 0)
            return -1;
    return 0;
}

/* The largest step ratio (fixed step / elastic limit) at which the two-bar impact does not
 * blow up. Explicit penalty contact is not monotonic near its limit (a step may blow up while a
 * slightly larger one survives), so this sweeps down a geometric grid (factor `grid`) from hi
 * to the top of the first `confirm` consecutive stable grid steps (every grid step from there
 * down to confirm steps below is stable), then bisects `refine` times between that step and the
 * unstable grid step above it. *highest: the largest stable grid step met at all. Runs that
 * blow up stop early, so sweeping from above is cheap. Returns 0, or -1. */
static int find_stable_ratio(two_bar_config c, double hi, double grid, int confirm, int refine,
                             double* ratio, double* highest) {
    double top = 0;
    int run = 0;
    two_bar_result res;
    *highest = 0;
    for (double r = hi; r >= 1.0 / 256 && run < confirm; r /= grid) {
        c.step_ratio = r;
        if (two_bar_run(&c, &res) != 0) return -1;
        if (!res.stable) {
            top = 0, run = 0;
            continue;
        }
        if (*highest == 0) *highest = r;
        if (run++ == 0) top = r;
    }
    double unstable = top * grid;
    for (int k = 0; k < refine && top > 0 && top < hi; ++k) {
        c.step_ratio = sqrt(top * unstable);
        if (two_bar_run(&c, &res) != 0) return -1;
        if (res.stable)
            top = c.step_ratio;
        else
            unstable = c.step_ratio;
    }
    if (top > *highest) *highest = top;
    *ratio = top;
    return 0;
}

/* ---- output -------------------------------------------------------------------------------- */

static void csv_number(FILE* f, double v) {
    if (isnan(v))
        fputc(',', f);
    else
        fprintf(f, ",%.6g", v);
}

static int write_csv(const char* path, const row_list* list) {
    FILE* f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "cannot write %s\n", path);
        return -1;
    }
    /* error: two_bar impulse; spin the largest of momentum_err, kinetic_err, volume_change;
     * cantilever tip deflection; incline acceleration; hertz the larger of peak_force_err and
     * duration_err. All errors relative; penetration in m. element: tet4, tet10 or tet10c; mesh: the
     * cells, or the Hertz mesh (cells 0). */
    fprintf(f, "problem,contact,model,cells_x,cells_y,cells_z,tets,safety,step_s,steps,wall_s,stable,"
               "error,impulse_err,plateau_err,peak_force_err,duration_err,v1_err,v2_err,"
               "max_penetration_m,momentum_err,kinetic_err,volume_change,element,nodes,mesh,"
               "mass_scaling,added_mass_share\n");
    for (size_t i = 0; i < list->count; ++i) {
        const run_row* r = &list->rows[i];
        fprintf(f, "%s,%s,%s,%u,%u,%u,%u,%.4g,%.6g,%llu,%.4f,%d", r->problem, r->contact, r->model,
                r->cells[0], r->cells[1], r->cells[2], r->tets, r->safety, r->step,
                (unsigned long long)r->steps, r->wall, r->stable);
        csv_number(f, r->error);
        csv_number(f, r->impulse);
        csv_number(f, r->plateau);
        csv_number(f, r->peak_force);
        csv_number(f, r->duration);
        csv_number(f, r->v1);
        csv_number(f, r->v2);
        csv_number(f, r->penetration);
        csv_number(f, r->momentum);
        csv_number(f, r->kinetic);
        csv_number(f, r->volume);
        fprintf(f, ",%s,%u,%s", element_name(r), r->nodes, r->mesh);
        csv_number(f, r->mass_scaling);
        csv_number(f, r->added_mass);
        fputc('\n', f);
    }
    if (fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        return -1;
    }
    return 0;
}

/* The fastest stable lfem run (no baseline) of a problem with 4-node or 10-node tets within
 * an error level, or NULL. */
static const run_row* fastest_within(const row_list* list, const char* problem, int quadratic, double level) {
    const run_row* best = NULL;
    for (size_t i = 0; i < list->count; ++i) {
        const run_row* r = &list->rows[i];
        if (strcmp(r->problem, problem) != 0 || r->quadratic != quadratic || !r->stable ||
            strncmp(r->contact, "penalty", 7) == 0 || !isnan(r->mass_scaling) || !(fabs(r->error) <= level))
            continue;
        if (!best || r->wall < best->wall) best = r;
    }
    return best;
}

static void print_setting(const run_row* r) {
    if (r)
        printf(" %s, %s, %.2f | %.3f s | %+.3f %% |", r->mesh, r->model, r->safety, r->wall, 100 * r->error);
    else
        printf(" not reached | | |");
}

/* For each problem and error level, the fastest setting with linear and with 10-node tets. */
static void print_levels_table(const row_list* list) {
    static const char* problems[] = {"two_bar", "spin", "cantilever", "incline", "hertz", "hertz_10"};
    static const char* what[] = {"impulse", "angular momentum, kinetic energy, volume", "tip deflection",
                                  "acceleration", "peak force, contact time; 1 m/s",
                                  "peak force, contact time; 10 m/s"};
    static const double levels[] = {0.05, 0.02, 0.01, 0.005, 0.003};
    printf("\n| problem (error) | level | 4-node tets: mesh, model, safety | wall time | error "
           "| 10-node tets: mesh, model, safety | wall time | error "
           "| 10-node composite tets: mesh, model, safety | wall time | error |\n");
    printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (int p = 0; p < 6; ++p)
        for (int l = 0; l < 5; ++l) {
            printf("| %s (%s) | %g %% |", problems[p], what[p], 100 * levels[l]);
            print_setting(fastest_within(list, problems[p], 0, levels[l]));
            print_setting(fastest_within(list, problems[p], 1, levels[l]));
            print_setting(fastest_within(list, problems[p], 2, levels[l]));
            printf("\n");
        }
}

/* Of the runs of a problem with one element kind within max_wall seconds, the smallest |error|
 * (as a run, or NULL). */
static const run_row* best_within_time(const row_list* list, const char* problem, int quadratic, double max_wall) {
    const run_row* best = NULL;
    for (size_t i = 0; i < list->count; ++i) {
        const run_row* r = &list->rows[i];
        if (strcmp(r->problem, problem) != 0 || r->quadratic != quadratic || !r->stable ||
            strncmp(r->contact, "penalty", 7) == 0 || strcmp(r->contact, "no_contact") == 0 ||
            !isnan(r->mass_scaling) || r->wall > max_wall)
            continue;
        if (!best || fabs(r->error) < fabs(best->error)) best = r;
    }
    return best;
}

/* Issue 20's targets for the 10-node tets (kind 1) or the composite ones (kind 2), from the
 * runs made. */
static void print_quadratic_targets(const row_list* list, int kind) {
    const char* name = kind == 2 ? "10-node composite" : "10-node";
    const run_row* beam = fastest_within(list, "cantilever", kind, 0.01);
    printf("\ntarget (%s cantilever within 1 %% in under 2 s): ", name);
    if (beam)
        printf("%s, %s %s safety %.2f, %.3f s, %+.3f %%\n", beam->wall < 2.0 ? "met" : "NOT met", beam->mesh,
               beam->model, beam->safety, beam->wall, 100 * beam->error);
    else
        printf("NOT met (no run within 1 %%)\n");
    const run_row* hertz = fastest_within(list, "hertz", kind, 0.05);
    printf("target (%s Hertz impact, peak force and contact time within 5 %% in under 10 s): ", name);
    if (hertz)
        printf("%s at 1 m/s, %s, %.3f s, peak force %+.2f %%, contact time %+.2f %%\n",
               hertz->wall < 10.0 ? "met" : "NOT met", hertz->mesh, hertz->wall, 100 * hertz->peak_force,
               100 * hertz->duration);
    else
        printf("NOT met at 1 m/s (no run within 5 %%)\n");
    const run_row* fast10 = best_within_time(list, "hertz_10", kind, 10.0);
    if (fast10)
        printf("  at 10 m/s the best %s run within 10 s: %s, %.3f s, peak force %+.2f %%, contact time %+.2f %%\n",
               name, fast10->mesh, fast10->wall, 100 * fast10->peak_force, 100 * fast10->duration);
    printf("target (two bars with %s tets no worse than with linear tets at the same run time):\n", name);
    int worse = 0, runs = 0;
    for (size_t i = 0; i < list->count; ++i) {
        const run_row* q = &list->rows[i];
        if (strcmp(q->problem, "two_bar") != 0 || q->quadratic != kind || strcmp(q->contact, "multipliers") != 0) continue;
        const run_row* l = best_within_time(list, "two_bar", 0, q->wall);
        ++runs;
        worse += l && fabs(l->error) < fabs(q->error);
        printf("  %s %s: %.3f s, impulse %+.3f %%; the best linear run within that time: ", q->mesh, q->model,
               q->wall, 100 * q->error);
        if (l)
            printf("%s %s safety %.2f, %.3f s, %+.3f %%\n", l->mesh, l->model, l->safety, l->wall, 100 * l->error);
        else
            printf("none\n");
    }
    printf("  %s: %d of %d %s runs are worse than the best linear run of the same time\n",
           worse ? "NOT met" : "met", worse, runs, name);
}

/* The mass-scaling series: per problem, the requested step's factor, the step, the added mass,
 * the wall time and the errors. */
static void print_mass_scaling_table(const row_list* list) {
    printf("\n| problem | mesh | requested step | step | added mass | wall time | error |\n");
    printf("| --- | --- | --- | --- | --- | --- | --- |\n");
    for (size_t i = 0; i < list->count; ++i) {
        const run_row* r = &list->rows[i];
        if (isnan(r->mass_scaling)) continue;
        printf("| %s (%s) | %s | x%g | %.3g s | %.1f %% | %.3f s | %+.2f %%", r->problem,
               strcmp(r->problem, "two_bar") == 0 ? "impulse" : "acceleration", r->mesh, r->mass_scaling,
               r->step, 100 * r->added_mass, r->wall, 100 * r->error);
        if (strcmp(r->problem, "two_bar") == 0)
            printf(" (contact time %+.1f %%, bar 2's final velocity %+.1f %%)", 100 * r->duration, 100 * r->v2);
        printf(" |\n");
    }
}

/* "1.05e-06 s (x1.000)", with the isolated stable steps above it when there are any. */
static void stable_cell(char* out, size_t size, double ratio, double highest, double elastic_step) {
    if (highest > ratio * 1.001)
        snprintf(out, size, "%.4g s (x%.3f; isolated stable steps up to x%.3f)", ratio * elastic_step,
                 ratio, highest);
    else
        snprintf(out, size, "%s%.4g s (x%.3f)", ratio >= 2.0 ? ">= " : "", ratio * elastic_step, ratio);
}

/* ---- the sweep ----------------------------------------------------------------------------- */

int main(int argc, char** argv) {
    int quick = 0, only_10_node = 0;
    const char* out = LFEM_BENCH_RESULTS_DIR "/error_vs_runtime.csv";
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--quick") == 0)
            quick = 1;
        else if (strcmp(argv[i], "--10-node") == 0)
            only_10_node = 1;
        else if (strcmp(argv[i], "--out") == 0 && i + 1 < argc)
            out = argv[++i];
        else if (strcmp(argv[i], "--repeats") == 0 && i + 1 < argc && atoi(argv[i + 1]) >= 1)
            g_repeats = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_error_vs_runtime [--quick] [--10-node] [--out file.csv] [--repeats n]\n"
                            "  --10-node: the 10-node runs and the 4-node two bars they are compared with only\n");
            return 2;
        }
    }
    const double start = bench_now();
    row_list list = {0};
    const lfem_model all_models[4] = {LFEM_MODEL_PAPER, LFEM_MODEL_LINEAR, LFEM_MODEL_COROTATIONAL,
                                      LFEM_MODEL_NEO_HOOKEAN};
    printf("lfem %s: error against run time%s, the fastest of %d run(s) of each setting\n", lfem_version_string(),
           quick ? " (quick subset)" : "", g_repeats);

    /* Two-bar impact, nu = 0, Lagrange multipliers. Refining along the bar is what pays: with
     * nu = 0 nothing couples the cross-section, so one cell across is enough. */
    two_bar_config bar = {LFEM_MODEL_PAPER, {40, 1, 1}, 0.0, 0.9, 0.0, 200e-6, 0, 0.0};
    static const uint32_t ladder[5] = {40, 80, 160, 240, 320};
    const int ladder_count = quick ? 2 : 5;
    for (int m = 0; m < (quick ? 2 : only_10_node ? 1 : 4); ++m)
        for (int i = 0; i < ladder_count; ++i) {
            bar.model = all_models[m];
            bar.cells[0] = ladder[i];
            bar.cells[1] = bar.cells[2] = 1;
            if (run_two_bar(&list, &bar, NULL) != 0) return 1;
        }
    if (only_10_node) {
        /* The largest safe step, where the 4-node bars are fastest for their error. */
        for (int i = 0; i < 5; ++i) {
            bar.cells[0] = ladder[i];
            bar.step_ratio = 1.0;
            if (run_two_bar(&list, &bar, NULL) != 0) return 1;
        }
    } else if (!quick) {
        /* Step safety factors (paper model), and cells across the bar. */
        static const double safeties[3] = {0.5, 0.7, 1.0};
        for (int s = 0; s < 3; ++s)
            for (int i = 0; i < (s == 2 ? 5 : 4); ++i) { /* 320 cells at the largest step only */
                bar.model = LFEM_MODEL_PAPER;
                bar.cells[0] = ladder[i];
                bar.cells[1] = bar.cells[2] = 1;
                bar.step_ratio = safeties[s];
                if (run_two_bar(&list, &bar, NULL) != 0) return 1;
            }
        static const uint32_t across[5][3] = {{40, 2, 2}, {40, 4, 4}, {80, 2, 2}, {80, 4, 4}, {160, 2, 2}};
        for (int i = 0; i < 5; ++i) {
            bar.model = LFEM_MODEL_PAPER;
            bar.step_ratio = 0.9;
            memcpy(bar.cells, across[i], sizeof bar.cells);
            if (run_two_bar(&list, &bar, NULL) != 0) return 1;
        }
    }

    /* Spinning body (one turn), cantilever, incline: four meshes each, the four models, and a
     * smaller step on one model. */
    static const uint32_t spin_meshes[4][3] = {{2, 1, 1}, {4, 2, 2}, {6, 3, 3}, {8, 4, 4}};
    static const uint32_t beam_meshes[7][3] = {{20, 1, 2}, {40, 1, 4}, {60, 1, 6}, {80, 1, 8},
                                               {20, 1, 4}, {20, 1, 8}, {40, 1, 8}};
    static const uint32_t block_meshes[4][3] = {{2, 2, 2}, {3, 3, 3}, {4, 4, 4}, {6, 6, 6}};
    if (only_10_node) {
    } else if (quick) {
        if (run_case(&list, "spin", spin_run, LFEM_MODEL_COROTATIONAL, spin_meshes[0], 0.9, 0.2, 0) != 0 ||
            run_case(&list, "cantilever", cantilever_run, LFEM_MODEL_COROTATIONAL, beam_meshes[0], 0.9, 0, 0) != 0 ||
            run_case(&list, "incline", incline_run, LFEM_MODEL_PAPER, block_meshes[0], 0.9, 0, 0) != 0)
            return 1;
    } else {
        for (int m = 0; m < 4; ++m)
            for (int i = 0; i < 4; ++i) {
                /* The finest spin and beam meshes on the rotating models only: the linear model
                 * cannot spin (rotation read as strain), and the beam's finest mesh is costly. */
                const int rotating = all_models[m] != LFEM_MODEL_LINEAR;
                if ((i < 3 || rotating) &&
                    run_case(&list, "spin", spin_run, all_models[m], spin_meshes[i], 0.9, 0, 0) != 0)
                    return 1;
                if ((i < 3 || all_models[m] == LFEM_MODEL_COROTATIONAL) &&
                    run_case(&list, "cantilever", cantilever_run, all_models[m], beam_meshes[i], 0.9, 0, 0) != 0)
                    return 1;
                if (run_case(&list, "incline", incline_run, all_models[m], block_meshes[i], 0.9, 0, 0) != 0)
                    return 1;
            }
        for (int i = 4; i < 7; ++i)
            if (run_case(&list, "cantilever", cantilever_run, LFEM_MODEL_COROTATIONAL, beam_meshes[i], 0.9, 0, 0) != 0)
                return 1;
        for (int i = 0; i < 3; ++i)
            if (run_case(&list, "spin", spin_run, LFEM_MODEL_COROTATIONAL, spin_meshes[i], 0.5, 0, 0) != 0 ||
                run_case(&list, "cantilever", cantilever_run, LFEM_MODEL_COROTATIONAL, beam_meshes[i], 0.5, 0, 0) != 0 ||
                run_case(&list, "incline", incline_run, LFEM_MODEL_PAPER, block_meshes[i], 0.5, 0, 0) != 0)
                return 1;
    }

    /* 10-node tets (issue 20): the same problems, the cantilever with one to three elements
     * through the depth, and the two bars along and across. */
    if (run_quadratic_cases(&list, quick, 1) != 0 || run_quadratic_cases(&list, quick, 2) != 0) return 1;
    if (!only_10_node && run_mass_scaling(&list, quick) != 0) return 1;
    /* Hertz impact of the Gmsh sphere (tests/bench/data/hertz_*.msh: element kind, element
     * size at the pole in 0.1 mm), linear model, at 1 m/s, and at 10 m/s (a / R = 0.11, where
     * the finite sphere departs from Hertz's half-space: the meshes converge to ~5 % off). */
    static const char* hertz_meshes[6] = {"hertz_tet4_10", "hertz_tet4_07", "hertz_tet4_05",
                                          "hertz_tet10_20", "hertz_tet10_15", "hertz_tet10_10"};
    const int hertz = gmsh_reader_built();
    if (!hertz) printf("hertz: left out (this build of lfem has no Gmsh reader: LFEM_WITH_IO=OFF)\n");
    for (int i = 0; i < 6 && hertz; ++i)
        if ((!quick || i == 0 || i == 3) && (!only_10_node || i >= 3) &&
            run_hertz(&list, "hertz", hertz_meshes[i], 1.0, 0) != 0)
            return 1;
    for (int i = 1; i < 5 && hertz && !quick; ++i)
        if ((!only_10_node || i >= 3) && run_hertz(&list, "hertz_10", hertz_meshes[i], 10.0, 0) != 0) return 1;
    /* The composite element on the 10-node spheres. */
    for (int i = 3; i < 6 && hertz; ++i)
        if ((!quick || i == 3) && run_hertz(&list, "hertz", hertz_meshes[i], 1.0, 1) != 0) return 1;
    for (int i = 3; i < 5 && hertz && !quick; ++i)
        if (run_hertz(&list, "hertz_10", hertz_meshes[i], 10.0, 1) != 0) return 1;

    if (only_10_node) { /* no CSV: the committed one holds the whole sweep */
        printf("\n%zu runs in %.1f s\n", list.count, bench_now() - start);
        print_levels_table(&list);
        print_quadratic_targets(&list, 1);
        print_quadratic_targets(&list, 2);
        free(list.rows);
        return 0;
    }

    /* The penalty baseline against the multipliers on one mesh: the largest step that does not
     * blow up (a sweep down from 2 times the elastic limit in steps of 5 %, refined by
     * bisection to ~0.6 %, see find_stable_ratio), then a run at 0.9 of it, as a user would run
     * either. The bars without any contact give their own
     * critical step: the one the multipliers should keep. */
    static const double factors[4] = {0.0, 1.0, 10.0, 100.0};
    const uint32_t penalty_cells = quick ? 40 : 80;
    const double grid = quick ? 1.25 : 1.05;
    const int confirm = quick ? 2 : 3, refine = quick ? 1 : 3;
    double stable_ratio[4], highest_ratio[4], free_ratio = 0, free_highest = 0, elastic_step = 0;
    two_bar_result pen[4];
    size_t pen_row[4];
    {
        const two_bar_config c = {LFEM_MODEL_PAPER, {penalty_cells, 1, 1}, 0.0, 1.0, -1.0, 200e-6, 0, 0.0};
        if (find_stable_ratio(c, 2.0, grid, confirm, refine, &free_ratio, &free_highest) != 0) return 1;
    }
    for (int f = 0; f < 4; ++f) {
        if (quick && (f == 1 || f == 3)) continue; /* multipliers and k = 10x only */
        two_bar_config c = {LFEM_MODEL_PAPER, {penalty_cells, 1, 1}, 0.0, 1.0, factors[f], 200e-6, 0, 0.0};
        if (find_stable_ratio(c, 2.0, grid, confirm, refine, &stable_ratio[f], &highest_ratio[f]) != 0)
            return 1;
        c.step_ratio = 0.9 * stable_ratio[f];
        pen_row[f] = list.count;
        if (c.step_ratio <= 0 || run_two_bar(&list, &c, &pen[f]) != 0) return 1;
        elastic_step = pen[f].elastic_step;
    }
    if (!quick) /* the baseline on the other meshes too, for the plot (the stiff springs' tiny
                   steps make 160 cells too costly for them) */
        for (int f = 1; f < 4; ++f)
            for (int i = 0; i < (f == 1 ? 3 : 1); i += 2) {
                two_bar_config c = {LFEM_MODEL_PAPER, {ladder[i], 1, 1}, 0.0,
                                    0.9 * stable_ratio[f], factors[f], 200e-6, 0, 0.0};
                if (run_two_bar(&list, &c, NULL) != 0) return 1;
            }

    if (write_csv(out, &list) != 0) return 1;
    printf("\nwrote %s (%zu runs) in %.1f s\n", out, list.count, bench_now() - start);

    print_levels_table(&list);
    /* The target. */
    const run_row* target = NULL;
    for (size_t i = 0; i < list.count; ++i) {
        const run_row* r = &list.rows[i];
        if (strcmp(r->problem, "two_bar") == 0 && strcmp(r->contact, "multipliers") == 0 &&
            r->stable && fabs(r->error) <= 0.005 && (!target || r->wall < target->wall))
            target = r;
    }
    if (target)
        printf("\ntarget (two-bar impulse error <= 0.5 %% in <= 1 s): %s, %ux%ux%u %s safety %.2f, "
               "%.3f s, %+.3f %%\n", target->wall <= 1.0 ? "met" : "NOT met", target->cells[0],
               target->cells[1], target->cells[2], target->model, target->safety, target->wall,
               100 * target->error);
    else
        printf("\ntarget (two-bar impulse error <= 0.5 %% in <= 1 s): NOT met (no run within 0.5 %%)\n");
    print_quadratic_targets(&list, 1);
    print_quadratic_targets(&list, 2);
    printf("\nMass scaling (lfem_world_def.mass_scaling_step), the step requested at a multiple of the "
           "automatic step without it:\n");
    print_mass_scaling_table(&list);

    printf("\nPenalty baseline against Lagrange multipliers: two-bar impact, %ux1x1 cells a bar, paper "
           "model, elastic stable limit %.4g s; k in multiples of E A2 / l_e\n\n",
           penalty_cells, elastic_step);
    printf("| contact | largest stable step (x elastic limit) | step used | max penetration | impulse "
           "error | plateau error | peak force error | duration error | wall time |\n");
    printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
    char cell[96];
    stable_cell(cell, sizeof cell, free_ratio, free_highest, elastic_step);
    printf("| no contact (bars pass through each other) | %s | | | | | | | |\n", cell);
    for (int f = 0; f < 4; ++f) {
        if (quick && (f == 1 || f == 3)) continue;
        const run_row* r = &list.rows[pen_row[f]];
        char name[48];
        if (factors[f] > 0)
            snprintf(name, sizeof name, "penalty baseline, k = %gx", factors[f]);
        else
            snprintf(name, sizeof name, "Lagrange multipliers (lfem)");
        stable_cell(cell, sizeof cell, stable_ratio[f], highest_ratio[f], elastic_step);
        printf("| %s | %s | %.4g s | %.2e m | %+.3f %% | %+.3f %% | %+.2f %% | %+.2f %% | %.3f s%s |\n",
               name, cell, pen[f].step,
               pen[f].max_penetration, 100 * r->impulse, 100 * r->plateau, 100 * r->peak_force,
               100 * r->duration, r->wall, r->stable ? "" : " (blew up)");
    }
    free(list.rows);
    return 0;
}
