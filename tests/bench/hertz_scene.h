/* Hertz impact: an elastic sphere hits a rigid plane head on. Hertz's theory of impact (the
 * quasi-static contact of a sphere on a half-space, integrated over the approach) gives, from
 * E, nu, rho, R and v, the largest force and the duration of the contact. The sphere is a Gmsh
 * mesh graded towards the point that touches (tests/bench/data/hertz_sphere.geo); the plane is
 * a rigid plane shape. The theory treats the contact zone as a half-space: its error grows with
 * the contact radius a against R (a / R = 0.043 at 1 m/s, 0.11 at 10 m/s here). */
#ifndef LFEM_BENCH_HERTZ_SCENE_H
#define LFEM_BENCH_HERTZ_SCENE_H

#include <stdint.h>

#include "lfem.h"

typedef struct hertz_exact {
    double effective_modulus; /* Pa, E* = E / (1 - nu^2) against a rigid plane */
    double approach;          /* m, the largest approach delta_max = (15 m v^2 / (16 E* R^1/2))^2/5 */
    double force;             /* N, the peak force (4/3) E* R^1/2 delta_max^3/2 */
    double duration;          /* s, the contact time 2 delta_max / v * int_0^1 dx / sqrt(1 - x^5/2) */
} hertz_exact;

/* The closed forms for a sphere of mass m (kg), radius R (m), Young's modulus E (Pa), Poisson's
 * ratio nu, hitting at speed v (m/s). */
hertz_exact hertz_exact_solution(double m, double R, double E, double nu, double v);

typedef struct hertz_config {
    const char* mesh_path;  /* the sphere's Gmsh file, centred at the origin, of radius
                               hertz_radius(): 4-node tets, or 10-node ones (type 11, whose
                               boundary mid-edge nodes Gmsh puts on the sphere) */
    lfem_model model;
    double step_ratio;      /* fixed step as a fraction of the stable limit */
    double speed;           /* m/s, the impact speed */
    int composite;          /* 1: 10-node tets as the composite element (composite_tets) */
} hertz_config;

typedef struct hertz_result {
    uint32_t tets, nodes, nodes_per_tet;
    double step;            /* s */
    uint64_t steps;
    double mass;            /* kg, the lumped mass of the mesh */
    double peak_force;      /* N, the largest summed contact force of a step */
    double duration;        /* s, first to last step with a contact force */
    double max_penetration; /* m, largest over the steps (the solver's stats) */
    hertz_exact exact;      /* for this mesh's mass */
    double wall;            /* s, the whole run: loading the mesh, set-up, stepping */
} hertz_result;

double hertz_radius(void);  /* m */

/* Returns 0, or -1 after printing why. */
int hertz_run(const hertz_config* config, hertz_result* result);

#endif
