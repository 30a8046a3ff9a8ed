/* The other validation problems of src/DESIGN.md section 11 as timed benchmark runs, each set up as
 * its test in tests/physics does it: a free spinning body (test_spinning_body.cpp), a
 * cantilever under gravity (test_cantilever.cpp) and a block sliding down an incline
 * (test_friction.cpp). Each returns its errors against the closed form and its wall time. */
#ifndef LFEM_BENCH_VALIDATION_CASES_H
#define LFEM_BENCH_VALIDATION_CASES_H

#include <stdint.h>

#include "lfem.h"

typedef struct case_config {
    lfem_model model;
    uint32_t cells[3];  /* hexahedra of the body along x, y, z */
    double safety;      /* step as a fraction of the elastic stable limit (step_safety) */
    double duration;    /* s of simulated time; 0 = the case's own (see each function) */
    int quadratic;      /* 1: the body of 10-node tets (lfem_mesh_make_quadratic); 2: the same
                           as the composite element (composite_tets) */
    double mass_scaling_step; /* s, lfem_world_def.mass_scaling_step (0: no mass scaling);
                                 the incline only */
} case_config;

typedef struct case_result {
    double error;        /* the case's main relative error against its closed form */
    double second_error; /* spin: kinetic energy change; incline: penetration (m); else 0 */
    double third_error;  /* spin: relative volume change, else 0 */
    uint32_t tets;
    uint32_t nodes;
    uint64_t steps;
    double step;         /* s */
    double wall;         /* s */
    double added_mass_share; /* what mass scaling added over the body's mass with it */
} case_result;

/* A free undamped 0.2 x 0.1 x 0.05 m box (E 1e7, nu 0.3) spinning at one turn a second about
 * its major axis, for one turn by default. error: |L - L0| / |L0| (angular momentum is
 * conserved exactly); second: kinetic energy change (only the centrifugal strain, ~1e-4, may
 * be exchanged); third: volume change (centrifugal dilatation, ~4e-5). */
int spin_run(const case_config* config, case_result* result);

/* A 0.5 x 0.05 x 0.05 m cantilever (E 6e8, nu 0, rho 1000) clamped at x = 0, critically damped
 * for its first bending mode, settled for 10 / omega1 by default. error: tip deflection against
 * Euler-Bernoulli q L^4 / (8 E I). */
int cantilever_run(const case_config* config, case_result* result);

/* A 0.1 m cube (E 1e6) on a static floor, gravity tilted by 30 degrees, mu = 0.3: it slides at
 * g (sin 30 - mu cos 30). error: the mean acceleration from 0.05 s to 0.45 s (default) against
 * that. */
int incline_run(const case_config* config, case_result* result);

#endif
