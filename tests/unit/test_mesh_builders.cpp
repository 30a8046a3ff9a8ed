// Builders: each mesh is checked against facts of its shape, not against printed numbers:
// analytic volume, positive tets, conformity, a closed and outward boundary surface of genus 0
// whose triangles all lie on the shape's surface.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "common/error.h"
#include "mesh/boundary.h"
#include "mesh/mesh_builders.h"
#include "mesh/mesh_check.h"
#include "test_mesh_helpers.h"

namespace lfem {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Inside = std::function<bool(const double p[3])>;

// Area of the regular polygon with `segments` corners on a circle of radius r: the builders'
// round cross-sections are such polygons, so their volumes are exact prism volumes of it.
double polygon_area(double r, int segments) {
    return 0.5 * segments * r * r * std::sin(2.0 * kPi / segments);
}

// Strictly inside the regular polygon (corners at angles 2 pi k / segments, radius r).
bool inside_polygon(double x, double y, double r, int segments) {
    const double apothem = r * std::cos(kPi / segments);
    for (int k = 0; k < segments; ++k) {
        const double a = (2 * k + 1) * kPi / segments;  // outward normal of edge k
        if (x * std::cos(a) + y * std::sin(a) >= apothem) return false;
    }
    return true;
}

// Everything a builder promises, plus: the boundary triangles lie on the shape's surface with
// outward normals (a point just behind each triangle is inside the shape, one just in front
// is outside), which also rules out cracks between non-conforming cells.
void expect_solid(const TetMesh& m, double volume, const Inside& inside, double probe) {
    ASSERT_GT(m.tet_count(), 0u);
    EXPECT_NO_THROW(
        check_tet_mesh(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count()));
    EXPECT_GT(test::smallest_six_volume(m), 0.0);
    EXPECT_TRUE(test::every_node_used(m));
    EXPECT_NEAR(test::mesh_volume(m), volume, 1e-12 * volume);

    const test::FaceCounts faces = test::count_faces(m);
    EXPECT_LE(faces.most_tets_on_a_face, 2);
    const std::vector<uint32_t> boundary = extract_boundary_triangles(m.tets.data(), m.tet_count());
    EXPECT_EQ(boundary.size() / 3, faces.faces_in_one_tet);

    const test::SurfaceFacts s = test::surface_facts(m, boundary);
    EXPECT_TRUE(s.closed);
    EXPECT_TRUE(s.consistent);
    EXPECT_EQ(s.euler, 2) << "the boundary should be one sphere-like surface";
    EXPECT_NEAR(s.enclosed_volume, volume, 1e-12 * volume);

    int misplaced = 0;
    for (std::size_t t = 0; t < boundary.size() / 3; ++t) {
        const double* a = test::node(m, boundary[3 * t]);
        const double* b = test::node(m, boundary[3 * t + 1]);
        const double* c = test::node(m, boundary[3 * t + 2]);
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double front[3], behind[3];
        for (int i = 0; i < 3; ++i) {
            const double centroid = (a[i] + b[i] + c[i]) / 3.0;
            front[i] = centroid + probe * n[i] / length;
            behind[i] = centroid - probe * n[i] / length;
        }
        if (inside(front) || !inside(behind)) ++misplaced;
    }
    EXPECT_EQ(misplaced, 0) << "boundary triangles off the surface or facing inwards";
}

void expect_invalid_argument(const std::function<void()>& build) {
    try {
        build();
        ADD_FAILURE() << "no error thrown";
    } catch (const Error& e) {
        EXPECT_EQ(e.status(), Status::invalid_argument) << e.what();
        EXPECT_GT(std::string(e.what()).size(), 10u);
    }
}

// ---- box -----------------------------------------------------------------------------------

TEST(MeshBuilders, BoxIsExact) {
    const double size[3] = {1.0, 2.0, 3.0};
    const uint32_t cells[3] = {2, 3, 4};
    const TetMesh m = build_box(size, cells);
    EXPECT_EQ(m.node_count(), 3u * 4u * 5u);
    EXPECT_EQ(m.tet_count(), 6u * 2u * 3u * 4u);
    expect_solid(
        m, 6.0,
        [&](const double p[3]) {
            return p[0] > 0 && p[0] < size[0] && p[1] > 0 && p[1] < size[1] && p[2] > 0 &&
                   p[2] < size[2];
        },
        1e-6);
    const std::vector<uint32_t> boundary = extract_boundary_triangles(m.tets.data(), m.tet_count());
    // Two triangles per boundary quad; area of the box surface.
    EXPECT_EQ(boundary.size() / 3, 2u * 2u * (2 * 3 + 3 * 4 + 4 * 2));
    EXPECT_NEAR(test::surface_facts(m, boundary).area, 2.0 * (2.0 + 6.0 + 3.0), 1e-12);
    for (int a = 0; a < 3; ++a) {  // corners exactly where asked
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (uint32_t n = 0; n < m.node_count(); ++n) {
            lo = std::min(lo, m.positions[3 * n + a]);
            hi = std::max(hi, m.positions[3 * n + a]);
        }
        EXPECT_EQ(lo, 0.0);
        EXPECT_EQ(hi, size[a]);
    }
}

TEST(MeshBuilders, SingleCellBoxHasSixTets) {
    const double size[3] = {0.5, 0.25, 2.0};
    const uint32_t cells[3] = {1, 1, 1};
    const TetMesh m = build_box(size, cells);
    EXPECT_EQ(m.node_count(), 8u);
    EXPECT_EQ(m.tet_count(), 6u);
    expect_solid(
        m, 0.25,
        [&](const double p[3]) {
            return p[0] > 0 && p[0] < 0.5 && p[1] > 0 && p[1] < 0.25 && p[2] > 0 && p[2] < 2.0;
        },
        1e-7);
}

TEST(MeshBuilders, BoxRefusesBadParameters) {
    const uint32_t one[3] = {1, 1, 1};
    const double unit[3] = {1, 1, 1};
    for (double bad : {0.0, -1.0, double(NAN), double(INFINITY)}) {
        const double size[3] = {1.0, bad, 1.0};
        expect_invalid_argument([&] { build_box(size, one); });
    }
    const uint32_t zero[3] = {1, 0, 1};
    expect_invalid_argument([&] { build_box(unit, zero); });
    const uint32_t huge[3] = {1000, 1000, 1000};  // 6e9 tets
    expect_invalid_argument([&] { build_box(unit, huge); });
    const uint32_t widest[3] = {UINT32_MAX, UINT32_MAX, UINT32_MAX};
    expect_invalid_argument([&] { build_box(unit, widest); });
    // Valid numbers, but the tets would be flat to rounding precision.
    const double flat[3] = {1.0, 1.0, 1e-20};
    expect_invalid_argument([&] { build_box(flat, one); });
}

// ---- cylinder ------------------------------------------------------------------------------

TEST(MeshBuilders, CylinderHasThePolygonalPrismVolume) {
    const double radius = 0.5, height = 2.0;
    const int segments = 12;
    const TetMesh m = build_cylinder(radius, height, segments, 3, 4);
    EXPECT_EQ(m.node_count(), (1u + 3u * 12u) * 5u);
    EXPECT_EQ(m.tet_count(), 3u * 12u * (2u * 3u - 1u) * 4u);
    expect_solid(
        m, polygon_area(radius, segments) * height,
        [&](const double p[3]) {
            return p[2] > 0 && p[2] < height && inside_polygon(p[0], p[1], radius, segments);
        },
        1e-7);
}

TEST(MeshBuilders, CoarsestCylinder) {
    const TetMesh m = build_cylinder(1.0, 1.0, 3, 1, 1);
    EXPECT_EQ(m.tet_count(), 9u);
    expect_solid(
        m, polygon_area(1.0, 3),
        [](const double p[3]) {
            return p[2] > 0 && p[2] < 1 && inside_polygon(p[0], p[1], 1.0, 3);
        },
        1e-7);
}

TEST(MeshBuilders, FineCylinder) {
    const TetMesh m = build_cylinder(0.1, 0.3, 40, 6, 9);
    expect_solid(
        m, polygon_area(0.1, 40) * 0.3,
        [](const double p[3]) {
            return p[2] > 0 && p[2] < 0.3 && inside_polygon(p[0], p[1], 0.1, 40);
        },
        1e-8);
}

TEST(MeshBuilders, CylinderRefusesBadParameters) {
    expect_invalid_argument([] { build_cylinder(0.0, 1.0, 8, 1, 1); });
    expect_invalid_argument([] { build_cylinder(1.0, -1.0, 8, 1, 1); });
    expect_invalid_argument([] { build_cylinder(NAN, 1.0, 8, 1, 1); });
    expect_invalid_argument([] { build_cylinder(1.0, INFINITY, 8, 1, 1); });
    expect_invalid_argument([] { build_cylinder(1.0, 1.0, 2, 1, 1); });
    expect_invalid_argument([] { build_cylinder(1.0, 1.0, 8, 0, 1); });
    expect_invalid_argument([] { build_cylinder(1.0, 1.0, 8, 1, 0); });
    expect_invalid_argument([] { build_cylinder(1.0, 1.0, UINT32_MAX, UINT32_MAX, UINT32_MAX); });
}

// ---- cup -----------------------------------------------------------------------------------

struct CupShape {
    double outer, height, wall, bottom;
    int segments;
    // Outer polygonal prism minus the cavity: the inner polygonal prism above the bottom.
    double volume() const {
        return polygon_area(outer, segments) * height -
               polygon_area(outer - wall, segments) * (height - bottom);
    }
    bool inside(const double p[3]) const {
        const bool in_outer =
            p[2] > 0 && p[2] < height && inside_polygon(p[0], p[1], outer, segments);
        const bool in_cavity = p[2] > bottom && inside_polygon(p[0], p[1], outer - wall, segments);
        return in_outer && !in_cavity;
    }
};

TEST(MeshBuilders, CupIsOneGenusZeroSolid) {
    const CupShape cup{1.0, 1.5, 0.2, 0.3, 16};
    const TetMesh m = build_cup(cup.outer, cup.height, cup.wall, cup.bottom, 16, 5);
    expect_solid(
        m, cup.volume(), [&](const double p[3]) { return cup.inside(p); }, 1e-7);
}

TEST(MeshBuilders, CupShapes) {
    for (const CupShape& cup :
         {CupShape{0.05, 0.08, 0.004, 0.006, 24}, CupShape{1.0, 0.5, 0.9, 0.45, 3},
          CupShape{2.0, 4.0, 0.1, 3.0, 7}}) {
        for (uint32_t layers : {1u, 3u}) {
            SCOPED_TRACE(::testing::Message()
                         << "cup " << cup.outer << " " << cup.height << " " << cup.wall << " "
                         << cup.bottom << " layers " << layers);
            const TetMesh m = build_cup(cup.outer, cup.height, cup.wall, cup.bottom,
                                        uint32_t(cup.segments), layers);
            expect_solid(
                m, cup.volume(), [&](const double p[3]) { return cup.inside(p); }, 1e-6 * cup.wall);
        }
    }
}

TEST(MeshBuilders, CupRefusesBadParameters) {
    expect_invalid_argument([] { build_cup(1.0, 1.0, 1.0, 0.1, 8, 2); });  // wall == radius
    expect_invalid_argument([] { build_cup(1.0, 1.0, 1.5, 0.1, 8, 2); });
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.1, 1.0, 8, 2); });  // bottom == height
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.1, 2.0, 8, 2); });
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.0, 0.1, 8, 2); });
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.1, -0.1, 8, 2); });
    expect_invalid_argument([] { build_cup(NAN, 1.0, 0.1, 0.1, 8, 2); });
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.1, 0.1, 2, 2); });
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.1, 0.1, 8, 0); });
    expect_invalid_argument([] { build_cup(1.0, 1.0, 0.1, 0.1, 100000, 100000); });
}

