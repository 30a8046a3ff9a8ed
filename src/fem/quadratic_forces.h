// Internal (elastic) forces of a body of 10-node tets (fem/quadratic_tet.h), element by element:
// the quadratic counterparts of the kernels of internal_forces.h, which dispatches a quadratic
// mesh here. The same contracts: forces overwritten, strain energy and stiffening returned,
// bitwise the same result for any thread count.
#pragma once

#include "common/quadratic_tet_nodes.h"
#include "common/thread_pool.h"
#include "fem/element_mesh.h"
#include "fem/internal_forces.h"
#include "fem/material.h"

namespace lfem {

// Every model at every quadrature point: linear (Hooke's law of the displacement gradient),
// paper (Hooke's law in the body's frame state.frame), corotational (the polar rotation of F at
// each quadrature point, warm-started from state.tet_rotation, 4 per quadrature point: 16 per
// tet), neo-Hookean (with the stiffening of its stiffest quadrature point).
ElasticResult compute_quadratic_elastic_forces(const ElementMesh& mesh, const Material& material,
                                               const ElasticState& state, ThreadPool* pool);

// y = K u, the small-strain stiffness at the reference state, element by element.
void apply_quadratic_reference_stiffness(const ElementMesh& mesh, const Lame& lame, const double* u,
                                         double* y, ThreadPool* pool);

// Von Mises value of each tet's mean Cauchy stress (over its quadrature points, weighted by
// their volumes) at positions x, into out[tet_count]; tet_rotation and frame as above.
void compute_quadratic_von_mises(const ElementMesh& mesh, const Material& material, const double* x,
                                 const float* tet_rotation, const double* frame, double* out);

}  // namespace lfem
