// Sphere and capsule overlaps (lfem_world_overlap_sphere, _capsule) against closed forms: a
// body is found exactly when its nearest triangle or shape comes within the radius of the
// query's core, with that triangle or shape, its nearest point and the distance; a body of
// tets that holds the query inside is found too; the filter and the buffer rules as for the
// other queries. Bad input is refused with the outputs untouched.
#include <cmath>
#include <string>
#include <vector>

#include "physics/lfem_test_util.h"
#include "physics/query_test_util.h"
#include "physics/skin_test_meshes.h"

using namespace lfem_test;

namespace {

std::vector<lfem_overlap> overlap_capsule(lfem_world* w, const double* a, const double* b, double r,
                                          lfem_query_filter f = lfem_query_filter_default()) {
    uint32_t count = 0;
    const lfem_status asked = lfem_world_overlap_capsule(w, a, b, r, f, nullptr, 0, &count);
    EXPECT_EQ(asked, count ? LFEM_BUFFER_TOO_SMALL : LFEM_OK) << lfem_last_error();
    std::vector<lfem_overlap> out(count);
    if (count) {
        EXPECT_EQ(lfem_world_overlap_capsule(w, a, b, r, f, out.data(), count, &count), LFEM_OK) << lfem_last_error();
    }
    return out;
}

std::vector<lfem_overlap> overlap_sphere(lfem_world* w, const double* c, double r) {
    uint32_t count = 0;
    std::vector<lfem_overlap> out(8);
    EXPECT_EQ(lfem_world_overlap_sphere(w, c, r, lfem_query_filter_default(), out.data(), 8, &count), LFEM_OK)
        << lfem_last_error();
    out.resize(count);
    return out;
}

}  // namespace

// Shapes: a sphere (r 0.5 at (2, 0, 0)), a box (half 0.3, 0.2, 0.1 at (0, 2, 0)), a capsule
// (half length 0.4 along z, r 0.1 at (0, -2, 0)), a plane z = -1. A query sphere meets each
// exactly when its centre is within its radius of the shape (closed forms of the distance).
TEST(Overlaps, ASphereMeetsEachShapeWithinItsRadius) {
    World world(no_gravity());
    const lfem_body s = static_body(world);
    lfem_shape_def d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_SPHERE, d.radius = 0.5, d.center[0] = 2.0;
    add_shape(world, s, d);
    d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_BOX, d.center[1] = 2.0;
    d.half_extents[0] = 0.3, d.half_extents[1] = 0.2, d.half_extents[2] = 0.1;
    add_shape(world, s, d);
    d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_CAPSULE, d.center[1] = -2.0, d.radius = 0.1, d.half_length = 0.4;
    add_shape(world, s, d);
    d = lfem_shape_def_default();
    d.center[2] = -1.0;  // the plane z = -1
    add_shape(world, s, d);
    struct Case {
        double c[3], r;
        uint32_t shape;
        double point[3], distance;
    } cases[] = {
        {{2.0, 0.0, 0.8}, 0.31, 0, {2.0, 0.0, 0.5}, 0.3},                   // above the sphere
        {{2.6, 0.8, 0.0}, 0.5, 0, {2.3, 0.4, 0.0}, 0.5},                    // touching: 1 - 0.5
        {{0.5, 2.35, 0.1}, 0.3, 1, {0.3, 2.2, 0.1}, std::sqrt(0.04 + 0.0225)},  // the box's edge
        {{0.0, -2.0, 0.7}, 0.21, 2, {0.0, -2.0, 0.5}, 0.2},                 // the capsule's end
        {{0.15, -2.0, 0.1}, 0.06, 2, {0.1, -2.0, 0.1}, 0.05},               // its side
        {{5.0, 5.0, -0.7}, 0.3, 3, {5.0, 5.0, -1.0}, 0.3},                  // the plane
    };
    for (const Case& k : cases) {
        std::vector<lfem_overlap> o = overlap_sphere(world, k.c, k.r);
        ASSERT_EQ(o.size(), 1u) << "sphere at " << k.c[0] << ", " << k.c[1] << ", " << k.c[2];
        EXPECT_TRUE(same_body(o[0].body, s));
        EXPECT_EQ(o[0].shape, k.shape);
        EXPECT_EQ(o[0].triangle, UINT32_MAX);
        expect_near3(o[0].point, k.point[0], k.point[1], k.point[2], kExact, "nearest point");
        EXPECT_NEAR(o[0].distance, k.distance, kExact);
        // A hair smaller: nothing (2e-12: twice the closed forms' round-off).
        EXPECT_TRUE(overlap_sphere(world, k.c, k.distance - 2e-12).empty());
    }
    // Inside the box: the core is in the shape, distance 0.
    const double inside[3] = {0.1, 2.05, 0.0};
    std::vector<lfem_overlap> o = overlap_sphere(world, inside, 0.0);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_EQ(o[0].shape, 1u);
    EXPECT_EQ(o[0].distance, 0.0);
}

