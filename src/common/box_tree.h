// A bounding volume hierarchy of items given by their boxes: a binary tree of axis-aligned
// boxes, leaves of a few items. Contact's triangle trees (contact/triangle_bvh.h), the skins'
// search for the tet around a vertex and the queries' tree of bodies are each one of these.
// The structure comes from the items' centroids (median splits, deterministic), the boxes from
// the items' boxes; a refit takes new boxes for the same structure. A box query visits the
// items of the leaves it overlaps, O(log n + k); a ray visits the leaves it meets nearest
// first, so a closest-hit search stops as soon as nothing nearer can come.
#pragma once

#include <cstdint>
#include <vector>

#include "common/box.h"

namespace lfem {

class BoxTree {
public:
    // The structure over `count` items from their centroids (3 per item): split at the median
    // along the longest axis of their box, ties by item index. O(n log n). The boxes are left
    // for refit().
    void build(const double* centroid, uint32_t count);
    // The boxes again, bottom up: box_of(item) -> Aabb for every item. O(n).
    template <class BoxOf>
    void refit(const BoxOf& box_of) {
        // Children always come after their parent: one pass from the back sets every box.
        for (std::size_t i = nodes_.size(); i-- > 0;) {
            Node& n = nodes_[i];
            if (n.count > 0) {
                n.box = box_of(order_[n.first]);
                for (uint32_t j = n.first + 1; j < n.first + n.count; ++j) join(n.box, box_of(order_[j]));
            } else {
                n.box = nodes_[n.first].box;
                join(n.box, nodes_[n.first + 1].box);
            }
        }
    }
    bool empty() const { return nodes_.empty(); }
    // The box of every item (the root's box); only for a non-empty tree.
    const Aabb& bounds() const { return nodes_[0].box; }

    // visit(item), in no particular order, for every item of a leaf whose box overlaps `box`
    // (the caller tests the item itself).
    template <class Visit>
    void query(const Aabb& box, const Visit& visit) const {
        if (nodes_.empty()) return;
        uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = nodes_[stack[--top]];
            if (!overlaps(n.box, box)) continue;
            if (n.count > 0) {
                for (uint32_t i = n.first; i < n.first + n.count; ++i) visit(order_[i]);
            } else {
                stack[top++] = n.first;
                stack[top++] = n.first + 1;
            }
        }
    }

    // The ray origin + t direction for t in [0, t_max]: t_max = visit(item, t_max) for every
    // item of a leaf whose box the ray meets before the current t_max, the nearest boxes
    // first. visit returns the bound for what follows (the same t_max to see everything, the
    // distance of a hit found to look only for nearer ones). Every box it passes is counted in
    // *boxes (nullable). With grow > 0 every box is taken grown by it on every side (a sphere of
    // that radius swept along the ray meets what is in it only inside those).
    template <class Visit>
    void cast(const RaySlabs& ray, double t_max, const Visit& visit, uint64_t* boxes = nullptr,
              double grow = 0.0) const {
        if (nodes_.empty()) return;
        struct Entry {
            uint32_t node;
            double t;
        };
        Entry stack[128];
        int top = 0;
        double t0, t1;
        auto box = [&](uint32_t node) { return grow > 0.0 ? grown(nodes_[node].box, grow) : nodes_[node].box; };
        if (!ray_interval(box(0), ray, 0.0, t_max, t0, t1)) return;
        stack[top++] = {0, t0};
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.t > t_max) continue;
            const Node& n = nodes_[e.node];
            if (boxes) *boxes += 1;
            if (n.count > 0) {
                for (uint32_t i = n.first; i < n.first + n.count; ++i) t_max = visit(order_[i], t_max);
                continue;
            }
            double ta = 0, tb = 0, exit;
            const bool a = ray_interval(box(n.first), ray, 0.0, t_max, ta, exit);
            const bool b = ray_interval(box(n.first + 1), ray, 0.0, t_max, tb, exit);
            // The nearer child goes on top, so it is taken first.
            if (a && b) {
                const bool a_first = ta <= tb;
                stack[top++] = {a_first ? n.first + 1 : n.first, a_first ? tb : ta};
                stack[top++] = {a_first ? n.first : n.first + 1, a_first ? ta : tb};
            } else if (a || b) {
                stack[top++] = {a ? n.first : n.first + 1, a ? ta : tb};
            }
        }
    }

private:
    struct Node {
        Aabb box;
        uint32_t first = 0;  // leaf: first of order_; inner node: its first child (the second follows)
        uint32_t count = 0;  // leaf: its items; 0 for an inner node
    };
    uint32_t build_node(uint32_t node, uint32_t first, uint32_t count, const double* centroid);
    std::vector<Node> nodes_;
    std::vector<uint32_t> order_;  // item indices, leaf by leaf
};

}  // namespace lfem
