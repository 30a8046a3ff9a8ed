/* Side by side with Bullet (issue 7): the same soft cubes dropped on a static floor, simulated
 * by lfem (public C API, neo-Hookean) and by Bullet's deformable world (neo-Hookean), one after
 * the other in this process, for one cube and for a 4 x 4 grid of cubes (scene.h).
 *
 * Damping differs in kind between the engines, and Bullet's cost depends on it, so Bullet runs
 * twice:
 *   Bullet-S  Bullet's default: btDeformableNeoHookeanForce damping 0.05 s, a stiffness-
 *             proportional damping that Bullet solves implicitly (a Krylov solve every step);
 *   Bullet-M  no stiffness damping; btSoftBody::Config::drag = alpha x step, the same
 *             mass-proportional damping alpha as lfem's (explicit, nearly free).
 * lfem runs three times: with its automatic step (re-checking the stable limit of the
 * neo-Hookean bodies as they deform), with Bullet's step fixed (checked once per call), both on
 * one thread like Bullet, and with the automatic step on two threads ("lfem-2t": this machine's
 * two cores; Debian's Bullet steps a deformable world on one thread).
 *
 * Printed per run: the step, wall time per simulated second, tet-steps per second, the largest
 * penetration into the floor, the RMS node speed at rest (last 10 % of the run), the final
 * lowest and highest node; the ratios lfem/Bullet; whether the target is met; where lfem
 * spent its time (lfem_world_get_profile). Wall times are measurements on a shared machine: only
 * ratios taken in one run mean anything.
 *
 *   bench_bullet [--edge m] [--cells n] [--duration s] [--grids 1,4] [--lfem-damping a]
 *                [--bullet-damping b] [--bullet-substeps k] [--bullet-implicit]
 *                [--only lfem|bullet] [--repeats n]
 *
 * --repeats n: every lfem run and Bullet-M run n times, the fastest kept (the runs are
 * deterministic; other load on the machine only slows one down); Bullet-S, minutes a run,
 * once.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_bullet.h"
#include "run_lfem.h"

/* "No penetration": deeper than this (m) counts. lfem's contact leaves nodes on the floor to
 * rounding (1e-18 m here); a nanometre is far below anything visible at 0.1 m cells. */
#define NO_PENETRATION 1e-9
#define TARGET_SPEEDUP 20.0

static void print_row(const char* engine, uint32_t cubes, const bench_result* r) {
    if (!r->ok) {
        printf("%5u  %-10s (run failed, see the message above)\n", cubes, engine);
        return;
    }
    printf("%5u  %-10s %6.0f  %9.3e  %5.0f  %9.3f  %11.4g  %10.2e  %10.2e  %8.4f  %7.4f\n",
           cubes, engine, r->tets, r->step_max, r->steps, r->wall_seconds / r->simulated_seconds,
           r->tets * r->steps / r->wall_seconds, r->max_penetration, r->rest_rms_velocity,
           r->lowest_final, r->top_final);
}

static double wall_per_second(const bench_result* r) {
    return r->wall_seconds / r->simulated_seconds;
}

/* The ratio row a/b; a ratio with a zero denominator is printed as "-". */
static void print_ratio(const char* name, uint32_t cubes, const bench_result* a,
                        const bench_result* b) {
    char pen[16] = "-";
    if (!a->ok || !b->ok) return;
    if (b->max_penetration > 0)
        snprintf(pen, sizeof pen, "%.3g", a->max_penetration / b->max_penetration);
    printf("%5u  %-10s %6s  %9.3f  %5.3f  %9.4f  %11.4g  %10s  %10.3g   speed-up %.1fx\n", cubes,
           name, "", a->step_max / b->step_max, a->steps / b->steps,
           wall_per_second(a) / wall_per_second(b),
           (a->tets * a->steps / a->wall_seconds) / (b->tets * b->steps / b->wall_seconds), pen,
           a->rest_rms_velocity / b->rest_rms_velocity, wall_per_second(b) / wall_per_second(a));
}

/* The target: lfem at least 20 x faster at an equal or smaller step, no penetration. */
static void print_target(const char* against, uint32_t cubes, const bench_result* l,
                         const bench_result* b) {
    const double speedup = wall_per_second(b) / wall_per_second(l);
    const int step_ok = l->step_max <= b->step_max * (1 + 1e-12);
    const int pen_ok = l->max_penetration <= NO_PENETRATION;
    if (!l->ok || !b->ok) return;
    printf("target, %u cube(s), lfem against %s: %.1fx faster (>= %.0fx: %s), step %s, "
           "penetration %.2g m (%s) -> %s\n",
           cubes, against, speedup, TARGET_SPEEDUP, speedup >= TARGET_SPEEDUP ? "yes" : "no",
           step_ok ? "equal or smaller" : "LARGER", l->max_penetration,
           pen_ok ? "none" : "some", speedup >= TARGET_SPEEDUP && step_ok && pen_ok ? "MET"
                                                                                  : "NOT MET");
}

