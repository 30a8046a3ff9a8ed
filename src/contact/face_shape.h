// A rigid shape poking into a face between its nodes: the shape's deepest point under a boundary
// triangle of a moving body, where the triangle's nodes do not see it (a rod across a soft
// cube's face, a stud under it, a box's edge). The node-to-shape constraints hold the nodes out
// of the shape; this one holds the face's point out of it, with the triangle's barycentric
// weights on its three nodes, as eq. (6) weights a triangle's point against a node.
#pragma once

#include <cstdint>
#include <vector>

#include "common/box.h"
#include "common/math.h"
#include "contact/contact_body.h"
#include "contact/rigid_shape.h"

namespace lfem {

// The world box of a posed shape (empty for a plane, which has no points between a face's nodes).
Aabb shape_box(const RigidShape& shape, const ShapePose& pose);

// The world boxes of a posed box shape's twelve edges, appended to out.
void box_edge_boxes(const RigidShape& shape, const ShapePose& pose, std::vector<Aabb>& out);

// The points of the posed shape under triangle (p0, p1, p2), whose unit outward normal is n,
// that a constraint must hold the face above: those whose projection onto the triangle's plane
// lies in the triangle with the least height n.(x - p0). A sphere's lowest point there; a
// capsule's, or a box's or a hull's, at both ends of the part of its axis or its edge that runs
// under the face (the gap is linear along it: held at both ends, the face is above all of it),
// taken as one point when they lie less than `sep` apart; for a flat-sided shape the second is
// the candidate farthest from the lowest among those at most `rise` higher. Returns how many
// (0, 1 or 2), each with its `core`: the centre of a sphere, the point of a capsule's axis, the
// point itself for a box or a hull. None for a plane (no point that a face's nodes could miss).
int points_under(const RigidShape& shape, const ShapePose& pose, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                 const Vec3& n, double rise, double sep, Vec3 points[2], Vec3 cores[2]);

// Triangle t of body a (a moving body) against point `end` (0 or 1) of shape k of body o under
// it (points_under): filled when it lies within the capture band in front of the face at the end
// of the step; `start_gap` says how deep it was at the start and `unseen` how much deeper than
// the triangle's nodes see the shape it lies (0 for a box's face under the face, whose nodes
// hold it as on a floor): the caller decides. `held` (nullable): the weights of the
// face's point where the pair stuck at the last step, kept instead of the new deepest point's
// (the shape's point is then the one nearest to it).
struct FaceShapeHit {
    double weights[3] = {0, 0, 0};  // the point's barycentric weights on the triangle's nodes
    Vec3 point_end = Vec3::Zero(), point_start = Vec3::Zero();  // the shape's point, both ends of the step
    Vec3 normal = Vec3::Zero();     // unit, out of the shape, towards the face
    double gap = 0, start_gap = 0;  // the face's point's distance from the shape's along the normal,
                                    // at x* and at x^n (m)
    double unseen = 0;              // the nodes' weighted distance from the shape, less gap (m)
    int ends = 0;                   // how many points of the shape lie under the face (0 when
                                    // it was turned away before looking)
};
bool test_face_shape(const ContactBody& a, uint32_t t, const ContactBody& o, uint32_t k, double band, int end,
                     const double* held, FaceShapeHit& hit);

}  // namespace lfem
