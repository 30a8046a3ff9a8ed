// The stable step of central differences, h < 2 / omega_max, with omega_max^2 the largest
// eigenvalue of M^-1 K (lumped mass, stiffness at the reference state). K is never formed: it
// is applied element by element.
#pragma once

#include "common/thread_pool.h"
#include "fem/element_mesh.h"
#include "fem/material.h"

namespace lfem {

struct StableStepEstimate {
    double omega_max = 0;       // rad/s, the value used: min(Lanczos estimate * (1 + margin),
                                // Gershgorin bound)
    double omega_power = 0;     // rad/s, largest Ritz value of the Lanczos iteration (lower bound)
    double omega_gershgorin = 0;// rad/s, proven upper bound from nodal row sums of |K_e|
    int iterations = 0;         // Lanczos steps (products with the operator)
};

// Largest natural frequency of a body from its reference data (X, masses, tets, Dm_inv,
// volumes, colouring) and elastic constants; the operator runs on the pool when one is given.
StableStepEstimate estimate_stable_step(const ElementMesh& mesh, const Lame& lame,
                                        ThreadPool* pool = nullptr);

// Mass scaling to a requested step (the explicit codes' /DT/NODA/CST of OpenRadioss, DT2MS of
// LS-DYNA): every tet whose own highest frequency, omega_e^2 = lambda_max(K_e) / (rho V / 4)
// with its lumped share rho V / 4 at each node, exceeds omega_target^2 has its density raised
// by the ratio, the extra mass added to its nodes (`added`, per node, kg, added to what it
// holds). The assembled omega_max^2 is at most the largest element's (the element eigenvalue
// inequality, for a mass assembled from the elements' lumped shares), so omega_max <=
// omega_target: a step 2 / omega_target is stable. Returns the total added (kg).
double add_scaling_mass(const ElementMesh& mesh, const Lame& lame, double density, double omega_target,
                        double* added);

// Mass scaling as the stable step sees it: the element inequality above is conservative (a tet
// alone holds a quarter of its mass at each node, a node of a mesh the shares of all its tets:
// on the box builder's meshes it overestimates omega_max^2 about 2.2 times), so the element
// target is raised as far as the estimate of the whole body (Lanczos, as estimate_stable_step)
// stays at most omega_target; a few estimates, starting from the proven target. `mesh.mass`
// holds the physical lumped masses; `scaled` (per node) receives them with the added mass, and
// the estimate of the scaled body is returned, its omega_max at most omega_target.
StableStepEstimate scale_masses_for_step(const ElementMesh& mesh, const Lame& lame, double density,
                                         double omega_target, double* scaled, ThreadPool* pool = nullptr);

}  // namespace lfem
