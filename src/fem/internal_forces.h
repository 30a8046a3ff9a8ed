// Internal (elastic) forces of a body, element by element (step 1 of the pipeline).
#pragma once

#include "common/thread_pool.h"
#include "world/body.h"

namespace lfem {

// Overwrites state.elastic with the elastic nodal forces -f_int at state.x and sets
// state.strain_energy. Corotational bodies update their per-tet rotations (warm start);
// "paper" bodies use state.rotation, which must already be fitted to state.x. The element loop
// runs on the pool when one is given; the result is bitwise the same with or without it.
void compute_elastic_forces(const Body& body, BodyState& state, ThreadPool* pool = nullptr);

// Cauchy stress von Mises value of every tet at the state, into out[tet_count].
void compute_von_mises(const Body& body, const BodyState& state, double* out);

}  // namespace lfem
