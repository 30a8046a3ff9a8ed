/* The paper's two-bar impact (Fig. 3) as a benchmark run: build the bars, step them with a
 * fixed step, and measure the contact force history against the 1-D wave solution
 * (src/DESIGN.md section 4). Contact is either lfem's Lagrange multipliers or the penalty baseline
 * of penalty_baseline.h. */
#ifndef LFEM_BENCH_TWO_BAR_SCENE_H
#define LFEM_BENCH_TWO_BAR_SCENE_H

#include <stdint.h>

#include "lfem.h"

/* The 1-D solution at nu = 0: c = sqrt(E/rho); contact starts when the gap has closed and lasts
 * 2L/c; the plateau force brings the faces to a common velocity, F = Z1 Z2/(Z1 + Z2) 2v with
 * Z = rho c A; impulse F 2L/c; final velocities from each bar's momentum balance. */
typedef struct two_bar_exact {
    double wave_speed; /* m/s, 5134.85 */
    double start;      /* s, 24.73 us */
    double duration;   /* s, 98.93 us */
    double force;      /* N, 125.08 kN */
    double impulse;    /* N s, 12.375 */
    double v1, v2;     /* m/s, -4.491 and +5.781 */
} two_bar_exact;

two_bar_exact two_bar_exact_solution(void);

typedef struct two_bar_config {
    lfem_model model;
    uint32_t cells[3];      /* hexahedra per bar along x (the bar) and across (y, z) */
    double nu;              /* Poisson's ratio; 0 for the 1-D limit */
    double step_ratio;      /* fixed step as a fraction of the elastic stable limit
                               (lfem_world_get_stable_step); above 1 only to find where a
                               contact model blows up */
    double penalty_factor;  /* 0: lfem's Lagrange multipliers. > 0: the penalty baseline with
                               springs of total stiffness penalty_factor * E A2 / (L / cells[0]).
                               < 0: no contact at all (the bars pass through each other): the
                               bars' own critical step, for comparison */
    double end_time;        /* s, 200 us: contact is over by ~124 us */
    int quadratic;          /* 1: 10-node tets (lfem_mesh_make_quadratic), 2: the same as the
                               composite element (composite_tets), 0: 4-node tets */
    double mass_scaling_step; /* s, lfem_world_def.mass_scaling_step (0: no mass scaling) */
} two_bar_config;

typedef struct two_bar_result {
    int stable;             /* 1 when the run finished without blowing up */
    double step;            /* s, the fixed step used */
    double elastic_step;    /* s, the elastic stable limit of the bars */
    uint64_t steps;
    uint32_t tets;          /* both bars */
    uint32_t nodes;         /* both bars */
    double impulse;         /* N s, contact force on bar 2 summed over the steps */
    double plateau;         /* N, mean force from 40 to 110 us */
    double peak_force;      /* N, largest force of one step */
    double duration;        /* s, first to last step with a compressive force */
    double v1, v2;          /* m/s, final mean velocities (momentum / mass) */
    double max_penetration; /* m, largest over the steps: the solver's stats for multipliers, the
                               deepest spring for the penalty baseline */
    double energy_change;   /* relative change of kinetic + strain energy, start to end */
    double added_mass;      /* kg, what mass scaling added to both bars */
    double mass;            /* kg, both bars with it */
    double wall;            /* s, wall time of the whole run: set-up, stable step, stepping */
} two_bar_result;

/* Runs one impact. Returns 0 (also for a run that blew up: result->stable is then 0), or -1
 * after printing why when an lfem call failed for another reason. */
int two_bar_run(const two_bar_config* config, two_bar_result* result);

#endif
