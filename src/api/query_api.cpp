// C shim of the queries: the ray and the box checked (pointers, finite numbers, a direction of
// non-zero length, lo <= hi), the world's hits turned into lfem_ray_hit and handles.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "api/handles.h"

using namespace lfem;
using namespace lfem::api;

namespace {

QueryRay checked_ray(const double* origin, const double* direction, double max_distance) {
    require_pointer(origin, "origin");
    require_pointer(direction, "direction");
    require_finite(origin, 3, "origin");
    require_finite(direction, 3, "direction");
    require(!std::isnan(max_distance) && max_distance >= 0.0, "max_distance must be >= 0 m (HUGE_VAL: no limit)");
    // Scaled by its largest component first, so that neither a tiny nor a huge direction
    // under- or overflows on the way to unit length.
    const double largest = std::max({std::fabs(direction[0]), std::fabs(direction[1]), std::fabs(direction[2])});
    require(largest > 0.0, "direction is zero");
    QueryRay ray;
    ray.origin = Vec3(origin[0], origin[1], origin[2]);
    ray.dir = Vec3(direction[0] / largest, direction[1] / largest, direction[2] / largest).normalized();
    ray.max_distance = max_distance;
    return ray;
}

QueryFilter filter_of(const lfem_query_filter& f) {
    QueryFilter q;
    q.category = f.category_bits, q.mask = f.mask_bits;
    return q;
}

lfem_ray_hit hit_as_c(const World& w, const RayHit& h) {
    lfem_ray_hit out{};
    out.body = to_c(w.bodies().handle_of(h.slot));
    out.triangle = h.triangle;
    out.shape = h.shape;
    out.barycentric[0] = h.t1, out.barycentric[1] = h.t2;
    for (int k = 0; k < 3; ++k) out.point[k] = h.point[k], out.normal[k] = h.normal[k];
    out.distance = h.distance;
    return out;
}

// count, then out unless it holds too few: the rule of every list the C API returns.
template <class T, class Put>
void give_list(std::size_t total, T* out, uint32_t capacity, uint32_t* count, const char* what, const Put& put) {
    require(total <= UINT32_MAX, std::string("more than 2^32 - 1 ") + what);
    *count = uint32_t(total);
    if (total > capacity)
        throw Error(Status::buffer_too_small, "capacity " + std::to_string(capacity) + " is below the " +
                                               std::to_string(total) + " " + what);
    for (std::size_t i = 0; i < total; ++i) out[i] = put(i);
}

}  // namespace

extern "C" {

LFEM_API lfem_query_filter lfem_query_filter_default(void) {
    lfem_query_filter f;
    f.category_bits = 1u;
    f.mask_bits = 0xFFFFFFFFu;
    return f;
}

LFEM_API lfem_status lfem_world_cast_ray(const lfem_world* world, const double origin[3], const double direction[3],
                                         double max_distance, lfem_query_filter filter, lfem_ray_hit* out, int* hit) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const QueryRay ray = checked_ray(origin, direction, max_distance);
        require_pointer(out, "out");
        require_pointer(hit, "hit");
        RayHit h;
        const bool found = w.cast_ray(ray, filter_of(filter), h);
        if (found) *out = hit_as_c(w, h);
        *hit = found ? 1 : 0;
    });
}

LFEM_API lfem_status lfem_world_cast_sphere(const lfem_world* world, const double origin[3],
                                            const double direction[3], double radius, double max_distance,
                                            lfem_query_filter filter, lfem_ray_hit* out, int* hit) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const QueryRay ray = checked_ray(origin, direction, max_distance);
        require(std::isfinite(radius) && radius >= 0.0, "radius must be finite and >= 0 m");
        require_pointer(out, "out");
        require_pointer(hit, "hit");
        RayHit h;
        const bool found = w.cast_sphere(ray, radius, filter_of(filter), h);
        if (found) *out = hit_as_c(w, h);
        *hit = found ? 1 : 0;
    });
}

