// Rays against the world: the bodies whose box the ray meets, nearest first (the tree of body
// boxes), each body's triangles the ray meets (its tree of triangles) and its shapes (in
// closed form, hulls by GJK). Every crossing of a surface counts, from either side: a ray that
// starts inside a body or a shape meets its surface on the way out.
#include <algorithm>
#include <cmath>

#include "common/closest_point.h"
#include "common/ray_triangle.h"
#include "query/query_scene.h"
#include "query/ray_shape.h"

namespace lfem {
namespace {

Vec3 node(const double* x, uint32_t i) { return Vec3(x[3 * std::size_t(i)], x[3 * std::size_t(i) + 1], x[3 * std::size_t(i) + 2]); }

// Ray against boundary triangle t of body b: true, with the hit, when it crosses it at a
// distance in [0, t_max].
bool ray_triangle(const QueryBody& b, uint32_t t, const QueryRay& ray, double t_max, uint32_t slot, RayHit& hit) {
    const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
    const Vec3 a = node(b.x, tri[0]), e1 = node(b.x, tri[1]) - a, e2 = node(b.x, tri[2]) - a;
    double s, u, v;
    if (!line_meets_triangle(ray.origin, ray.dir, a, e1, e2, s, u, v) || !(s >= 0.0 && s <= t_max)) return false;
    const Vec3 n = e1.cross(e2);
    hit.slot = slot, hit.triangle = t, hit.shape = UINT32_MAX;
    hit.t1 = v, hit.t2 = u;  // the point is (1 - u - v) a + u b + v c
    hit.distance = s;
    hit.point = ray.origin + s * ray.dir;
    hit.normal = n / n.norm();
    return true;
}

}  // namespace

template <class Visit>
void QueryScene::for_bodies_on_ray(const QueryRay& ray, const Visit& visit, double grow) {
    double t_max = ray.max_distance;
    for (uint32_t slot : unbounded_) t_max = visit(slot, t_max);
    const double d[3] = {ray.dir[0], ray.dir[1], ray.dir[2]}, o[3] = {ray.origin[0], ray.origin[1], ray.origin[2]};
    const RaySlabs slabs(o, d);
    tree_.cast(slabs, t_max, [&](uint32_t item, double bound) {
        double enter, exit;  // a leaf holds a few bodies: each one's own box first
        const uint32_t slot = bounded_[item];
        const Aabb box = grow > 0.0 ? grown(slots_[slot].box, grow) : slots_[slot].box;
        return ray_interval(box, slabs, 0.0, bound, enter, exit) ? visit(slot, bound) : bound;
    }, nullptr, grow);
}

template <class Add>
double QueryScene::body_crossings(uint32_t slot, const QueryBody& b, const QueryRay& ray, double t_max,
                                  const Add& add) {
    counts_.bodies += 1;
    if (b.triangle_count > 0) {
        const double d[3] = {ray.dir[0], ray.dir[1], ray.dir[2]}, o[3] = {ray.origin[0], ray.origin[1], ray.origin[2]};
        tree_of(slot, b).tree().cast(RaySlabs(o, d), t_max, [&](uint32_t t, double bound) {
            counts_.primitives += 1;
            RayHit hit;
            if (ray_triangle(b, t, ray, bound, slot, hit)) bound = t_max = add(hit);
            return bound;
        });
    }
    for (uint32_t j = 0; j < b.shape_count; ++j) {
        counts_.primitives += 1;
        LineInterval line;
        if (!line_through_shape(b.shapes[j], ShapePose::load(b.shape_pose + 7 * std::size_t(j)), ray.origin, ray.dir,
                                line))
            continue;
        for (int end = 0; end < 2; ++end) {
            const double t = end == 0 ? line.t_in : line.t_out;
            // Behind the origin, too far, or infinite (a plane's solid has no far side): the
            // finiteness apart, since t_max is infinite for a ray without a limit.
            if (!(t >= 0.0 && t <= t_max) || !std::isfinite(t)) continue;
            RayHit hit;
            hit.slot = slot, hit.shape = j;
            hit.distance = t;
            hit.point = ray.origin + t * ray.dir;
            hit.normal = end == 0 ? line.n_in : line.n_out;
            t_max = add(hit);
        }
    }
    return t_max;
}

bool QueryScene::cast_ray(const QueryWorld& world, const QueryRay& ray, const QueryFilter& filter, RayHit& out) {
    in_use_ = true;
    counts_.queries += 1;
    bool found = false;
    RayHit best;
    for_bodies_on_ray(ray, [&](uint32_t slot, double t_max) {
        QueryBody b;
        if (!world.body(slot, b) || !filter.sees(b)) return t_max;
        return body_crossings(slot, b, ray, t_max, [&](const RayHit& hit) {
            if (!found || hit_before(hit, best)) best = hit, found = true;
            return best.distance;  // only as near (a tie may still come first in hit order)
        });
    });
    if (found) out = best;
    return found;
}

void QueryScene::cast_ray_all(const QueryWorld& world, const QueryRay& ray, const QueryFilter& filter,
                              std::vector<RayHit>& out) {
    in_use_ = true;
    counts_.queries += 1;
    out.clear();
    for_bodies_on_ray(ray, [&](uint32_t slot, double t_max) {
        QueryBody b;
        if (!world.body(slot, b) || !filter.sees(b)) return t_max;
        return body_crossings(slot, b, ray, t_max, [&](const RayHit& hit) {
            out.push_back(hit);
            return ray.max_distance;
        });
    });
    std::sort(out.begin(), out.end(), hit_before);
}

namespace {

// The first t in [0, t_max] at which the point origin + t dir comes within radius of a convex
// piece, whose distance and nearest point `nearest(p, q)` gives (0 or less inside): that
// distance less the radius is convex along the ray and changes by at most |dt| (a unit
// direction), so stepping by it never passes its first zero (conservative advancement: one
// step head on, a few dozen at a grazing touch); moving away from the piece while still out of
// reach, the sphere never touches it. True with t, the point touched and the normal there.
template <class Nearest>
bool sweep_to(const QueryRay& ray, double radius, double t_max, const Nearest& nearest, double& t, Vec3& point,
              Vec3& normal) {
    const double tolerance = 1e-12 * (radius + 1.0);
    t = 0.0;
    for (int step = 0; step < 200 && t <= t_max; ++step) {
        const Vec3 p = ray.origin + t * ray.dir;
        Vec3 q;
        const double d = nearest(p, q);
        const double gap = d - radius;
        if (gap <= tolerance) {
            point = q;
            const Vec3 out = p - q;
            normal = out.norm() > 0.0 ? Vec3(out / out.norm()) : Vec3(-ray.dir);  // started inside
            return true;
        }
        if (d > 0.0 && ray.dir.dot(p - q) >= 0.0) return false;  // moving away
        t += gap;
    }
    return false;
}

}  // namespace

bool QueryScene::cast_sphere(const QueryWorld& world, const QueryRay& ray, double radius, const QueryFilter& filter,
                             RayHit& out) {
    in_use_ = true;
    counts_.queries += 1;
    bool found = false;
    RayHit best;
    auto consider = [&](RayHit& hit, double t_max) {
        if (!found || hit_before(hit, best)) best = hit, found = true;
        return std::min(t_max, best.distance);
    };
    const double d[3] = {ray.dir[0], ray.dir[1], ray.dir[2]}, o[3] = {ray.origin[0], ray.origin[1], ray.origin[2]};
    for_bodies_on_ray(ray, [&](uint32_t slot, double t_max) {
        QueryBody b;
        if (!world.body(slot, b) || !filter.sees(b)) return t_max;
        counts_.bodies += 1;
        if (b.triangle_count > 0)
            tree_of(slot, b).tree().cast(RaySlabs(o, d), t_max, [&](uint32_t t, double bound) {
                counts_.primitives += 1;
                const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
                const Vec3 A = node(b.x, tri[0]), B = node(b.x, tri[1]), C = node(b.x, tri[2]);
                double w[3] = {1, 0, 0};
                RayHit hit;
                if (!sweep_to(ray, radius, bound, [&](const Vec3& p, Vec3& q) {
                        q = closest_on_triangle(p, A, B, C, w);
                        return (p - q).norm();
                    }, hit.distance, hit.point, hit.normal))
                    return bound;
                hit.slot = slot, hit.triangle = t, hit.shape = UINT32_MAX;
                hit.t1 = w[2], hit.t2 = w[1];  // the point is w0 a + w1 b + w2 c
                return t_max = consider(hit, bound);
            }, nullptr, radius);
        for (uint32_t j = 0; j < b.shape_count; ++j) {
            counts_.primitives += 1;
            const ShapePose pose = ShapePose::load(b.shape_pose + 7 * std::size_t(j));
            RayHit hit;
            if (!sweep_to(ray, radius, t_max, [&](const Vec3& p, Vec3& q) { return shape_distance(b.shapes[j], pose, p, q); },
                          hit.distance, hit.point, hit.normal))
                continue;
            hit.slot = slot, hit.shape = j;
            t_max = consider(hit, t_max);
        }
        return t_max;
    }, radius);
    if (found) out = best;
    return found;
}

}  // namespace lfem
