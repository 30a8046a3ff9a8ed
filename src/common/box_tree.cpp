#include "common/box_tree.h"

#include <algorithm>
#include <cmath>

namespace lfem {
namespace {

// Items per leaf: a few box tests are cheaper than a deeper tree.
constexpr uint32_t kLeafSize = 4;

}  // namespace

void BoxTree::build(const double* centroid, uint32_t count) {
    nodes_.clear();
    order_.resize(count);
    if (count == 0) return;
    for (uint32_t t = 0; t < count; ++t) order_[t] = t;
    nodes_.reserve(2 * (count / kLeafSize + 1));
    nodes_.emplace_back();
    build_node(0, 0, count, centroid);
}

// Splits order_[first, first + count) under `node`; returns the tree's depth below it. The
// children of an inner node are appended side by side, so a node needs one index.
uint32_t BoxTree::build_node(uint32_t node, uint32_t first, uint32_t count, const double* centroid) {
    if (count <= kLeafSize) {
        nodes_[node].first = first;
        nodes_[node].count = count;
        return 1;
    }
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = first; i < first + count; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], centroid[3 * std::size_t(order_[i]) + k]);
            hi[k] = std::max(hi[k], centroid[3 * std::size_t(order_[i]) + k]);
        }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    const uint32_t half = count / 2;
    // Ties broken by item index, so the tree depends on nothing but the input.
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](uint32_t a, uint32_t b) {
                         const double ca = centroid[3 * std::size_t(a) + axis], cb = centroid[3 * std::size_t(b) + axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    const uint32_t children = uint32_t(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[node].first = children;
    nodes_[node].count = 0;
    const uint32_t left = build_node(children, first, half, centroid);
    const uint32_t right = build_node(children + 1, first + half, count - half, centroid);
    return 1 + std::max(left, right);
}

}  // namespace lfem
