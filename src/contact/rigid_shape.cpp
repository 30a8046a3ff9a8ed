#include "contact/rigid_shape.h"

#if LFEM_WITH_CCD
#include <ccd/ccd.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>

namespace lfem {
namespace {

#if LFEM_WITH_CCD
// libccd's view of the two objects of a hull query: the posed hull, and a ball of radius r
// around the query point (the point inflated so that MPR reports depth for nearby points too).
struct CcdHull {
    const RigidShape* shape;
    const ShapePose* pose;
};
struct CcdBall {
    Vec3 center;
    double radius;
};

void hull_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const CcdHull& h = *static_cast<const CcdHull*>(obj);
    const Vec3 d_local = h.pose->rotation.conjugate() * Vec3(dir->v[0], dir->v[1], dir->v[2]);
    const std::vector<double>& p = h.shape->points;
    std::size_t best = 0;
    double best_dot = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); i += 3) {
        const double dot = p[i] * d_local[0] + p[i + 1] * d_local[1] + p[i + 2] * d_local[2];
        if (dot > best_dot) best_dot = dot, best = i;
    }
    const Vec3 w = h.pose->center + h.pose->rotation * Vec3(p[best], p[best + 1], p[best + 2]);
    for (int k = 0; k < 3; ++k) out->v[k] = w[k];
}

void hull_center(const void* obj, ccd_vec3_t* out) {
    const CcdHull& h = *static_cast<const CcdHull*>(obj);
    const std::vector<double>& p = h.shape->points;
    Vec3 c = Vec3::Zero();
    for (std::size_t i = 0; i < p.size(); i += 3) c += Vec3(p[i], p[i + 1], p[i + 2]);
    c = h.pose->center + h.pose->rotation * (c / double(p.size() / 3));
    for (int k = 0; k < 3; ++k) out->v[k] = c[k];
}

void ball_support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const CcdBall& b = *static_cast<const CcdBall*>(obj);
    const Vec3 d(dir->v[0], dir->v[1], dir->v[2]);
    const double n = d.norm();
    const Vec3 w = b.center + (n > 0.0 ? b.radius / n : 0.0) * d;
    for (int k = 0; k < 3; ++k) out->v[k] = w[k];
}

void ball_center(const void* obj, ccd_vec3_t* out) {
    const CcdBall& b = *static_cast<const CcdBall*>(obj);
    for (int k = 0; k < 3; ++k) out->v[k] = b.center[k];
}

#endif  // LFEM_WITH_CCD

// Signed distance to a box of half extents h centred at the origin, in its own frame.
double box_distance(const Vec3& p, const double h[3], Vec3& n) {
    Vec3 q;
    for (int k = 0; k < 3; ++k) q[k] = std::fabs(p[k]) - h[k];
    if (q.maxCoeff() > 0.0) {
        Vec3 outside = q.cwiseMax(0.0);
        const double d = outside.norm();
        for (int k = 0; k < 3; ++k) n[k] = std::copysign(outside[k], p[k]) / d;
        return d;
    }
    int axis = 0;  // inside: the nearest face
    for (int k = 1; k < 3; ++k)
        if (q[k] > q[axis]) axis = k;
    n = Vec3::Zero();
    n[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
    return q[axis];
}

}  // namespace

double shape_bounding_radius(const RigidShape& s) {
    switch (s.type) {
        case ShapeType::plane: return std::numeric_limits<double>::infinity();
        case ShapeType::box: return Vec3(s.half_extents).norm();
        case ShapeType::sphere: return s.radius;
        case ShapeType::capsule: return s.half_length + s.radius;
        default: {
            double r = 0.0;
            for (std::size_t i = 0; i < s.points.size(); i += 3)
                r = std::max(r, Vec3(s.points[i], s.points[i + 1], s.points[i + 2]).norm());
            return r;
        }
    }
}

bool shape_signed_distance(const RigidShape& s, const ShapePose& pose, const Vec3& x,
                           double max_distance, double& distance, Vec3& normal) {
    const Vec3 p = pose.rotation.conjugate() * (x - pose.center);  // local coordinates
    Vec3 n_local;
    switch (s.type) {
        case ShapeType::plane:
            distance = p.z();
            n_local = Vec3::UnitZ();
            break;
        case ShapeType::sphere: {
            const double r = p.norm();
            distance = r - s.radius;
            n_local = r > 0.0 ? Vec3(p / r) : Vec3::UnitZ();
            break;
        }
        case ShapeType::box:
            distance = box_distance(p, s.half_extents, n_local);
            break;
        case ShapeType::capsule: {
            const Vec3 axis_point(0.0, 0.0, std::clamp(p.z(), -s.half_length, s.half_length));
            const Vec3 v = p - axis_point;
            const double r = v.norm();
            distance = r - s.radius;
            n_local = r > 0.0 ? Vec3(v / r) : Vec3::UnitX();
            break;
        }
        default: {
#if !LFEM_WITH_CCD
            // Convex hulls are refused when added (and when loaded) in a build without libccd.
            return false;
#else
            // The point as a ball of radius max_distance: MPR's penetration depth of the ball
            // is max_distance minus the point's signed distance, its direction the normal.
            const CcdHull hull{&s, &pose};
            const CcdBall ball{x, max_distance};
            ccd_t ccd;
            CCD_INIT(&ccd);
            ccd.support1 = hull_support;
            ccd.support2 = ball_support;
            ccd.center1 = hull_center;
            ccd.center2 = ball_center;
            ccd.max_iterations = 200;
            ccd.mpr_tolerance = 1e-12;
            ccd_real_t depth = 0;
            ccd_vec3_t dir, pos;
            if (ccdMPRPenetration(&hull, &ball, &ccd, &depth, &dir, &pos) != 0) return false;
            distance = max_distance - depth;
            normal = Vec3(dir.v[0], dir.v[1], dir.v[2]).normalized();
            return distance <= max_distance;
#endif
        }
    }
    if (distance > max_distance) return false;
    normal = pose.rotation * n_local;
    return true;
}

}  // namespace lfem