LFEM_API lfem_status lfem_world_cast_ray_all(const lfem_world* world, const double origin[3],
                                             const double direction[3], double max_distance,
                                             lfem_query_filter filter, lfem_ray_hit* out, uint32_t capacity,
                                             uint32_t* count) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const QueryRay ray = checked_ray(origin, direction, max_distance);
        require_pointer(count, "count");
        require(capacity == 0 || out != nullptr, "out is NULL with a non-zero capacity");
        std::vector<RayHit> hits;
        w.cast_ray_all(ray, filter_of(filter), hits);
        give_list(hits.size(), out, capacity, count, "hits", [&](std::size_t i) { return hit_as_c(w, hits[i]); });
    });
}

LFEM_API lfem_status lfem_world_overlap_box(const lfem_world* world, const double lo[3], const double hi[3],
                                            lfem_query_filter filter, lfem_body* out, uint32_t capacity,
                                            uint32_t* count) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(lo, "lo");
        require_pointer(hi, "hi");
        require_finite(lo, 3, "lo");
        require_finite(hi, 3, "hi");
        for (int k = 0; k < 3; ++k)
            require(lo[k] <= hi[k], "lo[" + std::to_string(k) + "] is above hi[" + std::to_string(k) + "]");
        require_pointer(count, "count");
        require(capacity == 0 || out != nullptr, "out is NULL with a non-zero capacity");
        Aabb box;
        for (int k = 0; k < 3; ++k) box.lo[k] = lo[k], box.hi[k] = hi[k];
        std::vector<uint32_t> slots;
        w.overlap_box(box, filter_of(filter), slots);
        give_list(slots.size(), out, capacity, count, "bodies",
                  [&](std::size_t i) { return to_c(w.bodies().handle_of(slots[i])); });
    });
}

}  // extern "C"

namespace {

// The sphere and the capsule: a segment (a point for the sphere, named as its caller names it)
// swept by radius.
lfem_status overlap_capsule(const char* function, const lfem_world* world, const double* a, const char* a_name,
                            const double* b, const char* b_name, double radius, lfem_query_filter filter,
                            lfem_overlap* out, uint32_t capacity, uint32_t* count) {
    return guard(function, [&] {
        const World& w = world_of(world);
        require_pointer(a, a_name);
        require_pointer(b, b_name);
        require_finite(a, 3, a_name);
        require_finite(b, 3, b_name);
        require(std::isfinite(radius) && radius >= 0.0, "radius must be finite and >= 0 m");
        require_pointer(count, "count");
        require(capacity == 0 || out != nullptr, "out is NULL with a non-zero capacity");
        QueryCapsule capsule;
        capsule.a = Vec3(a), capsule.b = Vec3(b), capsule.radius = radius;
        std::vector<Overlap> found;
        w.overlap_capsule(capsule, filter_of(filter), found);
        give_list(found.size(), out, capacity, count, "overlaps", [&](std::size_t i) {
            const Overlap& o = found[i];
            lfem_overlap c{};
            c.body = to_c(w.bodies().handle_of(o.slot));
            c.triangle = o.triangle, c.shape = o.shape;
            for (int k = 0; k < 3; ++k) c.point[k] = o.point[k];
            c.distance = o.distance;
            return c;
        });
    });
}

}  // namespace

LFEM_API lfem_status lfem_world_overlap_sphere(const lfem_world* world, const double center[3], double radius,
                                               lfem_query_filter filter, lfem_overlap* out, uint32_t capacity,
                                               uint32_t* count) {
    return overlap_capsule(__func__, world, center, "center", center, "center", radius, filter, out, capacity, count);
}

LFEM_API lfem_status lfem_world_overlap_capsule(const lfem_world* world, const double a[3], const double b[3],
                                                double radius, lfem_query_filter filter, lfem_overlap* out,
                                                uint32_t capacity, uint32_t* count) {
    return overlap_capsule(__func__, world, a, "a", b, "b", radius, filter, out, capacity, count);
}

LFEM_API lfem_status lfem_body_closest_point(const lfem_world* world, lfem_body body, const double point[3],
                                             double out_point[3], uint32_t* triangle, double* distance) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(point, "point");
        require_finite(point, 3, "point");
        require_pointer(out_point, "out_point");
        const SurfacePoint s = w.closest_surface_point(b, point);
        for (int k = 0; k < 3; ++k) out_point[k] = s.point[k];
        if (triangle) *triangle = s.triangle;
        if (distance) *distance = s.distance;
    });
}
