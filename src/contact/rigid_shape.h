// Rigid shapes of static and kinematic bodies (plane, box, sphere, capsule, convex hull) and
// the one query contact needs of them: the signed distance of a point and the outward normal.
#pragma once

#include <cstdint>
#include <vector>

#include "common/math.h"
namespace lfem {

// The public ShapeType's values (the shim converts).
enum class ShapeType : int32_t { plane, box, sphere, capsule, convex_hull };

struct RigidShape {
    ShapeType type = ShapeType::plane;
    double half_extents[3] = {0, 0, 0};
    double radius = 0;
    double half_length = 0;
    std::vector<double> points;  // convex hull, local coordinates, 3 per point
    // A convex hull's edges where two of its faces meet at an angle: their points (2 each, into
    // `points`) and the sums of their faces' unit normals (3 each, local); derived from the
    // points (hull_edges.h), not saved.
    std::vector<uint32_t> hull_edges;
    std::vector<double> hull_edge_out;
};

// A shape's placement: world = center + R(rotation) local. 7 doubles: x, y, z, qw, qx, qy, qz.
struct ShapePose {
    Vec3 center;
    Quat rotation;
    static ShapePose load(const double* p) { return {Vec3(p[0], p[1], p[2]), load_quaternion(p + 3)}; }
};

// Signed distance (m, negative inside) from x to the posed shape and the outward unit normal of
// the nearest surface point. Returns false (and leaves the outputs undefined) when x is
// farther than max_distance outside: callers ask only about nearby points. Planes, spheres,
// boxes and capsules are answered in closed form; convex hulls by libccd's MPR.
bool shape_signed_distance(const RigidShape& shape, const ShapePose& pose, const Vec3& x,
                           double max_distance, double& distance, Vec3& normal);

// Radius of a sphere about the shape's local origin that contains it (infinite for a plane).
double shape_bounding_radius(const RigidShape& shape);

}  // namespace lfem
