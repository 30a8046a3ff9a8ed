// The bodies a sphere or a capsule overlaps, and where. The query is a core (a point, or the
// segment ab) swept by a radius: a body overlaps it when one of its boundary triangles or shapes
// comes within the radius of the core (touching counts), or when it holds the core inside (a
// body of tets whose surface the query does not reach). The distance from a point to a convex
// set (a triangle, a solid shape) is a convex function of the point, so along the segment its
// least value is found by golden-section search; for a sphere the core is one point and no
// search is needed.
#include <algorithm>
#include <cmath>

#include "common/closest_point.h"
#include "query/query_scene.h"
#include "query/ray_shape.h"

namespace lfem {
namespace {

Vec3 node(const double* x, uint32_t i) { return Vec3(x[3 * std::size_t(i)], x[3 * std::size_t(i) + 1], x[3 * std::size_t(i) + 2]); }

// The nearest point of a convex set to the core: `nearest(q, p)` gives the distance from q to
// the set (signed: negative inside a solid shape) and its point p there. Golden-section search
// over the segment: 80 rounds shrink the bracket to 0.618^80 < 1e-16 of its length; the two
// ends are tried as well (the least value may sit at one of them).
template <class Nearest>
double least_along(const QueryCapsule& c, const Nearest& nearest, Vec3& point, Vec3& core) {
    auto at = [&](double s) { return Vec3(c.a + s * (c.b - c.a)); };
    double best = nearest(c.a, point);
    core = c.a;
    if (c.a == c.b) return best;
    auto consider = [&](double s) {
        Vec3 p;
        const Vec3 q = at(s);
        const double d = nearest(q, p);
        if (d < best) best = d, point = p, core = q;
        return d;
    };
    consider(1.0);
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = 0.0, hi = 1.0, s1 = hi - g * (hi - lo), s2 = lo + g * (hi - lo);
    double f1 = consider(s1), f2 = consider(s2);
    for (int round = 0; round < 80; ++round) {
        if (f1 <= f2) {
            hi = s2, s2 = s1, f2 = f1;
            s1 = hi - g * (hi - lo);
            f1 = consider(s1);
        } else {
            lo = s1, s1 = s2, f1 = f2;
            s2 = lo + g * (hi - lo);
            f2 = consider(s2);
        }
    }
    return best;
}

}  // namespace

void QueryScene::overlap_capsule(const QueryWorld& world, const QueryCapsule& c, const QueryFilter& filter,
                                 std::vector<Overlap>& out) {
    in_use_ = true;
    counts_.queries += 1;
    out.clear();
    Aabb box = empty_box();
    for (int k = 0; k < 3; ++k)
        box.lo[k] = std::min(c.a[k], c.b[k]) - c.radius, box.hi[k] = std::max(c.a[k], c.b[k]) + c.radius;
    std::vector<uint32_t> met(unbounded_);
    tree_.query(box, [&](uint32_t item) {
        if (overlaps(slots_[bounded_[item]].box, box)) met.push_back(bounded_[item]);
    });
    std::sort(met.begin(), met.end());
    // Touching counts: 1e-12 of the query's size.
    const double touch = 1e-12 * (c.radius + (c.b - c.a).norm());
    for (uint32_t slot : met) {
        QueryBody b;
        if (!world.body(slot, b) || !filter.sees(b)) continue;
        counts_.bodies += 1;
        Overlap o;
        o.slot = slot;
        o.distance = HUGE_VAL;
        if (b.triangle_count > 0)
            tree_of(slot, b).query(box, b.x, b.triangles, 0.0, [&](uint32_t t) {
                counts_.primitives += 1;
                const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
                const Vec3 A = node(b.x, tri[0]), B = node(b.x, tri[1]), C = node(b.x, tri[2]);
                Vec3 p, core;
                const double d = least_along(c, [&](const Vec3& q, Vec3& at) {
                    double w[3];
                    at = closest_on_triangle(q, A, B, C, w);
                    return (at - q).norm();
                }, p, core);
                if (d < o.distance || (d == o.distance && t < o.triangle)) o.distance = d, o.triangle = t, o.point = p;
            });
        for (uint32_t j = 0; j < b.shape_count; ++j) {
            counts_.primitives += 1;
            const ShapePose pose = ShapePose::load(b.shape_pose + 7 * std::size_t(j));
            Vec3 p, core;
            const double d = least_along(c, [&](const Vec3& q, Vec3& at) { return shape_distance(b.shapes[j], pose, q, at); },
                                         p, core);
            if (d < o.distance) o.distance = d, o.triangle = UINT32_MAX, o.shape = j, o.point = p;
        }
        if (o.distance <= c.radius + touch) {
            // Inside a shape the core is in it (0); touching within `touch` reports the radius,
            // as the API promises (the fuzzer found a 1e4 m capsule 5e-9 beyond its radius).
            o.distance = std::clamp(o.distance, 0.0, c.radius);
            out.push_back(o);
        } else if (b.solid) {
            // Nothing of its surface within reach: the core lies wholly inside it or outside.
            Aabb point;
            for (int k = 0; k < 3; ++k) point.lo[k] = point.hi[k] = c.a[k];
            if (overlaps(point, slots_[slot].box) && contains(slot, b, c.a)) {
                Overlap inside;
                inside.slot = slot, inside.point = c.a, inside.distance = 0.0;
                out.push_back(inside);
            }
        }
    }
}

}  // namespace lfem
