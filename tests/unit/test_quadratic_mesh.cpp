// Meshes of 10-node tets: made from linear ones (every edge gets one node, at its middle,
// shared by the tets around it: checked against Euler's formula), read from Gmsh (type 11, in
// formats 2.2 and 4.1, with Gmsh's own edge order turned into lfem's), checked for conformity,
// their boundary as 6-node faces and 4 flat triangles each, re-ordered for locality and written
// to VTK as cell type 24. Facts are computed here independently of the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/quadratic_tet_nodes.h"
#include "mesh/boundary.h"
#include "mesh/gmsh_reader.h"
#include "mesh/mesh_builders.h"
#include "mesh/mesh_check.h"
#include "mesh/node_ordering.h"
#include "mesh/quadratic_mesh.h"
#include "mesh/surface.h"
#include "test_mesh_helpers.h"

namespace lfem {
namespace {

std::string data(const std::string& name) { return std::string(LFEM_TEST_DATA_DIR) + "/" + name; }

TetMesh box(uint32_t nx, uint32_t ny, uint32_t nz) {
    const double size[3] = {1.0, 0.5, 2.0};
    const uint32_t cells[3] = {nx, ny, nz};
    return build_box(size, cells);
}

// The corner tets of a quadratic mesh as a linear mesh.
TetMesh corners_of(const TetMesh& q) {
    TetMesh m;
    m.positions = q.positions;
    for (uint32_t t = 0; t < q.tet_count(); ++t)
        m.tets.insert(m.tets.end(), &q.tets[10 * std::size_t(t)], &q.tets[10 * std::size_t(t)] + 4);
    return m;
}

// Every mid-edge node of every tet sits at the middle of its edge (to `tolerance`).
void expect_mid_nodes_at_middles(const TetMesh& q, double tolerance) {
    for (uint32_t t = 0; t < q.tet_count(); ++t)
        for (int e = 0; e < 6; ++e) {
            const uint32_t* tet = &q.tets[10 * std::size_t(t)];
            const double* a = test::node(q, tet[kQuadraticTetEdges[e][0]]);
            const double* b = test::node(q, tet[kQuadraticTetEdges[e][1]]);
            const double* m = test::node(q, tet[4 + e]);
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(m[k], 0.5 * (a[k] + b[k]), tolerance) << "tet " << t << " edge " << e;
        }
}

// The distinct edges of a linear mesh, by their sorted corner pairs.
std::size_t edge_count(const TetMesh& m) {
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (uint32_t t = 0; t < m.tet_count(); ++t)
        for (const auto& e : kQuadraticTetEdges) {
            const uint32_t a = m.tets[4 * std::size_t(t) + e[0]], b = m.tets[4 * std::size_t(t) + e[1]];
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    return edges.size();
}

TEST(QuadraticMesh, EveryEdgeGetsOneNodeAtItsMiddle) {
    const TetMesh linear = box(3, 2, 4);
    const TetMesh q = make_quadratic(linear);
    EXPECT_EQ(q.nodes_per_tet, 10u);
    ASSERT_EQ(q.tet_count(), linear.tet_count());
    // A mesh of a ball: V - E + F - T = 1, with F = (4 T + boundary triangles) / 2.
    const std::size_t boundary = extract_boundary_triangles(linear.tets.data(), linear.tet_count()).size() / 3;
    const std::size_t faces = (4 * std::size_t(linear.tet_count()) + boundary) / 2;
    const std::size_t edges = linear.node_count() + faces - linear.tet_count() - 1;
    EXPECT_EQ(edges, edge_count(linear));
    EXPECT_EQ(q.node_count(), linear.node_count() + edges);
    for (uint32_t t = 0; t < q.tet_count(); ++t)  // the corners keep their indices
        for (int k = 0; k < 4; ++k) EXPECT_EQ(q.tets[10 * t + k], linear.tets[4 * t + k]);
    expect_mid_nodes_at_middles(q, 0.0);
    EXPECT_NO_THROW(check_tet_mesh(q.positions.data(), q.node_count(), q.tets.data(), q.tet_count(), 10));
    EXPECT_NEAR(test::mesh_volume(corners_of(q)), 1.0, 1e-14);
    try {
        make_quadratic(q);
        ADD_FAILURE() << "a quadratic mesh was made quadratic again";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::invalid_argument);
    }
}

void expect_topology_refused(const TetMesh& q, const char* fragment) {
    try {
        check_tet_mesh(q.positions.data(), q.node_count(), q.tets.data(), q.tet_count(), 10);
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::invalid_mesh);
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(QuadraticMesh, NonConformingMidEdgeNodesAreRefused) {
    const TetMesh q = make_quadratic(box(1, 1, 1));
    // Tet 1 gets a node of its own on an edge it shares with tet 0.
    TetMesh split = q;
    const std::array<uint32_t, 4> t0 = {q.tets[0], q.tets[1], q.tets[2], q.tets[3]};
    int shared = -1;
    for (int e = 0; e < 6 && shared < 0; ++e) {
        const uint32_t a = q.tets[10 + kQuadraticTetEdges[e][0]], b = q.tets[10 + kQuadraticTetEdges[e][1]];
        if (std::count(t0.begin(), t0.end(), a) && std::count(t0.begin(), t0.end(), b)) shared = e;
    }
    ASSERT_GE(shared, 0);
    const double* old = test::node(q, q.tets[10 + 4 + shared]);
    split.positions.insert(split.positions.end(), old, old + 3);
    split.tets[10 + 4 + shared] = split.node_count() - 1;
    expect_topology_refused(split, "not conforming");
    // Two tets sharing the face (1, 2, 3): a node can be a corner or a mid-edge node, not both,
    // and a mid-edge node sits on one edge.
    TetMesh two;
    two.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    two.tets = {0, 1, 2, 3, 4, 3, 2, 1};
    const TetMesh q2 = make_quadratic(two);
    const auto refused = [](const TetMesh& m, const char* fragment) {
        try {
            check_quadratic_topology(m.tets.data(), m.tet_count(), m.node_count());
            ADD_FAILURE() << "accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.status(), Status::invalid_mesh);
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    EXPECT_NO_THROW(check_quadratic_topology(q2.tets.data(), q2.tet_count(), q2.node_count()));
    TetMesh corner = q2;
    corner.tets[10 + mid_edge_node(0, 1)] = 0;  // the edge (4, 3) of tet 1 gets corner 0 of tet 0
    refused(corner, "node 0 is a corner of one tet and the mid-edge node of the edge between nodes 3 and 4");
    TetMesh twice = q2;
    twice.tets[10 + mid_edge_node(0, 2)] = twice.tets[10 + mid_edge_node(0, 1)];  // edges (4,3) and (4,2)
    refused(twice, "is the mid-edge node of both");
}

#if LFEM_WITH_IO
// The cube files (tests/data/cube10_v22.msh, cube10_v41.msh): one Gmsh mesh of 10-node tets
// in both formats; in the 2.2 file its first tet is reversed.
TEST(QuadraticMesh, GmshType11InBothFormats) {
    const TetMesh a = read_gmsh(data("cube10_v22.msh"));
    const TetMesh b = read_gmsh(data("cube10_v41.msh"));
    EXPECT_EQ(a.nodes_per_tet, 10u);
    EXPECT_GT(a.tet_count(), 10u);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.tets, b.tets);  // the reversed tet turned back, its mid-edge nodes with it
    // Gmsh puts the mid-edge nodes of a box on its straight edges: with Gmsh's order of the
    // last two edges kept, each of them would be off by half an edge.
    expect_mid_nodes_at_middles(a, 1e-12);
    EXPECT_GT(test::smallest_six_volume(corners_of(a)), 0.0);
    EXPECT_NEAR(test::mesh_volume(corners_of(a)), 1.0, 1e-12);
    EXPECT_NO_THROW(check_tet_mesh(a.positions.data(), a.node_count(), a.tets.data(), a.tet_count(), 10));
}

TEST(QuadraticMesh, GmshFileMixingTetKindsIsRefused) {
    const std::string path = ::testing::TempDir() + "lfem_mixed_tets.msh";
    {
        FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n"
                   "$EndNodes\n$Elements\n2\n1 4 0 1 2 3 4\n2 11 0 1 2 3 5 1 2 3 4 5 1\n$EndElements\n",
                   f);
        std::fclose(f);
    }
    try {
        read_gmsh(path);
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::io_error);
        EXPECT_NE(std::string(e.what()).find(":15: the file mixes 4-node and 10-node"), std::string::npos) << e.what();
    }
    std::remove(path.c_str());
}

#endif  // LFEM_WITH_IO

TEST(QuadraticMesh, BoundaryAsSixNodeFacesAndFourFlatTriangles) {
    const TetMesh linear = box(2, 2, 3);
    const TetMesh q = make_quadratic(linear);
    const std::vector<uint32_t> tri = extract_boundary_triangles(linear.tets.data(), linear.tet_count());
    const std::vector<uint32_t> faces = extract_quadratic_boundary(q.tets.data(), q.tet_count());
    ASSERT_EQ(faces.size(), 2 * tri.size());
    for (std::size_t f = 0; f < tri.size() / 3; ++f) {
        for (int i = 0; i < 3; ++i) EXPECT_EQ(faces[6 * f + i], tri[3 * f + i]);  // same faces, same order
        for (int i = 0; i < 3; ++i) {  // the mid-edge node of ab, bc, ca
            const double* a = test::node(q, faces[6 * f + i]);
            const double* b = test::node(q, faces[6 * f + (i + 1) % 3]);
            const double* m = test::node(q, faces[6 * f + 3 + i]);
            for (int k = 0; k < 3; ++k) EXPECT_EQ(m[k], 0.5 * (a[k] + b[k]));
        }
    }
    // The flat triangles close the same surface, consistently oriented, around the same volume.
    const std::vector<uint32_t> flat = split_quadratic_faces(faces);
    ASSERT_EQ(flat.size(), 4 * tri.size());
    const test::SurfaceFacts s = test::surface_facts(q, flat), l = test::surface_facts(linear, tri);
    EXPECT_TRUE(s.closed);
    EXPECT_TRUE(s.consistent);
    EXPECT_EQ(s.euler, 2);
    EXPECT_NEAR(s.enclosed_volume, 1.0, 1e-14);
    EXPECT_NEAR(s.area, l.area, 1e-14);
}

TEST(QuadraticMesh, LocalityOrderKeepsEveryMidEdgeNodeOnItsEdge) {
    TetMesh q = make_quadratic(box(3, 2, 2));
    const LocalityOrder o = order_for_locality(q.positions.data(), q.node_count(), q.tets.data(), q.tet_count(), 10);
    TetMesh r;
    r.nodes_per_tet = 10;
    r.positions = o.positions;
    r.tets = o.tets;
    ASSERT_EQ(r.tet_count(), q.tet_count());
    expect_mid_nodes_at_middles(r, 0.0);
    const TetMesh rc = corners_of(r), qc = corners_of(q);
    for (uint32_t e = 0; e < r.tet_count(); ++e) {
        EXPECT_EQ(test::tet_six_volume(rc, e), test::tet_six_volume(qc, o.old_of_tet[e]));  // orientation kept
        std::set<uint32_t> given, now;
        for (int a = 0; a < 10; ++a) {
            given.insert(o.node_of_old[q.tets[10 * o.old_of_tet[e] + a]]);
            now.insert(r.tets[10 * e + a]);
        }
        EXPECT_EQ(given, now);
    }
    // Numbered otherwise (nodes reversed), the same mesh comes out.
    TetMesh reversed = q;
    const uint32_t n = q.node_count();
    for (uint32_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) reversed.positions[3 * (n - 1 - i) + k] = q.positions[3 * i + k];
    for (uint32_t& v : reversed.tets) v = n - 1 - v;
    const LocalityOrder o2 =
        order_for_locality(reversed.positions.data(), n, reversed.tets.data(), reversed.tet_count(), 10);
    EXPECT_EQ(o2.positions, o.positions);
    EXPECT_EQ(o2.tets, o.tets);
}

TEST(QuadraticMesh, PermutedCornersCarryTheirEdges) {
    TetMesh q = make_quadratic(box(1, 1, 1));
    const int from[4] = {2, 0, 3, 1};
    uint32_t tet[10];
    std::copy_n(q.tets.data(), 10, tet);
    permute_corners(tet, 10, from);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(tet[k], q.tets[from[k]]);
    for (int e = 0; e < 6; ++e) {
        const int i = kQuadraticTetEdges[e][0], j = kQuadraticTetEdges[e][1];
        EXPECT_EQ(tet[4 + e], q.tets[mid_edge_node(from[i], from[j])]);
    }
}

}  // namespace
}  // namespace lfem