static void print_profile(const char* engine, uint32_t cubes, const lfem_profile* p,
                          const bench_result* r) {
    const double wall = r->wall_seconds;
    const struct {
        const char* name;
        double seconds;
    } phase[] = {{"internal forces", p->internal_forces.seconds},
                 {"predictor", p->predictor.seconds},
                 {"broad phase", p->broad_phase.seconds},
                 {"narrow phase", p->narrow_phase.seconds},
                 {"shape queries", p->shape_queries.seconds},
                 {"normal solve", p->normal_solve.seconds},
                 {"friction", p->friction.seconds},
                 {"commit", p->commit.seconds}};
    double sum = 0;
    size_t i;
    printf("%s, %u cube(s): smallest stable limit %.4e s; %% of the stepping wall time:",
           engine, cubes, r->stable_limit);
    for (i = 0; i < sizeof phase / sizeof phase[0]; ++i) {
        printf(" %s %.1f,", phase[i].name, 100.0 * phase[i].seconds / wall);
        sum += phase[i].seconds;
    }
    printf(" outside the phases (stable-step checks, call overhead) %.1f\n",
           100.0 * (wall - sum) / wall);
}

/* The fastest of `repeats` runs (each run is deterministic: only its wall time differs; other
 * load on a shared machine only ever slows a run down). */
static bench_result fastest_lfem(const bench_scene* s, lfem_profile* profile, uint32_t repeats) {
    bench_result best = bench_run_lfem(s, profile);
    uint32_t k;
    for (k = 1; k < repeats && best.ok; ++k) {
        lfem_profile p;
        const bench_result r = bench_run_lfem(s, &p);
        if (r.ok && r.wall_seconds < best.wall_seconds) best = r, *profile = p;
    }
    return best;
}
static bench_result fastest_bullet(const bench_scene* s, uint32_t repeats) {
    bench_result best = bench_run_bullet(s);
    uint32_t k;
    for (k = 1; k < repeats && best.ok; ++k) {
        const bench_result r = bench_run_bullet(s);
        if (r.ok && r.wall_seconds < best.wall_seconds) best = r;
    }
    return best;
}

