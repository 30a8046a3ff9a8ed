#include "query/ray_shape.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "query/gjk.h"

namespace lfem {
namespace {

// The line o + t d against a sphere of radius r about c: false when it misses.
bool line_sphere(const Vec3& o, const Vec3& d, const Vec3& c, double r, LineInterval& out) {
    const Vec3 m = o - c;
    const double b = m.dot(d), q = m.squaredNorm() - r * r;
    const double disc = b * b - q;
    if (!(disc >= 0.0)) return false;
    // The root far from cancellation first, the other from their product q (Vieta).
    const double root = std::sqrt(disc);
    const double far = b > 0.0 ? -b - root : -b + root;
    const double near = far != 0.0 ? q / far : 0.0;
    out.t_in = std::min(far, near), out.t_out = std::max(far, near);
    out.n_in = (o + out.t_in * d - c) / r;
    out.n_out = (o + out.t_out * d - c) / r;
    return true;
}

// The line (local coordinates) against the box of half extents h about the origin.
bool line_box(const Vec3& o, const Vec3& d, const double h[3], LineInterval& out) {
    double t_in = -HUGE_VAL, t_out = HUGE_VAL;
    int in_axis = -1, out_axis = -1;
    double in_sign = 0, out_sign = 0;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (std::fabs(o[k]) > h[k]) return false;
            continue;
        }
        // Entering through the face the line comes from, leaving through the other.
        const double sign = d[k] > 0.0 ? -1.0 : 1.0;
        const double enter = (sign * h[k] - o[k]) / d[k], leave = (-sign * h[k] - o[k]) / d[k];
        if (enter > t_in) t_in = enter, in_axis = k, in_sign = sign;
        if (leave < t_out) t_out = leave, out_axis = k, out_sign = -sign;
    }
    if (!(t_in <= t_out) || in_axis < 0) return false;
    out.t_in = t_in, out.t_out = t_out;
    out.n_in = Vec3::Zero(), out.n_out = Vec3::Zero();
    out.n_in[in_axis] = in_sign;
    out.n_out[out_axis] = out_sign;
    return true;
}

// Joins piece into the union `all` (the pieces of a convex solid overlap, so the union is one
// interval); `any` says whether all holds one yet.
void unite(const LineInterval& piece, LineInterval& all, bool& any) {
    if (!any || piece.t_in < all.t_in) all.t_in = piece.t_in, all.n_in = piece.n_in;
    if (!any || piece.t_out > all.t_out) all.t_out = piece.t_out, all.n_out = piece.n_out;
    any = true;
}

// The line (local coordinates) against a capsule along z: its two end spheres and the side of
// the cylinder between them. The cylinder's flat ends lie inside the spheres, so every end of
// the union lies on a sphere or on the side.
bool line_capsule(const Vec3& o, const Vec3& d, double r, double h, LineInterval& out) {
    bool any = false;
    LineInterval piece;
    for (double z : {-h, h})
        if (line_sphere(o, d, Vec3(0, 0, z), r, piece)) unite(piece, out, any);
    const double a = d.x() * d.x() + d.y() * d.y();
    if (!(a > 0.0)) return any;  // along the axis: the spheres' union is all of it
    const double b = o.x() * d.x() + o.y() * d.y(), c = o.x() * o.x() + o.y() * o.y() - r * r;
    const double disc = b * b - a * c;
    if (!(disc >= 0.0)) return any;
    const double q = b > 0.0 ? -b - std::sqrt(disc) : -b + std::sqrt(disc);
    const double t0 = q != 0.0 ? std::min(q / a, c / q) : 0.0, t1 = q != 0.0 ? std::max(q / a, c / q) : 0.0;
    double lo = -HUGE_VAL, hi = HUGE_VAL;  // between the end planes
    if (d.z() != 0.0) {
        const double za = (-h - o.z()) / d.z(), zb = (h - o.z()) / d.z();
        lo = std::min(za, zb), hi = std::max(za, zb);
    } else if (std::fabs(o.z()) > h) {
        return any;
    }
    const auto radial = [&](double t) {
        const Vec3 p = o + t * d;
        return Vec3(Vec3(p.x(), p.y(), 0.0) / r);
    };
    // An end of the side's interval between the end planes is where the line crosses the side.
    if (t0 >= lo && t0 <= hi && (!any || t0 < out.t_in)) {
        out.t_in = t0, out.n_in = radial(t0);
        if (!any) out.t_out = t0, out.n_out = out.n_in;
        any = true;
    }
    if (t1 >= lo && t1 <= hi && (!any || t1 > out.t_out)) {
        out.t_out = t1, out.n_out = radial(t1);
        if (!any) out.t_in = t1, out.n_in = out.n_out;
        any = true;
    }
    return any;
}

// The hull's points in the world.
std::vector<Vec3> hull_points(const RigidShape& s, const ShapePose& pose) {
    std::vector<Vec3> p(s.points.size() / 3);
    for (std::size_t i = 0; i < p.size(); ++i)
        p[i] = pose.center + pose.rotation * Vec3(s.points[3 * i], s.points[3 * i + 1], s.points[3 * i + 2]);
    return p;
}

