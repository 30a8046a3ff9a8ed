// A line against the rigid shapes (plane, box, sphere, capsule in closed form; convex hulls by
// the GJK ray cast, query/gjk.h, so libccd is not needed), and a shape against a query box.
#pragma once

#include "common/box.h"
#include "common/math.h"
#include "contact/rigid_shape.h"

namespace lfem {

// The part [t_in, t_out] of the line origin + t dir (dir a unit vector, t of any sign) inside a
// solid shape, with the outward unit normals of the shape's surface where the line enters and
// leaves it. A plane's solid is a half-space: one end is infinite (HUGE_VAL), and no surface
// is crossed there.
struct LineInterval {
    double t_in = 0, t_out = 0;
    Vec3 n_in = Vec3::Zero(), n_out = Vec3::Zero();
};

// False when the line misses the shape (or, for a plane, runs parallel to it).
bool line_through_shape(const RigidShape& shape, const ShapePose& pose, const Vec3& origin, const Vec3& dir,
                        LineInterval& out);

// Whether the solid shape overlaps the box (touching counts, to 1e-12 of their size).
bool shape_overlaps_box(const RigidShape& shape, const ShapePose& pose, const Aabb& box);

// The distance from q to a posed solid shape (negative inside; 0 inside a convex hull, whose
// surface GJK does not look for) and its nearest point (q itself inside a hull).
double shape_distance(const RigidShape& shape, const ShapePose& pose, const Vec3& q, Vec3& nearest);

// The eight corners of a box.
void box_corners(const Aabb& box, Vec3 corners[8]);

}  // namespace lfem
