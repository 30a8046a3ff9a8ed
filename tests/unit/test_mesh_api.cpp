// The C functions of lfem.h's "Meshes" section: argument checks, out untouched on failure,
// read-only views, rigid motions.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lfem.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

// A sentinel that a failed call must leave in *out.
lfem_mesh* const kUntouched = reinterpret_cast<lfem_mesh*>(0x1234);

void expect_failure(lfem_status status, lfem_status expected, lfem_mesh* out) {
    EXPECT_EQ(status, expected) << lfem_last_error();
    EXPECT_EQ(out, kUntouched);
    EXPECT_STRNE(lfem_last_error(), "");
}

std::vector<double> positions_of(const lfem_mesh* m) {
    const double* p = lfem_mesh_get_positions(m);
    return std::vector<double>(p, p + 3 * std::size_t(lfem_mesh_get_node_count(m)));
}

lfem_mesh* make_box() {
    const double size[3] = {1.0, 0.5, 0.25};
    const uint32_t cells[3] = {2, 2, 1};
    lfem_mesh* m = nullptr;
    EXPECT_EQ(lfem_mesh_create_box(size, cells, &m), LFEM_OK);
    return m;
}

TEST(MeshApi, CreateEveryShape) {
    lfem_mesh* m = make_box();
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(lfem_mesh_get_node_count(m), 3u * 3u * 2u);
    EXPECT_EQ(lfem_mesh_get_tet_count(m), 6u * 4u);
    EXPECT_NE(lfem_mesh_get_positions(m), nullptr);
    EXPECT_NE(lfem_mesh_get_tets(m), nullptr);
    lfem_mesh_destroy(m);

    m = nullptr;
    EXPECT_EQ(lfem_mesh_create_cylinder(0.5, 1.0, 8, 2, 3, &m), LFEM_OK);
    EXPECT_EQ(lfem_mesh_get_tet_count(m), 3u * 8u * 3u * 3u);
    lfem_mesh_destroy(m);

    m = nullptr;
    EXPECT_EQ(lfem_mesh_create_cup(0.5, 1.0, 0.1, 0.2, 12, 4, &m), LFEM_OK);
    EXPECT_GT(lfem_mesh_get_tet_count(m), 0u);
    lfem_mesh_destroy(m);

    m = nullptr;
    EXPECT_EQ(lfem_mesh_create_hammer(0.3, 0.04, 0.16, 0.06, 0.02, &m), LFEM_OK);
    EXPECT_GT(lfem_mesh_get_tet_count(m), 0u);
    lfem_mesh_destroy(m);

    if (!LFEM_WITH_IO) return;  // no Gmsh reader in this build (test_build_options.cpp)
    m = nullptr;
    const std::string cube = std::string(LFEM_TEST_DATA_DIR) + "/cube_v41.msh";
    EXPECT_EQ(lfem_mesh_load_gmsh(cube.c_str(), &m), LFEM_OK);
    EXPECT_EQ(lfem_mesh_get_node_count(m), 8u);
    EXPECT_EQ(lfem_mesh_get_tet_count(m), 5u);
    lfem_mesh_destroy(m);
}

TEST(MeshApi, NullMeshGettersAndDestroy) {
    EXPECT_EQ(lfem_mesh_get_node_count(nullptr), 0u);
    EXPECT_EQ(lfem_mesh_get_tet_count(nullptr), 0u);
    EXPECT_EQ(lfem_mesh_get_positions(nullptr), nullptr);
    EXPECT_EQ(lfem_mesh_get_tets(nullptr), nullptr);
    lfem_mesh_destroy(nullptr);
}

TEST(MeshApi, BadArgumentsLeaveOutUntouched) {
    const double size[3] = {1, 1, 1};
    const uint32_t cells[3] = {1, 1, 1};
    const double nan_size[3] = {1, NAN, 1};
    const uint32_t no_cells[3] = {1, 1, 0};
    lfem_mesh* out = kUntouched;
    expect_failure(lfem_mesh_create_box(nullptr, cells, &out), LFEM_INVALID_ARGUMENT, out);
    expect_failure(lfem_mesh_create_box(size, nullptr, &out), LFEM_INVALID_ARGUMENT, out);
    EXPECT_EQ(lfem_mesh_create_box(size, cells, nullptr), LFEM_INVALID_ARGUMENT);
    expect_failure(lfem_mesh_create_box(nan_size, cells, &out), LFEM_INVALID_ARGUMENT, out);
    EXPECT_NE(std::string(lfem_last_error()).find("lfem_mesh_create_box: size[1]"),
              std::string::npos)
        << lfem_last_error();
    expect_failure(lfem_mesh_create_box(size, no_cells, &out), LFEM_INVALID_ARGUMENT, out);

    expect_failure(lfem_mesh_create_cylinder(INFINITY, 1, 8, 1, 1, &out), LFEM_INVALID_ARGUMENT,
                   out);
    expect_failure(lfem_mesh_create_cylinder(1, 1, 2, 1, 1, &out), LFEM_INVALID_ARGUMENT, out);
    EXPECT_EQ(lfem_mesh_create_cylinder(1, 1, 8, 1, 1, nullptr), LFEM_INVALID_ARGUMENT);

    expect_failure(lfem_mesh_create_cup(1, 1, 1, 0.1, 8, 1, &out), LFEM_INVALID_ARGUMENT, out);
    expect_failure(lfem_mesh_create_cup(1, 1, 0.1, NAN, 8, 1, &out), LFEM_INVALID_ARGUMENT, out);
    EXPECT_EQ(lfem_mesh_create_cup(1, 1, 0.1, 0.1, 8, 1, nullptr), LFEM_INVALID_ARGUMENT);

    expect_failure(lfem_mesh_create_hammer(1, 0.1, 0.5, 0.2, -0.05, &out), LFEM_INVALID_ARGUMENT,
                   out);
    expect_failure(lfem_mesh_create_hammer(1, 0.1, 0.5, 0.2, 1e-5, &out), LFEM_INVALID_ARGUMENT,
                   out);
    EXPECT_EQ(lfem_mesh_create_hammer(1, 0.1, 0.5, 0.2, 0.05, nullptr), LFEM_INVALID_ARGUMENT);

    expect_failure(lfem_mesh_load_gmsh(nullptr, &out), LFEM_INVALID_ARGUMENT, out);
    EXPECT_EQ(lfem_mesh_load_gmsh("x.msh", nullptr), LFEM_INVALID_ARGUMENT);
    if (!LFEM_WITH_IO) return;  // no Gmsh reader in this build (test_build_options.cpp)
    const std::string bad = std::string(LFEM_TEST_DATA_DIR) + "/bad_unknown_tag.msh";
    expect_failure(lfem_mesh_load_gmsh(bad.c_str(), &out), LFEM_IO_ERROR, out);
    EXPECT_NE(std::string(lfem_last_error()).find("bad_unknown_tag.msh:14:"), std::string::npos)
        << lfem_last_error();
}

