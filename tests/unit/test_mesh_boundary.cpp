// Boundary extraction: outward orientation, deterministic order, closed surfaces, and refusal
// of faces shared by more than two tets or by two tets on the same side.
#include <gtest/gtest.h>

#include <vector>

#include "common/error.h"
#include "mesh/boundary.h"
#include "mesh/mesh_builders.h"
#include "test_mesh_helpers.h"

namespace lfem {
namespace {

TetMesh single_tet() {
    TetMesh m;
    m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    m.tets = {0, 1, 2, 3};
    return m;
}

void expect_invalid_mesh(const std::vector<uint32_t>& tets, const char* fragment) {
    try {
        extract_boundary_triangles(tets.data(), uint32_t(tets.size() / 4));
        ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::invalid_mesh);
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(Boundary, SingleTetFacesPointOutwards) {
    const TetMesh m = single_tet();
    const std::vector<uint32_t> tri = extract_boundary_triangles(m.tets.data(), 1);
    ASSERT_EQ(tri.size(), 12u);
    // The documented order: (0,2,1), (0,1,3), (1,2,3), (0,3,2).
    EXPECT_EQ(tri, (std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2}));
    const double centre[3] = {0.25, 0.25, 0.25};
    for (int f = 0; f < 4; ++f) {
        const double* a = test::node(m, tri[3 * f]);
        const double* b = test::node(m, tri[3 * f + 1]);
        const double* c = test::node(m, tri[3 * f + 2]);
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        const double out[3] = {a[0] - centre[0], a[1] - centre[1], a[2] - centre[2]};
        EXPECT_GT(n[0] * out[0] + n[1] * out[1] + n[2] * out[2], 0.0) << "face " << f;
    }
    const test::SurfaceFacts s = test::surface_facts(m, tri);
    EXPECT_TRUE(s.closed);
    EXPECT_TRUE(s.consistent);
    EXPECT_EQ(s.euler, 2);
    EXPECT_NEAR(s.enclosed_volume, 1.0 / 6.0, 1e-15);
}

TEST(Boundary, SharedFaceIsInterior) {
    TetMesh m = single_tet();
    m.positions.insert(m.positions.end(), {0.3, 0.3, -1});
    m.tets.insert(m.tets.end(), {0, 2, 1, 4});  // below the triangle (0, 1, 2)
    const std::vector<uint32_t> tri = extract_boundary_triangles(m.tets.data(), 2);
    // 8 faces minus the shared pair; first-appearance order: tet 0's, then tet 1's.
    EXPECT_EQ(tri, (std::vector<uint32_t>{0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 2, 4, 2, 1, 4, 0, 4, 1}));
    const test::SurfaceFacts s = test::surface_facts(m, tri);
    EXPECT_TRUE(s.closed);
    EXPECT_EQ(s.euler, 2);
    EXPECT_NEAR(s.enclosed_volume, test::mesh_volume(m), 1e-15);
}

TEST(Boundary, BoxSurface) {
    const double size[3] = {2.0, 1.0, 0.5};
    const uint32_t cells[3] = {4, 3, 2};
    const TetMesh m = build_box(size, cells);
    const std::vector<uint32_t> tri = extract_boundary_triangles(m.tets.data(), m.tet_count());
    EXPECT_EQ(tri.size() / 3, 2u * 2u * (4 * 3 + 3 * 2 + 2 * 4));
    const test::SurfaceFacts s = test::surface_facts(m, tri);
    EXPECT_TRUE(s.closed);
    EXPECT_TRUE(s.consistent);
    EXPECT_EQ(s.euler, 2);
    EXPECT_NEAR(s.enclosed_volume, 1.0, 1e-13);
    // Same input, same output.
    EXPECT_EQ(tri, extract_boundary_triangles(m.tets.data(), m.tet_count()));
}

TEST(Boundary, SparseIndicesGiveTheSameTriangles) {
    // Indices far above the face count take the comparison-sort path instead of the buckets.
    const double size[3] = {1.0, 1.0, 1.0};
    const uint32_t cells[3] = {3, 2, 2};
    const TetMesh m = build_box(size, cells);
    const uint32_t offset = 3000000000u;
    std::vector<uint32_t> far(m.tets);
    for (uint32_t& n : far) n += offset;
    std::vector<uint32_t> expected = extract_boundary_triangles(m.tets.data(), m.tet_count());
    for (uint32_t& n : expected) n += offset;
    EXPECT_EQ(extract_boundary_triangles(far.data(), m.tet_count()), expected);
}

TEST(Boundary, FaceInThreeTetsIsRefused) {
    expect_invalid_mesh({0, 1, 2, 3, 0, 2, 1, 4, 0, 1, 2, 5}, "shared by more than two tets");
}

TEST(Boundary, DuplicateTetIsRefused) {
    expect_invalid_mesh({0, 1, 2, 3, 1, 2, 0, 3}, "lie on the same side");
}

TEST(Boundary, NoTetsNoTriangles) { EXPECT_TRUE(extract_boundary_triangles(nullptr, 0).empty()); }

}  // namespace
}  // namespace lfem
