// The node-triangle test (contact/node_face.h) at the seam between two faces: a node that slides
// across their shared edge must be held by one of them, and one that comes at a face from the
// side, passing its plane outside it, by neither.
//
// The faces: the unit square at z = 0 split along its diagonal v0-v2 into T0 = (v0, v1, v2)
// (x > y) and T1 = (v0, v2, v3) (y > x), with v1 raised by 0.02: a shallow valley along the
// diagonal, as a soft surface dented by what presses on it. Edge length 1, so the residual depth
// is 1e-3 and the capture band 0.05.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/contact_body.h"
#include "contact/detection_tolerances.h"
#include "contact/node_face.h"

namespace {

using lfem::ContactBody;
using lfem::NodeCandidate;
using lfem::Vec3;

struct Seam {
    std::vector<double> face_x{0, 0, 0, 1, 0, 0.02, 1, 1, 0, 0, 1, 0};
    std::vector<uint32_t> triangles{0, 1, 2, 0, 2, 3};
    std::vector<double> normals;
    std::vector<double> node_start, node_end;
    uint32_t no_triangles[2] = {0, 0};
    ContactBody face, node;

    Seam(const Vec3& start, const Vec3& end, double dent = 0.02) {
        face_x[5] = dent;  // v1's height
        for (int t = 0; t < 2; ++t) {  // a static body's unit normals, as made when its mesh is added
            const uint32_t* q = &triangles[3 * t];
            const Vec3 a = lfem::position(face_x.data(), q[0]);
            const Vec3 n = (lfem::position(face_x.data(), q[1]) - a).cross(lfem::position(face_x.data(), q[2]) - a).normalized();
            normals.insert(normals.end(), {n[0], n[1], n[2]});
        }
        face.moves = false;
        face.triangles = triangles.data();
        face.triangle_count = 2;
        face.total_nodes = 4;
        face.face_normals = normals.data();
        face.x_start = face.x = face_x.data();
        face.edge_length = 1.0;
        face.slot = 1;
        node_start = {start[0], start[1], start[2]};
        node_end = {end[0], end[1], end[2]};
        node.total_nodes = 1;
        node.node_triangle_begin = no_triangles;  // no surface of its own around it
        node.x_start = node_start.data();
        node.x = node_end.data();
        node.edge_length = 1.0;
    }

    // Face t tested for the node, c holding what the faces tested before it found.
    lfem::Outside test(uint32_t t, NodeCandidate& c) const {
        Vec3 down(0, 0, -1);  // the node's surface faces the floor
        uint8_t known = 1;
        const lfem::NodeNormal normal{node, 0, &down, &known};
        const double allowance = lfem::kResidualDepth;  // a pair held last step with no residual
        return lfem::test_node_triangle(node, 0, normal, face, t, nullptr, allowance, nullptr, lfem::NodeSlots{c});
    }

    // Both faces tested, as the narrow phase tests a node's candidates: the face that holds it.
    NodeCandidate best() const {
        NodeCandidate c;
        for (uint32_t t = 0; t < 2; ++t) test(t, c);
        return c;
    }
};

// Starting 1e-9 in front of T1's plane but over T0 (x - y = 0.02: outside T1 by its weight
// -0.02, past the edge tolerance 0.01), 4e-4 behind T0's plane (within the allowance), and ending
// over T1 (weights 0.45, 0.45, 0.1) 1e-5 behind it. T0 sees its end over T1, outside itself; T1
// sees a crossing of its plane where the path started, outside itself. The node is at the
// surface all the way and must stay held.
TEST(NodeFace, ANodeSlidingAcrossASharedEdgeIsHeldByTheFaceItSlidOnto) {
    const Seam seam(Vec3(0.51, 0.49, 1e-9), Vec3(0.45, 0.55, -1e-5));
    const NodeCandidate c = seam.best();
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.triangle, 1u);
    EXPECT_NEAR(c.gap, -1e-5, 1e-12);  // T1 is the plane z = 0
    // Its point: the end's projection, weights (0.45, 0.45, 0.1) on (v0, v2, v3).
    EXPECT_NEAR(c.w[0], 0.45, 1e-12);
    EXPECT_NEAR(c.w[1], 0.45, 1e-12);
    EXPECT_NEAR(c.w[2], 0.10, 1e-12);
}

// A node that starts 0.1 in front of T1 beside the square (x = -0.5) and ends 0.1 behind it
// over the square has passed the plane outside the triangle (at x = -0.1): it came from the
// side, under the edge, and T1 must not take it for a node at its surface, although its end
// projects inside T1.
TEST(NodeFace, ANodeThatPassesThePlaneBesideTheFaceIsNotTaken) {
    const Seam seam(Vec3(-0.5, 0.5, 0.1), Vec3(0.3, 0.5, -0.1));
    EXPECT_FALSE(seam.best().found);
}

// On the flat square (no dent), a node resting 1e-6 behind it at (0.45, 0.55) is held by T1
// (weights 0.45, 0.45, 0.1). Tested next, T0 lies in the same plane at the same depth, so it is
// no better; its point is outside it, T0's weight of v1 being x - y = -0.1. The test must say so
// (the narrow phase then skips T0 while the node rests): by the margin that weight lacks for the
// edge tolerance, 0.1 - 0.01, over T0's smallest height, 1 / sqrt(2), and T1 must stay the face.
TEST(NodeFace, AFaceNoBetterThanTheOneHeldIsReportedOutsideToBeSkipped) {
    const Seam seam(Vec3(0.45, 0.55, -1e-6), Vec3(0.45, 0.55, -1e-6), 0.0);
    NodeCandidate c;
    EXPECT_EQ(seam.test(1, c).margin, 0.0);  // taken: nothing to skip
    ASSERT_TRUE(c.found);
    ASSERT_EQ(c.triangle, 1u);
    const lfem::Outside out = seam.test(0, c);
    EXPECT_NEAR(out.margin, 0.1 - lfem::kEdgeTolerance, 1e-12);
    EXPECT_NEAR(out.height, 1.0 / std::sqrt(2.0), 1e-12);
    EXPECT_EQ(c.triangle, 1u);
    EXPECT_NEAR(c.w[2], 0.1, 1e-12);
}

}  // namespace
