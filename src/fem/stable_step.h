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

}  // namespace lfem