// ---- hammer --------------------------------------------------------------------------------

struct HammerShape {
    double handle_length, handle_width, head_length, head_width;
    // Box 0 handle, box 1 head: low and high corners.
    void boxes(double low[2][3], double high[2][3]) const {
        const double h = handle_width / 2;
        const double l0[3] = {-h, -h, 0.0}, h0[3] = {h, h, handle_length};
        const double l1[3] = {-head_length / 2, -head_width / 2, handle_length - head_width / 2};
        const double h1[3] = {head_length / 2, head_width / 2, handle_length + head_width / 2};
        for (int i = 0; i < 3; ++i) {
            low[0][i] = l0[i], high[0][i] = h0[i], low[1][i] = l1[i], high[1][i] = h1[i];
        }
    }
    // Handle + head - their overlap.
    double volume() const {
        double low[2][3], high[2][3];
        boxes(low, high);
        double v[2] = {1, 1}, overlap = 1;
        for (int i = 0; i < 3; ++i) {
            v[0] *= high[0][i] - low[0][i];
            v[1] *= high[1][i] - low[1][i];
            overlap *=
                std::max(0.0, std::min(high[0][i], high[1][i]) - std::max(low[0][i], low[1][i]));
        }
        return v[0] + v[1] - overlap;
    }
    bool inside(const double p[3]) const {
        double low[2][3], high[2][3];
        boxes(low, high);
        for (int b = 0; b < 2; ++b)
            if (low[b][0] < p[0] && p[0] < high[b][0] && low[b][1] < p[1] && p[1] < high[b][1] &&
                low[b][2] < p[2] && p[2] < high[b][2])
                return true;
        return false;
    }
};

