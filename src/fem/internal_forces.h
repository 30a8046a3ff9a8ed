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

// y = K u with K the small-strain stiffness at the reference state (Hooke's law), element by
// element: the operator of the stable-step estimate. u, y: 3 per node.
void apply_reference_stiffness(const BodyReference& ref, const Lame& lame, const double* u,
                               double* y, ThreadPool* pool = nullptr);

// Cauchy stress von Mises value of every tet at the state, into out[tet_count].
void compute_von_mises(const Body& body, const BodyState& state, double* out);

}  // namespace lfem