// The line against a hull: the GJK ray cast from a point on the line behind the hull, and
// again from a point beyond it, back (both start outside: the hull lies within its bounding
// radius of its centre).
bool line_hull(const RigidShape& s, const ShapePose& pose, const Vec3& o, const Vec3& d, LineInterval& out) {
    const std::vector<Vec3> p = hull_points(s, pose);
    const ConvexPoints hull{p.data(), uint32_t(p.size())};
    const double L = (o - pose.center).norm() + shape_bounding_radius(s) + 1.0;
    double t;
    Vec3 n;
    if (!convex_ray_cast(hull, o - L * d, d, 2.0 * L, t, n) || n == Vec3::Zero()) return false;
    out.t_in = t - L, out.n_in = n;
    if (!convex_ray_cast(hull, o + L * d, -d, 2.0 * L, t, n) || n == Vec3::Zero()) return false;
    out.t_out = L - t, out.n_out = n;
    return out.t_in <= out.t_out;
}

}  // namespace

void box_corners(const Aabb& box, Vec3 corners[8]) {
    for (int i = 0; i < 8; ++i)
        corners[i] = Vec3(i & 1 ? box.hi[0] : box.lo[0], i & 2 ? box.hi[1] : box.lo[1], i & 4 ? box.hi[2] : box.lo[2]);
}

bool line_through_shape(const RigidShape& s, const ShapePose& pose, const Vec3& origin, const Vec3& dir,
                        LineInterval& out) {
    if (s.type == ShapeType::convex_hull) return line_hull(s, pose, origin, dir, out);
    const Quat inv = pose.rotation.conjugate();
    const Vec3 o = inv * (origin - pose.center), d = inv * dir;
    bool hit = false;
    switch (s.type) {
        case ShapeType::plane:  // the solid is local z <= 0
            if (d.z() == 0.0) return false;
            out.t_in = d.z() < 0.0 ? -o.z() / d.z() : -HUGE_VAL;
            out.t_out = d.z() > 0.0 ? -o.z() / d.z() : HUGE_VAL;
            out.n_in = out.n_out = Vec3::UnitZ();
            hit = true;
            break;
        case ShapeType::sphere: hit = line_sphere(o, d, Vec3::Zero(), s.radius, out); break;
        case ShapeType::box: hit = line_box(o, d, s.half_extents, out); break;
        case ShapeType::capsule: hit = line_capsule(o, d, s.radius, s.half_length, out); break;
        default: return false;
    }
    if (!hit) return false;
    out.n_in = pose.rotation * out.n_in, out.n_out = pose.rotation * out.n_out;
    return true;
}

bool shape_overlaps_box(const RigidShape& s, const ShapePose& pose, const Aabb& box) {
    Vec3 corners[8];
    box_corners(box, corners);
    const double size = std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
    const double touch = 1e-12 * (size + (s.type == ShapeType::plane ? 0.0 : shape_bounding_radius(s)));
    const ConvexPoints query{corners, 8};
    switch (s.type) {
        case ShapeType::plane: {  // a corner on or below the plane
            const Vec3 n = pose.rotation * Vec3::UnitZ();
            double lowest = HUGE_VAL;
            for (const Vec3& c : corners) lowest = std::min(lowest, n.dot(c - pose.center));
            return lowest <= touch;
        }
        case ShapeType::sphere: {
            const ConvexPoints centre{&pose.center, 1};
            return convex_distance(centre, query) <= s.radius + touch;
        }
        case ShapeType::capsule: {
            const Vec3 axis = pose.rotation * Vec3(0, 0, s.half_length);
            const Vec3 ends[2] = {pose.center - axis, pose.center + axis};
            return convex_distance(ConvexPoints{ends, 2}, query) <= s.radius + touch;
        }
        case ShapeType::box: {
            Vec3 local[8];
            Aabb own;
            for (int k = 0; k < 3; ++k) own.lo[k] = -s.half_extents[k], own.hi[k] = s.half_extents[k];
            box_corners(own, local);
            for (Vec3& c : local) c = pose.center + pose.rotation * c;
            return convex_distance(ConvexPoints{local, 8}, query) <= touch;
        }
        default: {
            const std::vector<Vec3> p = hull_points(s, pose);
            return convex_distance(ConvexPoints{p.data(), uint32_t(p.size())}, query) <= touch;
        }
    }
}

double shape_distance(const RigidShape& shape, const ShapePose& pose, const Vec3& q, Vec3& p) {
    if (shape.type == ShapeType::convex_hull) {
        std::vector<Vec3> points(shape.points.size() / 3);
        const Mat3 R = pose.rotation.normalized().toRotationMatrix();
        for (std::size_t i = 0; i < points.size(); ++i) points[i] = pose.center + R * Vec3(&shape.points[3 * i]);
        const Vec3 v = convex_separation(ConvexPoints{&q, 1}, ConvexPoints{points.data(), uint32_t(points.size())});
        p = q - v;
        return v.norm();
    }
    double d = 0.0;
    Vec3 normal;
    shape_signed_distance(shape, pose, q, HUGE_VAL, d, normal);  // closed forms: any distance
    p = q - d * normal;
    return d;
}

}  // namespace lfem