TEST(MeshBuilders, HammerIsHandlePlusHeadMinusOverlap) {
    const HammerShape h{1.0, 0.2, 0.8, 0.4};
    EXPECT_NEAR(h.volume(), 0.16, 1e-15);
    const TetMesh m =
        build_hammer(h.handle_length, h.handle_width, h.head_length, h.head_width, 0.1);
    expect_solid(
        m, h.volume(), [&](const double p[3]) { return h.inside(p); }, 1e-7);
}

TEST(MeshBuilders, HammerShapes) {
    // Cell sizes that do not divide the dimensions, a head narrower than the handle, faces
    // that coincide, a head reaching below the handle's foot.
    const HammerShape shapes[] = {{1.0, 0.2, 0.8, 0.4}, {0.3, 0.05, 0.25, 0.09},
                                  {1.0, 0.3, 0.2, 0.2}, {1.0, 0.2, 0.8, 0.2},
                                  {0.2, 0.1, 0.5, 0.6}, {0.5, 0.1, 0.1, 0.3}};
    for (const HammerShape& h : shapes)
        for (double cell : {0.07, 0.1, 1.0}) {
            SCOPED_TRACE(::testing::Message()
                         << "hammer " << h.handle_length << " " << h.handle_width << " "
                         << h.head_length << " " << h.head_width << " cell " << cell);
            const TetMesh m =
                build_hammer(h.handle_length, h.handle_width, h.head_length, h.head_width, cell);
            expect_solid(
                m, h.volume(), [&](const double p[3]) { return h.inside(p); }, 1e-7);
        }
}

TEST(MeshBuilders, HammerRefusesBadParameters) {
    expect_invalid_argument([] { build_hammer(0.0, 0.1, 0.5, 0.2, 0.05); });
    expect_invalid_argument([] { build_hammer(1.0, -0.1, 0.5, 0.2, 0.05); });
    expect_invalid_argument([] { build_hammer(1.0, 0.1, NAN, 0.2, 0.05); });
    expect_invalid_argument([] { build_hammer(1.0, 0.1, 0.5, INFINITY, 0.05); });
    expect_invalid_argument([] { build_hammer(1.0, 0.1, 0.5, 0.2, 0.0); });
    expect_invalid_argument([] { build_hammer(1.0, 0.1, 0.5, 0.2, 1e-4); });   // too many tets
    expect_invalid_argument([] { build_hammer(1.0, 1e-6, 0.5, 0.2, 0.05); });  // cell too big
    expect_invalid_argument([] { build_hammer(1e300, 1e300, 1e300, 1e300, 1e300); });
}

}  // namespace
}  // namespace lfem