// A cube [0, 0.2]^3 of tets: a sphere above its top face meets it when its radius reaches the
// face (nearest point straight below); one deep inside, out of reach of every face, is held by
// it; a capsule lying over the top at height 0.3 reaches it with a radius of 0.1; a slanted one
// reaches its edge (x = 0.2, z = 0.2) from its lower end.
TEST(Overlaps, ABodyOfTetsIsMetAtItsSurfaceOrHoldsTheQuery) {
    World world(no_gravity());
    Mesh m;
    make_box_mesh(m, 0.2, 0.2, 0.2, 2, 2, 2);
    const lfem_body cube = add_body(world, lfem_body_def_default(), m);
    const double above[3] = {0.07, 0.13, 0.25};
    std::vector<lfem_overlap> o = overlap_sphere(world, above, 0.06);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_TRUE(same_body(o[0].body, cube));
    EXPECT_NE(o[0].triangle, UINT32_MAX);
    EXPECT_EQ(o[0].shape, UINT32_MAX);
    expect_near3(o[0].point, 0.07, 0.13, 0.2, kExact, "below the centre");
    EXPECT_NEAR(o[0].distance, 0.05, kExact);
    EXPECT_TRUE(overlap_sphere(world, above, 0.05 - 2e-12).empty());
    const double centre[3] = {0.1, 0.1, 0.1};
    o = overlap_sphere(world, centre, 0.01);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_EQ(o[0].triangle, UINT32_MAX);
    EXPECT_EQ(o[0].shape, UINT32_MAX);
    expect_near3(o[0].point, 0.1, 0.1, 0.1, 0.0, "the centre itself");
    EXPECT_EQ(o[0].distance, 0.0);
    // Over the top, from x = -0.5 to 0.5 at y = 0.1, z = 0.3: 0.1 above the face.
    const double a[3] = {-0.5, 0.1, 0.3}, b[3] = {0.5, 0.1, 0.3};
    o = overlap_capsule(world, a, b, 0.1);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_NEAR(o[0].distance, 0.1, kExact);
    EXPECT_NEAR(o[0].point[2], 0.2, kExact);
    EXPECT_TRUE(overlap_capsule(world, a, b, 0.1 - 2e-12).empty());
    // Slanted, from (0.3, 0.1, 0.25) up and away: nearest the edge at its lower end, sqrt(0.01
    // + 0.0025) m from (0.2, 0.1, 0.2).
    const double s0[3] = {0.3, 0.1, 0.25}, s1[3] = {0.5, 0.1, 0.45};
    o = overlap_capsule(world, s0, s1, 0.12);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_NEAR(o[0].distance, std::sqrt(0.0125), kExact);
    expect_near3(o[0].point, 0.2, 0.1, 0.2, kExact, "the edge");
    EXPECT_TRUE(overlap_capsule(world, s0, s1, 0.11).empty());
    // A capsule 1e4 m long along the edge (x = 0.2, z = 0.2), 0.1 + 5e-9 m from it: touching
    // counts to 1e-12 of the query's size (1e-8 m here), and the distance reported stays within
    // the radius, as lfem_overlap promises.
    const double off = (0.1 + 5e-9) / std::sqrt(2.0);
    const double l0[3] = {0.2 + off, -5000.0, 0.2 + off}, l1[3] = {0.2 + off, 5000.0, 0.2 + off};
    o = overlap_capsule(world, l0, l1, 0.1);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_LE(o[0].distance, 0.1);
    EXPECT_NEAR(o[0].distance, 0.1, 1e-8);
}