TEST(MeshApi, Translate) {
    lfem_mesh* m = make_box();
    const std::vector<double> before = positions_of(m);
    const double offset[3] = {1.0, -2.0, 0.5};
    ASSERT_EQ(lfem_mesh_translate(m, offset), LFEM_OK);
    const std::vector<double> after = positions_of(m);
    for (std::size_t i = 0; i < after.size(); ++i) EXPECT_EQ(after[i], before[i] + offset[i % 3]);
    lfem_mesh_destroy(m);
}

TEST(MeshApi, TranslateAndRotateRefuseBadArguments) {
    lfem_mesh* m = make_box();
    const std::vector<double> before = positions_of(m);
    const double offset[3] = {1, 0, 0}, nan_offset[3] = {0, NAN, 0}, huge[3] = {1.7e308, 0, 0};
    const double axis[3] = {0, 0, 1}, zero[3] = {0, 0, 0}, inf_axis[3] = {INFINITY, 0, 0};
    EXPECT_EQ(lfem_mesh_translate(nullptr, offset), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_mesh_translate(m, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_mesh_translate(m, nan_offset), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_mesh_rotate(nullptr, axis, 1.0), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_mesh_rotate(m, nullptr, 1.0), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_mesh_rotate(m, zero, 1.0), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("axis"), std::string::npos);
    EXPECT_EQ(lfem_mesh_rotate(m, inf_axis, 1.0), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_mesh_rotate(m, axis, NAN), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(positions_of(m), before);

    // 1.7e308 + x is still finite, twice that is not: the second move is refused whole.
    ASSERT_EQ(lfem_mesh_translate(m, huge), LFEM_OK);
    const std::vector<double> far = positions_of(m);
    EXPECT_EQ(lfem_mesh_translate(m, huge), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(positions_of(m), far);
    lfem_mesh_destroy(m);
}

TEST(MeshApi, RotateQuarterTurnAboutZ) {
    lfem_mesh* m = make_box();
    const std::vector<double> before = positions_of(m);
    const double axis[3] = {0, 0, 2.5};  // any length
    ASSERT_EQ(lfem_mesh_rotate(m, axis, kPi / 2), LFEM_OK);
    const std::vector<double> after = positions_of(m);
    for (std::size_t n = 0; n < after.size(); n += 3) {  // (x, y, z) -> (-y, x, z)
        EXPECT_NEAR(after[n], -before[n + 1], 1e-15);
        EXPECT_NEAR(after[n + 1], before[n], 1e-15);
        EXPECT_EQ(after[n + 2], before[n + 2]);
    }
    lfem_mesh_destroy(m);
}

TEST(MeshApi, RotationKeepsDistancesAndAxis) {
    lfem_mesh* m = make_box();
    const std::vector<double> before = positions_of(m);
    const double axis[3] = {1, 1, 1};
    ASSERT_EQ(lfem_mesh_rotate(m, axis, 2 * kPi / 3), LFEM_OK);  // cycles x -> y -> z -> x
    const std::vector<double> after = positions_of(m);
    for (std::size_t n = 0; n < after.size(); n += 3) {
        EXPECT_NEAR(after[n + 1], before[n], 1e-15);
        EXPECT_NEAR(after[n + 2], before[n + 1], 1e-15);
        EXPECT_NEAR(after[n], before[n + 2], 1e-15);
    }
    lfem_mesh_destroy(m);
}

TEST(MeshApi, FullTurnReturnsToTheStart) {
    const double axes[][3] = {
        {0, 0, 1}, {1, 0, 0}, {0.3, -0.7, 0.2}, {1e-200, 3e-200, -2e-200}, {1e200, -1e200, 5e199}};
    for (const auto& axis : axes) {
        lfem_mesh* m = make_box();
        const double offset[3] = {3.0, -1.0, 2.0};  // away from the origin
        ASSERT_EQ(lfem_mesh_translate(m, offset), LFEM_OK);
        const std::vector<double> before = positions_of(m);
        ASSERT_EQ(lfem_mesh_rotate(m, axis, 2 * kPi), LFEM_OK);
        const std::vector<double> after = positions_of(m);
        for (std::size_t i = 0; i < after.size(); ++i) EXPECT_NEAR(after[i], before[i], 1e-12);
        lfem_mesh_destroy(m);
    }
}

}  // namespace
