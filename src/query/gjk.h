// Convex polytopes given by their points (the convex hull of the points), and the two questions
// the queries ask of them with nothing but a support function (the point farthest along a
// direction): how far apart two of them are (Gilbert, Johnson and Keerthi's algorithm, GJK),
// and where a ray first meets one (van den Bergen's GJK ray cast, "Ray casting against general
// convex objects with application to continuous collision detection", 2004). They answer for
// the convex-hull shapes without libccd, and for a triangle, a box or a capsule's axis against
// a query box. Exact for polytopes up to a tolerance of 1e-12 of their size.
#pragma once

#include <cstdint>

#include "common/math.h"

namespace lfem {

struct ConvexPoints {
    const Vec3* points = nullptr;
    uint32_t count = 0;
};

// The first of the points farthest along d.
Vec3 support_point(const ConvexPoints& c, const Vec3& d);

// The distance (m) between the two hulls; 0 when they overlap (touching: up to 1e-12 of
// their size).
double convex_distance(const ConvexPoints& a, const ConvexPoints& b);
// The same as the vector between their nearest points, p_a - p_b (zero when they overlap).
Vec3 convex_separation(const ConvexPoints& a, const ConvexPoints& b);

// The ray origin + t dir (dir a unit vector) against the hull, for t in [0, t_max]: true and
// the first t where it meets it, with the hull's outward unit normal there (zero when the ray
// starts inside: t = 0).
bool convex_ray_cast(const ConvexPoints& c, const Vec3& origin, const Vec3& dir, double t_max, double& t,
                     Vec3& normal);

}  // namespace lfem
