/* BASELINE, not lfem's method: penalty contact between two facing flat bar ends, built on the
 * public API only, so that the advantage of lfem's Lagrange multipliers is measured rather
 * than claimed (issue 4). The bars are put in collision filter groups that do not collide;
 * before each step every node of the slave face that lies behind the master face gets a spring
 * force k_i d_i (d_i its penetration, k_i its share of the total stiffness by tributary area),
 * and the master face's nodes get the opposite, split by the barycentric weights of the point
 * it touches (lfem_body_set_node_forces). That is the classic explicit node-to-surface penalty
 * method: the force of step n comes from the positions x^n.
 *
 * Simplifications that hold for the two-bar impact at nu = 0 (and are stated, not hidden): the
 * faces meet head on, so the normal is fixed to the master face's +x and each slave node keeps
 * the master triangle under its reference (y, z) (no lateral motion without Poisson coupling). */
#ifndef LFEM_BENCH_PENALTY_BASELINE_H
#define LFEM_BENCH_PENALTY_BASELINE_H

#include "lfem.h"

typedef struct penalty_contact penalty_contact; /* opaque */

/* Pairs the slave face (the slave body's boundary triangles whose nodes all lie at
 * x = slave_face_x) with the master face (at x = master_face_x, facing +x, towards the slave).
 * total_stiffness in N/m is shared among the slave face nodes by tributary area. Call before
 * the first step (positions are the reference ones). Returns 0, or -1 after printing why. */
int penalty_contact_create(lfem_world* world, lfem_body master, double master_face_x,
                           lfem_body slave, double slave_face_x, double total_stiffness,
                           penalty_contact** out);

/* Sets the spring forces of the current positions on both faces' nodes, for the next step.
 * *force: the total force on the slave along +x (N); *penetration: the deepest slave node (m,
 * 0 when none touches). Returns 0, or -1 after printing why. */
int penalty_contact_apply(penalty_contact* contact, lfem_world* world, double* force,
                          double* penetration);

/* Nullable. */
void penalty_contact_destroy(penalty_contact* contact);

#endif
