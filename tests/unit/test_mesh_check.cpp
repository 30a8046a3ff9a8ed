// check_tet_mesh: a valid mesh passes, each class of defect is refused with Status::invalid_mesh
// and a message naming the offending tet or node.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/error.h"
#include "mesh/mesh_check.h"

namespace lfem {
namespace {

// Two positive tets sharing the triangle (0, 1, 2): one above it, one below.
struct TwoTets {
    std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, -1};
    std::vector<uint32_t> tets = {0, 1, 2, 3, 0, 2, 1, 4};
};

void check(const std::vector<double>& positions, const std::vector<uint32_t>& tets) {
    check_tet_mesh(positions.data(), uint32_t(positions.size() / 3), tets.data(),
                   uint32_t(tets.size() / 4));
}

void expect_refused(const std::vector<double>& positions, const std::vector<uint32_t>& tets,
                    const std::string& fragment) {
    try {
        check(positions, tets);
        ADD_FAILURE() << "accepted; expected: " << fragment;
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::invalid_mesh);
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

TEST(MeshCheck, ValidMeshPasses) {
    const TwoTets m;
    EXPECT_NO_THROW(check(m.positions, m.tets));
}

TEST(MeshCheck, IndexOutOfRange) {
    TwoTets m;
    m.tets[6] = 5;
    expect_refused(m.positions, m.tets, "tet 1 refers to node 5 but the mesh has 5 nodes");
}

TEST(MeshCheck, RepeatedNode) {
    TwoTets m;
    m.tets[7] = 0;
    expect_refused(m.positions, m.tets, "tet 1 repeats node 0");
}

TEST(MeshCheck, InvertedTet) {
    TwoTets m;
    std::swap(m.tets[5], m.tets[6]);
    expect_refused(m.positions, m.tets, "tet 1 is inverted");
}

TEST(MeshCheck, ZeroVolumeTet) {
    TwoTets m;
    m.positions[14] = 0.0;  // node 4 moved into the plane of triangle (0, 1, 2)
    expect_refused(m.positions, m.tets, "tet 1 has zero volume");
}

TEST(MeshCheck, NegligibleVolumeIsRelative) {
    // Height 1e-13 over a unit triangle: 6V / L^3 ~ 1e-13, flat to rounding precision.
    TwoTets m;
    m.positions[14] = -1e-13;
    expect_refused(m.positions, m.tets, "tet 1 has zero volume");
    // A micrometre tet of good shape has a tiny volume (~1e-19 m^3) but is perfectly valid.
    std::vector<double> small(m.positions);
    for (double& x : small) x *= 1e-6;
    small[14] = -1e-6;
    EXPECT_NO_THROW(check(small, m.tets));
}

TEST(MeshCheck, UnusedNode) {
    TwoTets m;
    m.positions.insert(m.positions.end(), {5, 5, 5});
    expect_refused(m.positions, m.tets, "node 5 belongs to no tet");
}

TEST(MeshCheck, EmptyMesh) { expect_refused({}, {}, "no tets"); }

TEST(MeshCheck, OverflowingVolume) {
    TwoTets m;
    for (double& x : m.positions) x *= 1e200;
    expect_refused(m.positions, m.tets, "overflows");
}

}  // namespace
}  // namespace lfem
