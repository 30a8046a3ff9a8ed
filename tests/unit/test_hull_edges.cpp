// The edges of a convex hull shape (contact/hull_edges.h), against the hulls' known edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>

#include "contact/hull_edges.h"

namespace lfem {
namespace {

RigidShape hull_of(const std::vector<double>& points) {
    RigidShape s;
    s.type = ShapeType::convex_hull;
    s.points = points;
    compute_hull_edges(s);
    return s;
}

std::set<std::array<uint32_t, 2>> edges_of(const RigidShape& s) {
    std::set<std::array<uint32_t, 2>> out;
    for (std::size_t e = 0; e < s.hull_edges.size(); e += 2) out.insert({s.hull_edges[e], s.hull_edges[e + 1]});
    return out;
}

// A box's eight corners (corner i at (+-1, +-2, +-3) by its bits), in a shuffled order, with
// points that are not corners: the centre, points inside, the middles of faces and of edges.
// The hull's edges are the box's twelve (two corners differing in one bit), not the diagonals
// of its split faces, each with the sum of its two faces' normals (the two axes' directions).
TEST(HullEdges, ABoxsTwelveEdgesAmongPointsThatAreNotCorners) {
    std::vector<double> p;
    const auto corner = [](int i) {
        return std::array<double, 3>{i & 1 ? 1.0 : -1.0, i & 2 ? 2.0 : -2.0, i & 4 ? 3.0 : -3.0};
    };
    const int order[8] = {5, 2, 7, 0, 3, 6, 1, 4};
    p.insert(p.end(), {0.0, 0.0, 0.0, 0.5, -1.0, 2.0, 0.0, 0.0, 3.0, 1.0, 0.0, 0.0, 1.0, 2.0, 0.0});
    const uint32_t first = uint32_t(p.size() / 3);
    for (int i : order)
        for (double x : corner(i)) p.push_back(x);
    const RigidShape s = hull_of(p);
    std::set<std::array<uint32_t, 2>> expected;
    for (int a = 0; a < 8; ++a)
        for (int b = a + 1; b < 8; ++b)
            if (__builtin_popcount(unsigned(order[a] ^ order[b])) == 1) expected.insert({first + a, first + b});
    EXPECT_EQ(edges_of(s), expected);
    for (std::size_t e = 0; e < s.hull_edges.size() / 2; ++e) {
        const double* a = &s.points[3 * s.hull_edges[2 * e]];
        const double* b = &s.points[3 * s.hull_edges[2 * e + 1]];
        for (int d = 0; d < 3; ++d) {
            // Along the edge's axis: 0; across it, the side both corners share (a unit normal).
            const double expected_out = a[d] == b[d] ? (a[d] > 0 ? 1.0 : -1.0) : 0.0;
            EXPECT_NEAR(s.hull_edge_out[3 * e + d], expected_out, 1e-12) << "edge " << e << " axis " << d;
        }
    }
}

// Points on a sphere: every triangle of their hull has its corners on it and no face is flat
// with another, so the hull has 3V - 6 edges (Euler, all faces triangles), each joining two
// of the points; points inside add none.
TEST(HullEdges, PointsOnASphereMakeATriangulatedHull) {
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    std::vector<double> p;
    const int on_sphere = 60;
    for (int i = 0; i < on_sphere; ++i) {
        double x = normal(random), y = normal(random), z = normal(random);
        const double r = std::sqrt(x * x + y * y + z * z);
        p.insert(p.end(), {x / r, y / r, z / r});
    }
    for (int i = 0; i < 40; ++i) p.insert(p.end(), {0.3 * normal(random) / 4, 0.3 * normal(random) / 4, 0.1});
    const RigidShape s = hull_of(p);
    EXPECT_EQ(s.hull_edges.size() / 2, std::size_t(3 * on_sphere - 6));
    for (uint32_t v : s.hull_edges) EXPECT_LT(v, uint32_t(on_sphere));
}

// Points without volume (the shim refuses them; a malformed checkpoint may hold them) give no
// edges, as do shapes other than hulls.
TEST(HullEdges, NoEdgesWithoutVolumeOrForOtherShapes) {
    EXPECT_TRUE(hull_of({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0}).hull_edges.empty());
    EXPECT_TRUE(hull_of({0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}).hull_edges.empty());
    EXPECT_TRUE(hull_of({0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}).hull_edges.empty());
    EXPECT_TRUE(hull_of({std::nan(""), 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}).hull_edges.empty());
    RigidShape box;
    box.type = ShapeType::box;
    compute_hull_edges(box);
    EXPECT_TRUE(box.hull_edges.empty());
}

}  // namespace
}  // namespace lfem
