// What the element kernels compute on: a body's reference mesh, fixed once the mesh is added
// (reference nodes, tets, the inverse reference edge matrices, volumes, lumped masses and the
// colouring of the parallel element loop), borrowed from whoever owns it. The deformed state
// comes separately, as spans, to each kernel. Its tets are linear (4 nodes) or quadratic (10
// nodes, fem/quadratic_tet.h), all of one kind.
#pragma once

#include <cstdint>

#include "common/span.h"
#include "fem/element_colouring.h"

namespace lfem {

struct ElementMesh {
    Span<const double> X;          // 3 per node: reference positions (m)
    Span<const uint32_t> tets;     // nodes_per_tet node indices per tet
    Span<const double> Dm_inv;     // 9 per tet (linear): inverse reference edge matrix; 9 per
                                   // quadrature point (quadratic): inverse reference Jacobian;
                                   // column-major
    Span<const double> volume;     // per tet: reference volume (m^3)
    Span<const double> qp_volume;  // quadratic: 4 per tet, the volume w_q det J_q of each
                                   // quadrature point (m^3); empty for linear tets
    Span<const double> mass;       // per node: lumped mass (kg)
    const ElementColouring* colouring = nullptr;  // blocks of tets for the parallel loop
    uint32_t nodes_per_tet = 4;    // 4 (linear) or 10 (quadratic)
    bool composite = false;        // quadratic: the composite element's strain (composite_tet.h)

    uint32_t node_count() const { return uint32_t(X.size() / 3); }
    uint32_t tet_count() const { return uint32_t(volume.size()); }
};

}  // namespace lfem
