// What the element loops (4-node tets: internal_forces.cpp; 10-node: quadratic_forces.cpp)
// report besides their forces: each block of tets gives one BlockResult, the blocks' results
// are summed in block order (so the sum is the same for any thread count), and the sum becomes
// the body's ElasticResult.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "common/block_array.h"
#include "fem/internal_forces.h"
#include "fem/neo_hookean_tangent.h"

namespace lfem {

struct BlockResult {
    double energy = 0;      // J, strain energy
    double tangent = 0;     // the largest tangent estimate (kTangent) or barrier stiffness (kBarrier)
    uint32_t inverted = 0;  // tets with J = det F <= 0 (a 10-node tet: at one of its quadrature points)
    double min_J = HUGE_VAL;  // the smallest J (a 10-node tet's: at its quadrature points)
};

// An element loop's block results: a 6000-tet body has about 24 blocks, a small cube one.
using BlockResults = BlockArray<BlockResult, 16>;

// The blocks' results summed in block order.
inline BlockResult sum_blocks(const BlockResults& per_block) {
    BlockResult total;
    for (uint32_t b = 0; b < per_block.size(); ++b) {
        const BlockResult& r = per_block[b];
        total.energy += r.energy;
        total.tangent = std::max(total.tangent, r.tangent);
        total.inverted += r.inverted;
        total.min_J = std::min(total.min_J, r.min_J);
    }
    return total;
}

// The body's result from the sum; stiffening 1 (the caller sets it from total.tangent for the
// models that have one).
inline ElasticResult elastic_result(const BlockResult& total) {
    ElasticResult out;
    out.strain_energy = total.energy;
    out.inverted_tets = total.inverted;
    out.min_jacobian = total.min_J < HUGE_VAL ? total.min_J : 1.0;  // (no tets: nothing crushed)
    out.stiffening = 1.0;
    return out;
}

// The stiffening rule of every element, for the stable step: how much stiffer the body's
// stiffest tet (a 10-node tet's stiffest point) is than at rest, from the loop's largest
// `tangent`. The neo-Hookean model (kTangent): its tangent over its value at rest, at least 1.
// The others (kBarrier): 1 + the volume barrier's stiffness over Hooke's largest tangent
// eigenvalue, which is the neo-Hookean's at rest (3 lambda + 2 mu). mu and lambda_mu = lambda +
// mu are the neo-Hookean's parameters (neo_hookean_tangent.h).
template <class Model>
double stiffening(double tangent, double mu, double lambda_mu) {
    const double at_rest = neo_hookean_tangent_estimate(1, 0, 0, 0, 1, 0, 0, 0, 1, mu, lambda_mu);
    if constexpr (Model::kTangent) return std::max(1.0, tangent / at_rest);
    if constexpr (Model::kBarrier) return 1.0 + tangent / at_rest;
    return 1.0;
}

}  // namespace lfem