int main(int argc, char** argv) {
    bench_scene s;
    uint32_t grids[4] = {1, 4}, grid_count = 2, g, repeats = 1;
    int run_lfem = 1, run_bullet = 1, i;
    double bullet_step;
    memset(&s, 0, sizeof s);
    s.edge = 1.0;
    s.cells = 10;
    s.spacing = 0.5;
    s.young_modulus = 1e5;
    s.poisson_ratio = 0.3;
    s.density = 1000.0;
    s.friction = 0.5;
    s.duration = 1.0;
    s.frame = 1.0 / 240.0;
    /* lfem's alpha gives the cube's lowest mode (a quarter wave through its height, omega_1 =
     * (pi/2) sqrt(E/rho)/L = 15.7 rad/s) the damping ratio that Bullet's default stiffness
     * damping beta = 0.05 s gives it: alpha/(2 omega_1) = beta omega_1/2, alpha = beta
     * omega_1^2 = 12.3 1/s. */
    s.lfem_damping = 12.0;
    s.bullet_damping = 0.05;
    s.bullet_substeps = 1;
    for (i = 1; i < argc; ++i) {
        const char* a = argv[i];
        const char* val = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--bullet-implicit") == 0) {
            s.bullet_implicit = 1;
            continue;
        }
        if (!val) goto usage;
        ++i;
        if (strcmp(a, "--edge") == 0) s.edge = atof(val);
        else if (strcmp(a, "--cells") == 0) s.cells = (uint32_t)atoi(val);
        else if (strcmp(a, "--duration") == 0) s.duration = atof(val);
        else if (strcmp(a, "--lfem-damping") == 0) s.lfem_damping = atof(val);
        else if (strcmp(a, "--bullet-damping") == 0) s.bullet_damping = atof(val);
        else if (strcmp(a, "--bullet-substeps") == 0) s.bullet_substeps = (uint32_t)atoi(val);
        else if (strcmp(a, "--repeats") == 0) repeats = (uint32_t)atoi(val);
        else if (strcmp(a, "--grids") == 0)
            grid_count = (uint32_t)sscanf(val, "%u,%u,%u,%u", &grids[0], &grids[1], &grids[2],
                                          &grids[3]);
        else if (strcmp(a, "--only") == 0)
            run_lfem = strcmp(val, "bullet") != 0, run_bullet = strcmp(val, "lfem") != 0;
        else goto usage;
    }
    if (!(s.edge > 0) || s.cells < 1 || !(s.duration > 0) || s.bullet_substeps < 1 ||
        grid_count < 1 || grid_count > 4 || !(s.lfem_damping >= 0) || !(s.bullet_damping >= 0) ||
        repeats < 1 || repeats > 100)
        goto usage;
    for (g = 0; g < grid_count; ++g)
        if (grids[g] < 1 || grids[g] > 16) goto usage;
    s.drop = 0.05 * s.edge;
    s.bullet_margin = 0.25 * s.edge / s.cells; /* a quarter cell */
    bullet_step = s.frame / s.bullet_substeps;
    if (bench_scene_build_mesh(&s) != 0) return 1;

    printf("lfem %s against Bullet %s (single precision, its default build), one thread each "
           "(lfem-2t: lfem on two).\n"
           "Scene: neo-Hookean cubes of %.3g m edge, %u^3 cells x 6 = %u tets (%u nodes) each, "
           "E = %.3g Pa, nu = %.2f, rho = %.0f kg/m^3, friction %.2f,\n"
           "dropped from %.3g m onto a static floor (lfem: a plane shape; Bullet: a static box), "
           "%.3g s simulated in frames of 1/%.0f s (each engine steps a frame as it needs).\n"
           "lfem: mass damping alpha = %.3g 1/s; \"lfem\" automatic step, \"lfem-fixed\" Bullet's "
           "step. Bullet: %s, step %.6f s, margin %.3g m;\n"
           "\"Bullet-S\" neo-Hookean damping %.3g s (Bullet's default), \"Bullet-M\" drag "
           "%.4f per step (mass damping alpha = %.3g 1/s, as lfem's).\n",
           lfem_version_string(), bench_bullet_version(), s.edge, s.cells, s.tet_count,
           s.node_count, s.young_modulus, s.poisson_ratio, s.density, s.friction, s.drop,
           s.duration, 1.0 / s.frame, s.lfem_damping,
           s.bullet_implicit ? "implicit elastic forces (Newton)" : "explicit elastic forces",
           bullet_step, s.bullet_margin, s.bullet_damping, s.lfem_damping * bullet_step,
           s.lfem_damping);
    printf("%5s  %-10s %6s  %9s  %5s  %9s  %11s  %10s  %10s  %8s  %7s\n", "cubes", "engine", "tets",
           "step s", "steps", "wall s/s", "tet-steps/s", "max pen. m", "rest RMS v", "lowest z",
           "top z");
    for (g = 0; g < grid_count; ++g) {
        bench_result la, lf, l2, bs, bm;
        lfem_profile pa, pf, p2;
        const uint32_t cubes = grids[g] * grids[g];
        memset(&la, 0, sizeof la), memset(&lf, 0, sizeof lf), memset(&l2, 0, sizeof l2);
        memset(&bs, 0, sizeof bs), memset(&bm, 0, sizeof bm);
        s.grid = grids[g];
        if (run_lfem) {
            s.lfem_step = 0.0;
            la = fastest_lfem(&s, &pa, repeats);
            print_row("lfem", cubes, &la);
            s.lfem_step = bullet_step;
            lf = fastest_lfem(&s, &pf, repeats);
            print_row("lfem-fixed", cubes, &lf);
            s.lfem_step = 0.0;
            s.lfem_threads = 2;
            l2 = fastest_lfem(&s, &p2, repeats);
            print_row("lfem-2t", cubes, &l2);
            s.lfem_threads = 0;
        }
        if (run_bullet) {
            const double damping = s.bullet_damping;
            s.bullet_drag = 0.0;
            bs = bench_run_bullet(&s); /* minutes: once */
            print_row("Bullet-S", cubes, &bs);
            s.bullet_damping = 0.0;
            s.bullet_drag = s.lfem_damping * bullet_step;
            bm = fastest_bullet(&s, repeats);
            print_row("Bullet-M", cubes, &bm);
            s.bullet_damping = damping;
        }
        if (run_lfem && run_bullet) {
            print_ratio("lfem/B-S", cubes, &la, &bs);
            print_ratio("lfem/B-M", cubes, &la, &bm);
            print_ratio("fixed/B-S", cubes, &lf, &bs);
            print_ratio("fixed/B-M", cubes, &lf, &bm);
            print_ratio("2t/B-S", cubes, &l2, &bs);
            print_ratio("2t/B-M", cubes, &l2, &bm);
        }
        fflush(stdout);
        if (run_lfem && la.ok) print_profile("lfem", cubes, &pa, &la);
        if (run_lfem && lf.ok) print_profile("lfem-fixed", cubes, &pf, &lf);
        if (run_lfem && l2.ok) print_profile("lfem-2t", cubes, &p2, &l2);
        if (run_lfem && run_bullet) {
            print_target("Bullet-S", cubes, &la, &bs);
            print_target("Bullet-M", cubes, &la, &bm);
            print_target("Bullet-S, lfem on 2 threads", cubes, &l2, &bs);
            print_target("Bullet-M, lfem on 2 threads", cubes, &l2, &bm);
        }
        fflush(stdout);
    }
    bench_scene_free_mesh(&s);
    return 0;
usage:
    fprintf(stderr, "usage: %s [--edge m] [--cells n] [--duration s] [--grids 1,4] "
                    "[--lfem-damping a] [--bullet-damping b] [--bullet-substeps k] "
                    "[--bullet-implicit] [--only lfem|bullet] [--repeats n]\n", argv[0]);
    return 2;
}
