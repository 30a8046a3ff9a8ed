#include "contact/triangle_bvh.h"

#include <algorithm>
#include <cmath>

namespace lfem {
namespace {

// Triangles per leaf: a few box tests are cheaper than a deeper tree.
constexpr uint32_t kLeafSize = 4;

void join(Aabb& a, const Aabb& b) {
    for (int k = 0; k < 3; ++k) a.lo[k] = std::min(a.lo[k], b.lo[k]), a.hi[k] = std::max(a.hi[k], b.hi[k]);
}

}  // namespace

void TriangleBvh::build(const double* x, const uint32_t* triangles, uint32_t triangle_count) {
    nodes_.clear();
    order_.resize(triangle_count);
    if (triangle_count == 0) return;
    std::vector<double> centroid(3 * std::size_t(triangle_count));
    for (uint32_t t = 0; t < triangle_count; ++t) {
        order_[t] = t;
        for (int k = 0; k < 3; ++k) {
            const uint32_t* tri = &triangles[3 * std::size_t(t)];
            centroid[3 * std::size_t(t) + k] = (x[3 * tri[0] + k] + x[3 * tri[1] + k] + x[3 * tri[2] + k]) / 3.0;
        }
    }
    nodes_.reserve(2 * (triangle_count / kLeafSize + 1));
    nodes_.emplace_back();
    build_node(0, 0, triangle_count, centroid);
    refit(x, triangles);
}

// Splits order_[first, first + count) under `node`; returns the tree's depth below it. The
// children of an inner node are appended side by side, so a node needs one index.
uint32_t TriangleBvh::build_node(uint32_t node, uint32_t first, uint32_t count, const std::vector<double>& centroid) {
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
    // Ties broken by triangle index, so the tree depends on nothing but the input.
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

void TriangleBvh::refit(const double* x, const uint32_t* triangles) {
    // Children always come after their parent: one pass from the back sets every box.
    for (std::size_t i = nodes_.size(); i-- > 0;) {
        Node& n = nodes_[i];
        if (n.count > 0) {
            n.box = triangle_box(x, &triangles[3 * std::size_t(order_[n.first])]);
            for (uint32_t j = n.first + 1; j < n.first + n.count; ++j)
                join(n.box, triangle_box(x, &triangles[3 * std::size_t(order_[j])]));
        } else {
            n.box = nodes_[n.first].box;
            join(n.box, nodes_[n.first + 1].box);
        }
    }
}

}  // namespace lfem
