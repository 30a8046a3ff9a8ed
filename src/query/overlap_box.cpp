// The bodies a box overlaps: those whose box meets it (the tree of body boxes), then exactly,
// a boundary triangle or a shape that meets the box (GJK, query/gjk.h), or, for a body of tets,
// the box inside it (its centre inside the closed surface, by the parity of a ray's crossings).
#include <algorithm>
#include <cmath>

#include "common/ray_triangle.h"
#include "query/gjk.h"
#include "query/query_scene.h"
#include "query/ray_shape.h"

namespace lfem {
namespace {

// The direction of the parity ray: no simple ratio of its components, so that it does not run
// along the edges and faces of a structured mesh (a crossing on an edge would count twice).
const Vec3 kParityDirection = Vec3(0.5387911, 0.6021707, 0.5890227).normalized();

Vec3 node(const double* x, uint32_t i) { return Vec3(x[3 * std::size_t(i)], x[3 * std::size_t(i) + 1], x[3 * std::size_t(i) + 2]); }

double box_size(const Aabb& box) {
    return std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
}

}  // namespace

bool QueryScene::contains(uint32_t slot, const QueryBody& b, const Vec3& p) {
    const double o[3] = {p[0], p[1], p[2]}, d[3] = {kParityDirection[0], kParityDirection[1], kParityDirection[2]};
    uint32_t crossings = 0;
    tree_of(slot, b).tree().cast(RaySlabs(o, d), HUGE_VAL, [&](uint32_t t, double bound) {
        counts_.primitives += 1;
        const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
        const Vec3 a = node(b.x, tri[0]);
        double s, u, v;
        if (line_meets_triangle(p, kParityDirection, a, node(b.x, tri[1]) - a, node(b.x, tri[2]) - a, s, u, v) && s > 0.0)
            crossings += 1;
        return bound;
    });
    return crossings % 2 == 1;
}

bool QueryScene::body_overlaps(uint32_t slot, const QueryBody& b, const Aabb& box) {
    counts_.bodies += 1;
    Vec3 corners[8];
    box_corners(box, corners);
    const ConvexPoints query{corners, 8};
    bool found = false;
    if (b.triangle_count > 0) {
        const double touch = 1e-12 * std::max(box_size(box), box_size(slots_[slot].box));
        tree_of(slot, b).query(box, b.x, b.triangles, 0.0, [&](uint32_t t) {
            if (found) return;
            counts_.primitives += 1;
            const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
            const Vec3 p[3] = {node(b.x, tri[0]), node(b.x, tri[1]), node(b.x, tri[2])};
            found = convex_distance(ConvexPoints{p, 3}, query) <= touch;
        });
    }
    for (uint32_t j = 0; j < b.shape_count && !found; ++j) {
        counts_.primitives += 1;
        found = shape_overlaps_box(b.shapes[j], ShapePose::load(b.shape_pose + 7 * std::size_t(j)), box);
    }
    if (!found && b.solid) {
        // No face meets the box: it lies wholly inside the body or wholly outside it.
        const Vec3 centre(0.5 * (box.lo[0] + box.hi[0]), 0.5 * (box.lo[1] + box.hi[1]), 0.5 * (box.lo[2] + box.hi[2]));
        Aabb point;
        for (int k = 0; k < 3; ++k) point.lo[k] = point.hi[k] = centre[k];
        found = overlaps(point, slots_[slot].box) && contains(slot, b, centre);
    }
    return found;
}

void QueryScene::overlap_box(const QueryWorld& world, const Aabb& box, const QueryFilter& filter,
                             std::vector<uint32_t>& out) {
    in_use_ = true;
    counts_.queries += 1;
    out.clear();
    std::vector<uint32_t> met(unbounded_);
    tree_.query(box, [&](uint32_t item) {
        if (overlaps(slots_[bounded_[item]].box, box)) met.push_back(bounded_[item]);
    });
    std::sort(met.begin(), met.end());
    for (uint32_t slot : met) {
        QueryBody b;
        if (world.body(slot, b) && filter.sees(b) && body_overlaps(slot, b, box)) out.push_back(slot);
    }
}

}  // namespace lfem