// Several bodies, in body order; the filter; the buffer; bad input.
TEST(Overlaps, FilterBufferAndBadInput) {
    World world(no_gravity());
    Mesh m1, m2;
    make_box_mesh(m1, 0.2, 0.2, 0.2, 1, 1, 1);
    make_box_mesh(m2, 0.2, 0.2, 0.2, 1, 1, 1, 0.3, 0, 0);
    lfem_body_def d = lfem_body_def_default();
    const lfem_body first = add_body(world, d, m1);
    d.category_bits = 2;
    const lfem_body second = add_body(world, d, m2);
    const double a[3] = {0.1, 0.1, 0.3}, b[3] = {0.4, 0.1, 0.3};
    std::vector<lfem_overlap> o = overlap_capsule(world, a, b, 0.15);
    ASSERT_EQ(o.size(), 2u);
    EXPECT_TRUE(same_body(o[0].body, first));
    EXPECT_TRUE(same_body(o[1].body, second));
    lfem_query_filter f = lfem_query_filter_default();
    f.mask_bits = 2;
    o = overlap_capsule(world, a, b, 0.15, f);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_TRUE(same_body(o[0].body, second));
    lfem_overlap one[1];
    one[0].distance = 7;
    uint32_t count = 0;
    EXPECT_EQ(lfem_world_overlap_capsule(world, a, b, 0.15, lfem_query_filter_default(), one, 1, &count),
              LFEM_BUFFER_TOO_SMALL);
    EXPECT_EQ(count, 2u);
    EXPECT_EQ(one[0].distance, 7.0);  // untouched
    const double nan3[3] = {NAN, 0, 0};
    count = 9;
    EXPECT_EQ(lfem_world_overlap_sphere(world, nan3, 0.1, f, one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_overlap_sphere(world, a, -0.1, f, one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_overlap_sphere(world, a, NAN, f, one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_overlap_sphere(world, nullptr, 0.1, f, one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("center"), std::string::npos) << lfem_last_error();
    EXPECT_EQ(lfem_world_overlap_capsule(world, a, nullptr, 0.1, f, one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_overlap_capsule(world, a, b, 0.1, f, nullptr, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_overlap_capsule(world, a, b, 0.1, f, one, 1, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_overlap_capsule(nullptr, a, b, 0.1, f, one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(count, 9u);
    EXPECT_EQ(one[0].distance, 7.0);
}

// A convex hull (an octahedron of half-diagonal 0.5 at (0, 5, 0)): the nearest point of its
// vertex and of a face's middle, to GJK's tolerance.
TEST(Overlaps, ASphereMeetsAHullAtItsNearestPoint) {
    World world(no_gravity());
    const lfem_body s = static_body(world);
    const double a = 0.5;
    const double octahedron[18] = {a, 0, 0, -a, 0, 0, 0, a, 0, 0, -a, 0, 0, 0, a, 0, 0, -a};
    lfem_shape_def d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_CONVEX_HULL;
    d.points = octahedron, d.point_count = 6;
    d.center[1] = 5.0;
    const lfem_status added = lfem_body_add_shape(world, s, &d, nullptr);
    if (added == LFEM_UNSUPPORTED) GTEST_SKIP() << "built without convex hulls (LFEM_WITH_CCD=OFF)";
    ASSERT_EQ(added, LFEM_OK) << lfem_last_error();
    const double above[3] = {0.0, 5.0, a + 0.2};
    std::vector<lfem_overlap> o = overlap_sphere(world, above, 0.21);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_EQ(o[0].shape, 0u);
    expect_near3(o[0].point, 0, 5.0, a, kGjk, "the vertex");
    EXPECT_NEAR(o[0].distance, 0.2, kGjk);
    // Off the face x + y' + z = a (y' = y - 5) along its normal by 0.1: its middle a/3 (1, 1, 1).
    const double k = 0.1 / std::sqrt(3.0), m = a / 3;
    const double off[3] = {m + k, 5.0 + m + k, m + k};
    o = overlap_sphere(world, off, 0.1 + 1e-9);
    ASSERT_EQ(o.size(), 1u);
    expect_near3(o[0].point, m, 5.0 + m, m, kGjk, "the face's middle");
    EXPECT_NEAR(o[0].distance, 0.1, kGjk);
    EXPECT_TRUE(overlap_sphere(world, off, 0.1 - 1e-9).empty());
}

namespace {

bool cast_sphere(lfem_world* w, const double* o, const double* d, double r, double max_distance, lfem_ray_hit& hit) {
    int found = 7;
    EXPECT_EQ(lfem_world_cast_sphere(w, o, d, r, max_distance, lfem_query_filter_default(), &hit, &found), LFEM_OK)
        << lfem_last_error();
    EXPECT_TRUE(found == 0 || found == 1);
    return found == 1;
}

}  // namespace

// A sphere swept along a ray (lfem_world_cast_sphere) stops where it first touches: head on a
// static sphere at the sum of the radii, off centre where the centres are that far apart, on a
// cube's face and on its edge where the closed forms put it; it misses what it passes beside
// and what lies beyond max_distance; one that starts overlapping hits at 0.
TEST(SphereCasts, StopWhereTheSphereFirstTouches) {
    World world(no_gravity());
    const lfem_body s = static_body(world);
    lfem_shape_def d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_SPHERE, d.radius = 0.5, d.center[0] = 2.0;
    add_shape(world, s, d);
    Mesh m;
    make_box_mesh(m, 0.2, 0.2, 0.2, 2, 2, 2, 0.0, 5.0, 0.0);  // [0, 0.2] x [5, 5.2] x [0, 0.2]
    const lfem_body cube = add_body(world, lfem_body_def_default(), m);
    lfem_ray_hit hit{};
    const double x_dir[3] = {1, 0, 0}, down[3] = {0, 0, -2};
    // Head on: 2 - 0.5 - 0.1; exact (one step of the advancement).
    const double o1[3] = {0, 0, 0};
    ASSERT_TRUE(cast_sphere(world, o1, x_dir, 0.1, HUGE_VAL, hit));
    EXPECT_TRUE(same_body(hit.body, s));
    EXPECT_EQ(hit.shape, 0u);
    EXPECT_NEAR(hit.distance, 1.4, kExact);
    expect_near3(hit.point, 1.5, 0, 0, kExact, "head on");
    expect_near3(hit.normal, -1, 0, 0, kExact, "head on");
    // 0.3 off the line of centres: (t - 2)^2 + 0.09 = 0.6^2. The advancement converges on a
    // slanted approach to its stopping gap (1e-12 m) over the cosine of the angle: 1e-11.
    const double o2[3] = {0, 0.3, 0};
    ASSERT_TRUE(cast_sphere(world, o2, x_dir, 0.1, HUGE_VAL, hit));
    const double t = 2 - std::sqrt(0.27), c[3] = {t - 2, 0.3, 0};
    EXPECT_NEAR(hit.distance, t, 1e-11);
    expect_near3(hit.point, 2 + c[0] * 0.5 / 0.6, c[1] * 0.5 / 0.6, 0, 1e-11, "off centre");
    expect_near3(hit.normal, c[0] / 0.6, c[1] / 0.6, 0, 1e-11, "off centre");
    // Down onto the cube's top face at (0.1, 5.1): 1 - 0.2 - 0.05.
    const double o3[3] = {0.1, 5.1, 1.0};
    ASSERT_TRUE(cast_sphere(world, o3, down, 0.05, HUGE_VAL, hit));
    EXPECT_TRUE(same_body(hit.body, cube));
    EXPECT_NE(hit.triangle, UINT32_MAX);
    EXPECT_NEAR(hit.distance, 0.75, kExact);
    expect_near3(hit.point, 0.1, 5.1, 0.2, kExact, "the top face");
    expect_near3(hit.normal, 0, 0, 1, kExact, "the top face");
    // Down past the side x = 0.2 at x = 0.23: it catches the top edge when its centre is 0.04
    // above it: t = 1 - 0.24, normal (0.03, 0, 0.04) / 0.05.
    const double o4[3] = {0.23, 5.1, 1.0};
    ASSERT_TRUE(cast_sphere(world, o4, down, 0.05, HUGE_VAL, hit));
    EXPECT_NEAR(hit.distance, 0.76, 1e-11);
    expect_near3(hit.point, 0.2, 5.1, 0.2, 1e-11, "the edge");
    expect_near3(hit.normal, 0.6, 0, 0.8, 1e-10, "the edge");
    // Beside it (0.06 from the side) it misses; short of the face it misses; overlapping, 0.
    const double o5[3] = {0.26, 5.1, 1.0};
    EXPECT_FALSE(cast_sphere(world, o5, down, 0.05, HUGE_VAL, hit));
    EXPECT_FALSE(cast_sphere(world, o3, down, 0.05, 0.7, hit));
    const double o6[3] = {0.1, 5.1, 0.22};
    ASSERT_TRUE(cast_sphere(world, o6, down, 0.05, HUGE_VAL, hit));
    EXPECT_EQ(hit.distance, 0.0);
    // Bad input: refused, the output untouched.
    int found = 7;
    hit.distance = 9;
    const double zero[3] = {0, 0, 0};
    EXPECT_EQ(lfem_world_cast_sphere(world, o1, x_dir, -1, 1, lfem_query_filter_default(), &hit, &found),
              LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_cast_sphere(world, o1, x_dir, NAN, 1, lfem_query_filter_default(), &hit, &found),
              LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_cast_sphere(world, o1, zero, 0.1, 1, lfem_query_filter_default(), &hit, &found),
              LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_cast_sphere(world, o1, x_dir, 0.1, 1, lfem_query_filter_default(), nullptr, &found),
              LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(found, 7);
    EXPECT_EQ(hit.distance, 9.0);
}
