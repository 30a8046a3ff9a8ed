// A bounding volume hierarchy of a body's boundary triangles: a binary tree of axis-aligned
// boxes, leaves of a few triangles. A static body's tree is built once, when its mesh is added;
// a moving body's is refitted (new boxes, same tree) when contact looks for candidates again.
// A query visits the triangles whose box overlaps a box: O(log T + k), whatever the size of
// the triangles or of the terrain.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/broad_phase.h"

namespace lfem {

// The box of the triangle with node indices tri[0..2] at positions x (3 per node).
inline Aabb triangle_box(const double* x, const uint32_t* tri) {
    Aabb b;
    for (int k = 0; k < 3; ++k) {
        const double a = x[3 * tri[0] + k], c = x[3 * tri[1] + k], d = x[3 * tri[2] + k];
        b.lo[k] = a < c ? (a < d ? a : d) : (c < d ? c : d);
        b.hi[k] = a > c ? (a > d ? a : d) : (c > d ? c : d);
    }
    return b;
}

class TriangleBvh {
public:
    // The tree over `triangle_count` triangles (3 node indices each into x, 3 doubles per node).
    // Split at the median of the centroids along the longest axis of their box: deterministic,
    // O(T log T).
    void build(const double* x, const uint32_t* triangles, uint32_t triangle_count);
    // The boxes again, bottom up, for the same triangles at new positions x. O(T).
    void refit(const double* x, const uint32_t* triangles);
    bool empty() const { return nodes_.empty(); }
    // The box of every triangle (the root's box); only for a non-empty tree.
    const Aabb& bounds() const { return nodes_[0].box; }
    // visit(t), in no particular order, for every triangle t (3 node indices each in
    // `triangles`) whose box at the positions x overlaps `box`. The tree's own boxes come from
    // the positions it was built or refitted on, which may lie up to `drift` per axis from x.
    template <class Visit>
    void query(const Aabb& box, const double* x, const uint32_t* triangles, double drift, const Visit& visit) const {
        if (nodes_.empty()) return;
        Aabb reach = box;
        for (int k = 0; k < 3; ++k) reach.lo[k] -= drift, reach.hi[k] += drift;
        uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = nodes_[stack[--top]];
            if (!overlaps(n.box, reach)) continue;
            if (n.count > 0) {
                for (uint32_t i = n.first; i < n.first + n.count; ++i)
                    if (overlaps(triangle_box(x, &triangles[3 * std::size_t(order_[i])]), box)) visit(order_[i]);
            } else {
                stack[top++] = n.first;
                stack[top++] = n.first + 1;
            }
        }
    }

private:
    struct Node {
        Aabb box;
        uint32_t first = 0;  // leaf: first of order_; inner node: its first child (the second follows)
        uint32_t count = 0;  // leaf: its triangles; 0 for an inner node
    };
    uint32_t build_node(uint32_t node, uint32_t first, uint32_t count, const std::vector<double>& centroid);
    std::vector<Node> nodes_;
    std::vector<uint32_t> order_;  // triangle indices, leaf by leaf
};

}  // namespace lfem
