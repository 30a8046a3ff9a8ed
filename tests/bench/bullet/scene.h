/* The scene of the side-by-side benchmark against Bullet (issue 7), the same for both engines:
 * soft cubes of cells^3 hexahedral cells split into 6 tets each (the tet mesh of
 * lfem_mesh_create_box, handed to both), dropped from rest a small height above a static floor
 * whose top is the plane z = 0, gravity -z. One cube, or a grid of n x n cubes set apart so that
 * they never touch each other: the floor is the only contact.
 *
 * Shared by the C driver and the C++ Bullet side, so plain C99. */
#ifndef LFEM_BENCH_BULLET_SCENE_H
#define LFEM_BENCH_BULLET_SCENE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bench_scene {
    double edge;           /* m, edge of a cube */
    uint32_t cells;        /* cells along an edge (6 tets per cell) */
    uint32_t grid;         /* grid x grid cubes */
    double spacing;        /* m, gap between neighbouring cubes */
    double drop;           /* m, gap between a cube's bottom and the floor at the start */
    double young_modulus;  /* Pa */
    double poisson_ratio;
    double density;        /* kg/m^3 */
    double friction;       /* Coulomb coefficient of the cube/floor pair */
    double duration;       /* s, simulated time */
    double frame;          /* s, the interval between measurements (each engine steps it) */
    /* Engine-specific settings (each engine's own kind of damping and step). */
    double lfem_damping;   /* 1/s, lfem's mass-proportional damping alpha */
    double lfem_step;      /* s, lfem's fixed sub-step; 0 = automatic (0.9 x stable limit) */
    uint32_t lfem_threads; /* lfem_world_def.thread_count; 0 = the default (1) */
    double bullet_damping; /* s, the damping argument of btDeformableNeoHookeanForce (Bullet's
                              default 0.05: a stiffness-proportional damping) */
    double bullet_drag;    /* btSoftBody::Config::drag: node velocities scaled by (1 - drag)
                              every step, a mass-proportional damping alpha = drag / step */
    uint32_t bullet_substeps; /* Bullet steps per frame (its step = frame / bullet_substeps) */
    int bullet_implicit;   /* btDeformableMultiBodyDynamicsWorld::setImplicit */
    double bullet_margin;  /* m, the soft body's collision margin */
    /* One cube's mesh, bottom corner at the origin (filled by bench_scene_build_mesh). */
    uint32_t node_count, tet_count;
    double* positions;     /* 3 per node */
    uint32_t* tets;        /* 4 per tet */
    double* node_mass;     /* kg, lumped: rho V / 4 from every tet a node belongs to */
} bench_scene;

/* Build the cube's mesh and lumped masses; 0 on success, -1 (with a message) otherwise. */
int bench_scene_build_mesh(bench_scene* scene);
void bench_scene_free_mesh(bench_scene* scene);

/* Where cube k (0 <= k < grid^2) starts: the offset added to the mesh positions. */
void bench_scene_cube_offset(const bench_scene* scene, uint32_t k, double offset[3]);

/* What one engine's run gives back. Wall time counts the step calls only (read-backs for the
 * measurements below are outside it). */
typedef struct bench_result {
    int ok;
    double wall_seconds;       /* s, spent in the engine's step calls */
    double simulated_seconds;  /* s */
    double steps;              /* integration steps taken (lfem: sub-steps) */
    double step_min, step_max; /* s, smallest and largest integration step taken */
    double tets;               /* total tets in the scene */
    double stable_limit;       /* s, lfem only: the smallest stable limit it reported (its
                                  automatic step is 0.9 x that, or the frame if smaller) */
    double max_penetration;    /* m, largest depth of a node below the floor, over every frame
                                  (lfem: also its own contact statistic) */
    double rest_rms_velocity;  /* m/s, RMS node speed over the frames of the last 10 % */
    double lowest_final;       /* m, lowest node z at the end */
    double top_final;          /* m, highest node z at the end: with lowest_final, a check
                                  that both engines settled to the same sagged shape */
} bench_result;

/* Accumulates the per-frame measurements of a run. */
typedef struct bench_meter {
    double max_penetration;
    double rest_sum_v2;   /* sum over rest frames and nodes of |v|^2 */
    double rest_samples;  /* node-frames summed */
} bench_meter;

/* One frame's node data (positions and velocities, 3 doubles per node); rest = 1 when the frame
 * lies in the last 10 % of the run. */
void bench_meter_add(bench_meter* meter, const double* x, const double* v, uint32_t nodes,
                     int rest);

#ifdef __cplusplus
}
#endif

#endif
