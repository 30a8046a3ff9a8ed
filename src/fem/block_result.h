// What the element loops (4-node tets: internal_forces.cpp; 10-node: quadratic_forces.cpp)
// report besides their forces: each block of tets gives one BlockResult, the blocks' results
// are summed in block order (so the sum is the same for any thread count), and the sum becomes
// the body's ElasticResult.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fem/internal_forces.h"

namespace lfem {

struct BlockResult {
    double energy = 0;      // J, strain energy
    double tangent = 0;     // the largest tangent estimate (kTangent) or barrier stiffness (kBarrier)
    uint32_t inverted = 0;  // tets with J = det F <= 0 (a 10-node tet: at one of its quadrature points)
    double min_J = HUGE_VAL;  // the smallest J (a 10-node tet's: at its quadrature points)
};

// One result per block of an element loop, written by the blocks (each its own) and summed in
// block order. A small body's few blocks are kept inline: no allocation per body and sub-step
// (a scene of 32 small cubes made one per cube and sub-step).
class BlockResults {
public:
    explicit BlockResults(uint32_t count) : count_(count) {
        if (count > kInline) heap_.resize(count);
    }
    BlockResult& operator[](uint32_t b) { return count_ > kInline ? heap_[b] : inline_[b]; }
    // The blocks' results summed in block order.
    BlockResult sum() const {
        const BlockResult* r = count_ > kInline ? heap_.data() : inline_;
        BlockResult total;
        for (uint32_t b = 0; b < count_; ++b) {
            total.energy += r[b].energy;
            total.tangent = std::max(total.tangent, r[b].tangent);
            total.inverted += r[b].inverted;
            total.min_J = std::min(total.min_J, r[b].min_J);
        }
        return total;
    }

private:
    static constexpr uint32_t kInline = 16;
    uint32_t count_;
    BlockResult inline_[kInline];
    std::vector<BlockResult> heap_;
};

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

}  // namespace lfem
