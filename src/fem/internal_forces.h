// Internal (elastic) forces of a body, element by element (step 1 of the pipeline): the
// local finite element method, no global matrix.
#pragma once

#include "common/span.h"
#include "common/thread_pool.h"
#include "fem/element_mesh.h"
#include "fem/material.h"

namespace lfem {

// The deformed state one force computation reads and writes.
struct ElasticState {
    Span<const double> x;          // 3 per node: positions (m)
    Span<double> force;            // 3 per node, out: the elastic nodal forces -f_int (N)
    Span<float> tet_rotation;      // corotational: 4 per tet (w, x, y, z), warm start, updated
    const double* frame = nullptr; // paper: the body's global rotation (w, x, y, z), fitted to x
};

struct ElasticResult {
    double strain_energy = 0;  // J, at x
    double stiffening = 1;     // neo-Hookean: how much stiffer the stiffest tet is than at rest
                               // (>= 1; neo_hookean_tangent.h); 1 for the other models
    uint32_t inverted_tets = 0;  // tets turned inside out at x (volume ratio J = det F <= 0)
    double min_jacobian = 1;     // the smallest J of the body's tets at x
};

// Overwrites state.force with the elastic forces at state.x. Corotational bodies update their
// per-tet rotations (warm start); "paper" bodies use state.frame. The element loop runs on the
// pool when one is given; the result is bitwise the same with or without it.
ElasticResult compute_elastic_forces(const ElementMesh& mesh, const Material& material,
                                     const ElasticState& state, ThreadPool* pool = nullptr);

// y = K u with K the small-strain stiffness at the reference state (Hooke's law), element by
// element: the operator of the stable-step estimate. u, y: 3 per node.
void apply_reference_stiffness(const ElementMesh& mesh, const Lame& lame, const double* u,
                               double* y, ThreadPool* pool = nullptr);

// Von Mises value of the Cauchy stress of every tet at positions x, into out[tet_count];
// tet_rotation and frame as in ElasticState (read only; nullable for the other models).
void compute_von_mises(const ElementMesh& mesh, const Material& material, const double* x,
                       const float* tet_rotation, const double* frame, double* out);

}  // namespace lfem
