// Node and tet order for locality (src/mesh/node_ordering.h): the reordered mesh is the same
// mesh (every tet keeps its nodes, as material points, and its orientation), a box numbered
// plane by plane keeps its node order, and the caller-to-internal maps are checked as
// permutations (what a damaged checkpoint relies on).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "mesh/mesh_builders.h"
#include "mesh/node_ordering.h"
#include "test_mesh_helpers.h"

namespace lfem {
namespace {

TetMesh box(uint32_t nx, uint32_t ny, uint32_t nz) {
    const double size[3] = {1.0, 0.5, 2.0};
    const uint32_t cells[3] = {nx, ny, nz};
    return build_box(size, cells);
}

TEST(NodeOrdering, ReorderedMeshIsTheSameMeshWithItsOrientation) {
    const TetMesh m = box(4, 3, 5);
    const LocalityOrder o = order_for_locality(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count());
    TetMesh r;
    r.positions = o.positions;
    r.tets = o.tets;
    std::set<uint32_t> seen_tets;
    for (uint32_t e = 0; e < r.tet_count(); ++e) {
        const uint32_t old = o.old_of_tet[e];
        EXPECT_TRUE(seen_tets.insert(old).second);
        // Same node set (through the node map), each node at its given position.
        std::array<uint32_t, 4> given, now;
        for (int a = 0; a < 4; ++a) {
            given[a] = o.node_of_old[m.tets[4 * old + a]];
            now[a] = r.tets[4 * e + a];
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(r.positions[3 * given[a] + k], m.positions[3 * m.tets[4 * old + a] + k]);
        }
        std::sort(given.begin(), given.end());
        std::array<uint32_t, 4> sorted = now;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(given, sorted);
        // Turned by an even permutation: same signed volume, bit for bit, lowest node first.
        EXPECT_EQ(test::tet_six_volume(r, e), test::tet_six_volume(m, old));
        EXPECT_EQ(now[0], sorted[0]);
        if (e > 0) {  // sorted by their nodes
            std::array<uint32_t, 4> before = {r.tets[4 * e - 4], r.tets[4 * e - 3], r.tets[4 * e - 2], r.tets[4 * e - 1]};
            std::sort(before.begin(), before.end());
            EXPECT_LT(before, sorted);
        }
    }
    EXPECT_EQ(seen_tets.size(), m.tet_count());
}

// The longest axis (z here) sweeps slowest, the shortest (y) fastest.
TEST(NodeOrdering, SweepsTheLongestAxisSlowest) {
    const TetMesh m = box(4, 3, 5);
    const LocalityOrder o = order_for_locality(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count());
    for (uint32_t i = 1; i < m.node_count(); ++i) {
        const double* a = &o.positions[3 * (i - 1)];
        const double* b = &o.positions[3 * i];
        EXPECT_TRUE(a[2] < b[2] || (a[2] == b[2] && (a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]))))
            << "node " << i;
    }
}

TEST(NodeOrdering, ACubeNumberedPlaneByPlaneKeepsItsNodeOrder) {
    const double size[3] = {1.0, 1.0, 1.0};
    const uint32_t cells[3] = {6, 6, 6};
    const TetMesh m = build_box(size, cells);
    const LocalityOrder o = order_for_locality(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count());
    for (uint32_t i = 0; i < m.node_count(); ++i) EXPECT_EQ(o.node_of_old[i], i);
    Numbering n;
    n.append(o, 0, 0);
    EXPECT_TRUE(n.node_of_api.empty() && n.api_of_node.empty());  // nothing to translate
    EXPECT_TRUE(n.consistent(m.node_count(), m.tet_count()));
}

TEST(NodeOrdering, NumberingChecksItsMapsArePermutations) {
    const TetMesh m = box(2, 2, 2);
    const LocalityOrder o = order_for_locality(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count());
    Numbering n;
    n.append(o, 0, 0);
    n.append(o, m.node_count(), m.tet_count());  // a second mesh block
    const uint32_t nodes = 2 * m.node_count(), count = 2 * m.tet_count();
    ASSERT_TRUE(n.consistent(nodes, count));
    ASSERT_FALSE(n.node_of_api.empty());  // y (the shortest axis) now runs fastest, not x
    for (uint32_t i = 0; i < nodes; ++i) EXPECT_EQ(n.api_node(n.node(i)), i);
    Numbering bad = n;
    bad.api_of_tet[1] = bad.api_of_tet[0];
    EXPECT_FALSE(bad.consistent(nodes, count));
    bad = n;
    bad.api_of_tet[0] = count;
    EXPECT_FALSE(bad.consistent(nodes, count));
    bad = n;
    bad.api_of_node.pop_back();
    EXPECT_FALSE(bad.consistent(nodes, count));
    bad = n;
    std::swap(bad.node_of_api[0], bad.node_of_api[1]);  // no longer the inverse of api_of_node
    EXPECT_FALSE(bad.consistent(nodes, count));
    EXPECT_FALSE(n.consistent(nodes + 1, count));
}

}  // namespace
}  // namespace lfem
