// A bounding volume hierarchy of a body's boundary triangles (a BoxTree of their boxes). A
// static body's tree is built once, when its mesh is added; a moving body's is refitted (new
// boxes, same tree) when contact looks for candidates again, and the queries keep trees of
// their own (query/query_scene.h). A box query visits the triangles whose box overlaps a box:
// O(log T + k), whatever the size of the triangles or of the terrain.
#pragma once

#include <cstdint>
#include <vector>

#include "common/box_tree.h"
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
    void refit(const double* x, const uint32_t* triangles) {
        tree_.refit([&](uint32_t t) { return triangle_box(x, &triangles[3 * std::size_t(t)]); });
    }
    bool empty() const { return tree_.empty(); }
    // The box of every triangle (the root's box); only for a non-empty tree.
    const Aabb& bounds() const { return tree_.bounds(); }
    // visit(t), in no particular order, for every triangle t (3 node indices each in
    // `triangles`) whose box at the positions x overlaps `box`. The tree's own boxes come from
    // the positions it was built or refitted on, which may lie up to `drift` per axis from x.
    template <class Visit>
    void query(const Aabb& box, const double* x, const uint32_t* triangles, double drift, const Visit& visit) const {
        tree_.query(grown(box, drift), [&](uint32_t t) {
            if (overlaps(triangle_box(x, &triangles[3 * std::size_t(t)]), box)) visit(t);
        });
    }
    // The tree itself (its ray traversal, for the queries).
    const BoxTree& tree() const { return tree_; }

private:
    BoxTree tree_;
};

}  // namespace lfem
