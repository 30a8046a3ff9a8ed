// C shim of rigid shapes: checks a shape definition completely before the body sees it.
#include <cmath>
#include <string>

#include "api/handles.h"
#include "contact/rigid_shape.h"

using namespace lfem;
using namespace lfem::api;

namespace {

void require_positive(double v, const char* name) {
    require(std::isfinite(v) && v > 0.0, std::string(name) + " must be finite and > 0 m");
}

// A hull needs volume: some point must lie off the plane of the first three non-collinear
// ones by more than 1e-9 of the hull's size.
void check_hull(const double* p, uint32_t n) {
    require(n >= 4, "def->point_count must be >= 4 for a convex hull");
    require_finite(p, 3 * std::size_t(n), "def->points");
    double size = 0.0;
    for (uint32_t i = 1; i < n; ++i) size = std::max(size, (Vec3(&p[3 * i]) - Vec3(p)).norm());
    require(size > 0.0, "def->points are all the same point");
    Vec3 normal = Vec3::Zero();
    for (uint32_t i = 1; i < n && normal.norm() <= 1e-9 * size * size; ++i)
        for (uint32_t j = i + 1; j < n && normal.norm() <= 1e-9 * size * size; ++j)
            normal = (Vec3(&p[3 * i]) - Vec3(p)).cross(Vec3(&p[3 * j]) - Vec3(p));
    require(normal.norm() > 1e-9 * size * size, "def->points are collinear");
    normal.normalize();
    double off = 0.0;
    for (uint32_t i = 0; i < n; ++i) off = std::max(off, std::fabs(normal.dot(Vec3(&p[3 * i]) - Vec3(p))));
    require(off > 1e-9 * size, "def->points are coplanar: a convex hull needs volume");
}

}  // namespace

extern "C" {

LFEM_API lfem_shape_def lfem_shape_def_default(void) {
    lfem_shape_def d{};
    d.type = LFEM_SHAPE_PLANE;
    d.rotation[0] = 1.0;
    d.half_extents[0] = d.half_extents[1] = d.half_extents[2] = 0.5;
    d.radius = 0.5;
    d.half_length = 0.5;
    d.points = nullptr;
    d.internal_value = shape_def_cookie;
    return d;
}

LFEM_API lfem_status lfem_body_add_shape(lfem_world* world, lfem_body body, const lfem_shape_def* def,
                                         uint32_t* index) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(def, "def");
        const lfem_shape_def& d = *def;
        require(d.internal_value == shape_def_cookie, "def was not initialised by lfem_shape_def_default()");
        require(b.is_static() || b.is_kinematic(),
                "rigid shapes belong to static or kinematic bodies");
        require_finite(d.center, 3, "def->center");
        require_finite(d.rotation, 4, "def->rotation");
        const Quat q = load_quaternion(d.rotation);
        require(std::fabs(q.norm() - 1.0) < 1e-6, "def->rotation must be a unit quaternion (w, x, y, z)");
        RigidShape shape;
        if (!shape_type_from_c(d.type, shape.type))
            throw Error(Status::invalid_argument, "def->type " + std::to_string(int(d.type)) + " is not a shape type");
        switch (shape.type) {
            case ShapeType::plane: break;
            case ShapeType::box:
                for (int k = 0; k < 3; ++k) require_positive(d.half_extents[k], "def->half_extents");
                for (int k = 0; k < 3; ++k) shape.half_extents[k] = d.half_extents[k];
                break;
            case ShapeType::sphere:
                require_positive(d.radius, "def->radius");
                shape.radius = d.radius;
                break;
            case ShapeType::capsule:
                require_positive(d.radius, "def->radius");
                require(std::isfinite(d.half_length) && d.half_length >= 0.0,
                        "def->half_length must be finite and >= 0 m");
                shape.radius = d.radius;
                shape.half_length = d.half_length;
                break;
            case ShapeType::convex_hull:
                require_pointer(d.points, "def->points");
                check_hull(d.points, d.point_count);
#if !LFEM_WITH_CCD
                unsupported("convex-hull shapes (libccd)", "LFEM_WITH_CCD");
#endif
                shape.points.assign(d.points, d.points + 3 * std::size_t(d.point_count));
                break;
        }
        const double pose[7] = {d.center[0], d.center[1], d.center[2], q.w() / q.norm(),
                                q.x() / q.norm(), q.y() / q.norm(), q.z() / q.norm()};
        const uint32_t added = w.add_shape(from_c(body), shape, pose);
        if (index) *index = added;
    });
}

}  // extern "C"
