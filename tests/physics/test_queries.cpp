// Queries (lfem_world_cast_ray, _all, lfem_world_overlap_box) against closed forms: rays hit
// planes, boxes, spheres, capsules and hulls at the analytic distance and normal, and the
// surface of a body where it is, at rest, stretched by a known linear map, or carried by a
// kinematic motion; the filter and max_distance are respected; all hits come sorted; a box
// finds exactly the bodies it overlaps. Their cost follows what the ray meets (the profile's
// counts do not grow with the scene), and making them changes nothing a step computes
// (fingerprints of two runs, with and without queries, bitwise equal). Bad input is refused
// with the world unchanged.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "physics/lfem_test_util.h"
#include "physics/query_test_util.h"
#include "physics/skin_test_meshes.h"

using namespace lfem_test;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(Queries, RaysMeetShapesAtTheirClosedForms) {
    World world(no_gravity());
    const lfem_body s = static_body(world);
    lfem_shape_def d = lfem_shape_def_default();
    // A plane through (0, 0, -1) tilted by 0.3 rad about x: normal (0, -sin 0.3, cos 0.3).
    d.center[2] = -1.0;
    quaternion(0.3, 1, 0, 0, d.rotation);
    const uint32_t plane = add_shape(world, s, d);
    // A box of half extents (0.3, 0.2, 0.1) about (2, 0, 0), turned 30 degrees about z.
    d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_BOX;
    d.center[0] = 2.0;
    d.half_extents[0] = 0.3, d.half_extents[1] = 0.2, d.half_extents[2] = 0.1;
    quaternion(M_PI / 6, 0, 0, 1, d.rotation);
    const uint32_t box = add_shape(world, s, d);
    // A sphere of radius 0.25 about (4, 0.1, 0).
    d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_SPHERE;
    d.center[0] = 4.0, d.center[1] = 0.1;
    d.radius = 0.25;
    const uint32_t sphere = add_shape(world, s, d);
    // A capsule of radius 0.2 and half length 0.5 about (6, 0, 0), its axis along world x.
    d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_CAPSULE;
    d.center[0] = 6.0;
    d.radius = 0.2, d.half_length = 0.5;
    quaternion(M_PI / 2, 0, 1, 0, d.rotation);
    const uint32_t capsule = add_shape(world, s, d);

    // Down onto the tilted plane from (0, 0.5, 1): t = n.(o - c) / -(n.d).
    {
        const double o[3] = {0, 0.5, 1}, dir[3] = {0, 0, -2};  // any length
        const double ny = -std::sin(0.3), nz = std::cos(0.3);
        const double t = (ny * 0.5 + nz * 2.0) / nz;
        const Hit h = cast(world, o, dir);
        ASSERT_TRUE(h.found);
        EXPECT_EQ(h.h.shape, plane);
        EXPECT_EQ(h.h.triangle, UINT32_MAX);
        EXPECT_NEAR(h.h.distance, t, kExact);
        expect_near3(h.h.normal, 0, ny, nz, kExact, "plane normal");
        expect_near3(h.h.point, 0, 0.5, 1 - t, kExact, "plane point");
    }
    // Along +x through the box's centre: the line leaves the centre through the face of local
    // +x at hx / cos 30 (before hy / sin 30), so it enters at 2 - 0.3 / cos 30.
    {
        const double o[3] = {1, 0, 0}, dir[3] = {1, 0, 0};
        const std::vector<lfem_ray_hit> hits = cast_all(world, o, dir, 2.5);
        ASSERT_EQ(hits.size(), 2u);
        const double half = 0.3 / std::cos(M_PI / 6);
        EXPECT_EQ(hits[0].shape, box);
        EXPECT_NEAR(hits[0].distance, 1 - half, kExact);
        expect_near3(hits[0].normal, -std::cos(M_PI / 6), -std::sin(M_PI / 6), 0, kExact, "box entry normal");
        EXPECT_NEAR(hits[1].distance, 1 + half, kExact);
        expect_near3(hits[1].normal, std::cos(M_PI / 6), std::sin(M_PI / 6), 0, kExact, "box exit normal");
    }
    // Along +x at height z = 0 past y = 0.1 + 0.15: the sphere's chord at offset 0.15.
    {
        const double o[3] = {3, 0.25, 0}, dir[3] = {1, 0, 0};
        const double half = std::sqrt(0.25 * 0.25 - 0.15 * 0.15);  // 0.2
        const Hit h = cast(world, o, dir, 2.5);
        ASSERT_TRUE(h.found);
        EXPECT_EQ(h.h.shape, sphere);
        EXPECT_NEAR(h.h.distance, 1 - half, kExact);
        expect_near3(h.h.normal, -half / 0.25, 0.15 / 0.25, 0, kExact, "sphere normal");
        // From the sphere's centre the ray meets its surface on the way out.
        const double c[3] = {4, 0.1, 0}, up[3] = {0, 0, 1};
        const Hit out = cast(world, c, up, 1.0);
        ASSERT_TRUE(out.found);
        EXPECT_NEAR(out.h.distance, 0.25, kExact);
        expect_near3(out.h.normal, 0, 0, 1, kExact, "exit normal along the ray");
    }
    // Down onto the capsule: its side at y = 0.05, its cap at x = 6.6, and along its axis.
    {
        const double side[3] = {6.3, 0.05, 2}, cap[3] = {6.6, 0, 2}, end[3] = {8, 0, 0};
        const double down[3] = {0, 0, -1}, back[3] = {-1, 0, 0};
        const double zs = std::sqrt(0.04 - 0.0025), zc = std::sqrt(0.04 - 0.01);
        Hit h = cast(world, side, down);
        ASSERT_TRUE(h.found);
        EXPECT_EQ(h.h.shape, capsule);
        EXPECT_NEAR(h.h.distance, 2 - zs, kExact);
        expect_near3(h.h.normal, 0, 0.05 / 0.2, zs / 0.2, kExact, "capsule side normal");
        h = cast(world, cap, down);
        ASSERT_TRUE(h.found);
        EXPECT_NEAR(h.h.distance, 2 - zc, kExact);
        expect_near3(h.h.normal, 0.1 / 0.2, 0, zc / 0.2, kExact, "capsule cap normal");
        h = cast(world, end, back);
        ASSERT_TRUE(h.found);
        EXPECT_NEAR(h.h.distance, 8 - 6.7, kExact);
        expect_near3(h.h.normal, 1, 0, 0, kExact, "capsule end normal");
    }
    // Misses leave the output alone.
    {
        const double o[3] = {4, 3, 0}, dir[3] = {1, 0, 0};
        lfem_ray_hit untouched{};
        untouched.distance = -5;
        int hit = 7;
        ASSERT_EQ(lfem_world_cast_ray(world, o, dir, HUGE_VAL, lfem_query_filter_default(), &untouched, &hit), LFEM_OK);
        EXPECT_EQ(hit, 0);
        EXPECT_EQ(untouched.distance, -5);
    }
}

TEST(Queries, HullsMeetRaysAsTheirFacesDo) {
    World world(no_gravity());
    const lfem_body s = static_body(world);
    // The box of the test above as a hull of its 8 corners, and an octahedron |x|+|y|+|z| <= a.
    double corners[24];
    for (int i = 0; i < 8; ++i) {
        corners[3 * i] = i & 1 ? 0.3 : -0.3;
        corners[3 * i + 1] = i & 2 ? 0.2 : -0.2;
        corners[3 * i + 2] = i & 4 ? 0.1 : -0.1;
    }
    lfem_shape_def d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_CONVEX_HULL;
    d.points = corners, d.point_count = 8;
    d.center[0] = 2.0;
    quaternion(M_PI / 6, 0, 0, 1, d.rotation);
    uint32_t index = 0;
    const lfem_status added = lfem_body_add_shape(world, s, &d, &index);
    if (added == LFEM_UNSUPPORTED) GTEST_SKIP() << "built without convex hulls (LFEM_WITH_CCD=OFF)";
    ASSERT_EQ(added, LFEM_OK) << lfem_last_error();
    const double a = 0.5;
    const double octahedron[18] = {a, 0, 0, -a, 0, 0, 0, a, 0, 0, -a, 0, 0, 0, a, 0, 0, -a};
    d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_CONVEX_HULL;
    d.points = octahedron, d.point_count = 6;
    d.center[1] = 5.0;
    ASSERT_EQ(lfem_body_add_shape(world, s, &d, nullptr), LFEM_OK) << lfem_last_error();
    {
        const double o[3] = {1, 0, 0}, dir[3] = {1, 0, 0};
        const std::vector<lfem_ray_hit> hits = cast_all(world, o, dir, 2.5);
        ASSERT_EQ(hits.size(), 2u);
        const double half = 0.3 / std::cos(M_PI / 6);
        EXPECT_NEAR(hits[0].distance, 1 - half, kGjk);
        expect_near3(hits[0].normal, -std::cos(M_PI / 6), -std::sin(M_PI / 6), 0, kGjk, "hull entry normal");
        EXPECT_NEAR(hits[1].distance, 1 + half, kGjk);
        expect_near3(hits[1].normal, std::cos(M_PI / 6), std::sin(M_PI / 6), 0, kGjk, "hull exit normal");
    }
    {
        // Towards the octahedron's centre along -(1, 1, 1): its face x + y + z = a lies a / sqrt 3
        // from the centre.
        const double o[3] = {1, 6, 1}, dir[3] = {-1, -1, -1};
        const Hit h = cast(world, o, dir);
        ASSERT_TRUE(h.found);
        EXPECT_EQ(h.h.shape, 1u);
        EXPECT_NEAR(h.h.distance, std::sqrt(3.0) - a / std::sqrt(3.0), kGjk);
        const double n = 1 / std::sqrt(3.0);
        expect_near3(h.h.normal, n, n, n, kGjk, "octahedron face normal");
    }
}

TEST(Queries, RaysMeetABodysSurfaceAtRestAndStretched) {
    World world(no_gravity());
    Mesh mesh;
    make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
    const lfem_body body = add_body(world, lfem_body_def_default(), mesh);
    const double o[3] = {-1, 0.031, 0.043}, dir[3] = {1, 0, 0};
    const std::vector<lfem_ray_hit> hits = cast_all(world, o, dir);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_TRUE(same_body(hits[0].body, body));
    EXPECT_NEAR(hits[0].distance, 1.0, kExact);
    EXPECT_NEAR(hits[1].distance, 1.2, kExact);
    expect_near3(hits[0].normal, -1, 0, 0, kExact, "entry face normal");
    expect_near3(hits[1].normal, 1, 0, 0, kExact, "exit face normal");
    // The barycentric weights give the point back from the triangle's nodes.
    uint32_t nt = 0;
    ASSERT_EQ(lfem_body_get_boundary_triangle_count(world, body, &nt), LFEM_OK);
    std::vector<uint32_t> tri(3 * std::size_t(nt));
    ASSERT_EQ(lfem_body_get_boundary_triangles(world, body, tri.data(), nt), LFEM_OK);
    const std::vector<double> x = positions(world, body);
    for (const lfem_ray_hit& h : hits) {
        ASSERT_LT(h.triangle, nt);
        EXPECT_EQ(h.shape, UINT32_MAX);
        const double t1 = h.barycentric[0], t2 = h.barycentric[1], w[3] = {1 - t1 - t2, t2, t1};
        for (int k = 0; k < 3; ++k) {
            double p = 0;
            for (int v = 0; v < 3; ++v) p += w[v] * x[3 * tri[3 * h.triangle + v] + k];
            EXPECT_NEAR(p, h.point[k], kExact);
        }
    }
    // Stretched by (I + t B): a ray along -x at deformed height (y', z') meets the face X = 0.2
    // at x = 0.2 (1 + 2t) + 0.5 t Y, where Z = z' / (1 - t) and Y = (y' - 0.8 t Z) / (1 + 0.5 t)
    // are the material coordinates under (y', z').
    const double B[9] = {2.0, 0.5, 0.0, 0.0, 0.5, 0.8, 0.0, 0.0, -1.0};
    prescribe_linear_motion(world, body, B);
    ASSERT_EQ(lfem_world_step(world, 0.1), LFEM_OK) << lfem_last_error();
    const double t = stats(world).time;
    const double y = 0.06, z = 0.05;
    const double Z = z / (1 - t), Y = (y - 0.8 * t * Z) / (1 + 0.5 * t);
    const double face = 0.2 * (1 + 2 * t) + 0.5 * t * Y;
    const double from[3] = {1, y, z}, back[3] = {-1, 0, 0};
    const Hit h = cast(world, from, back);
    ASSERT_TRUE(h.found);
    // The nodes carry ~1e-15 m of rounding from their sub-steps (the skins' test).
    EXPECT_NEAR(h.h.distance, 1 - face, 1e-13);
    // The face's normal: (I + t B)^-T e_x = (1, -0.5 t / (1 + 0.5 t), ...) normalised: row 1 of
    // the inverse transpose's first column.
    const double a = 1 + 2 * t, b = 0.5 * t, e = 1 + 0.5 * t, f = 0.8 * t, g = 1 - t;
    // A = [[a, b, 0], [0, e, f], [0, 0, g]]: A^-T e_x = (1/a, -b/(a e), b f/(a e g)).
    double n[3] = {1 / a, -b / (a * e), b * f / (a * e * g)};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    expect_near3(h.h.normal, n[0] / len, n[1] / len, n[2] / len, 1e-12, "stretched face normal");
}

TEST(Queries, MovingBodiesAreMetWhereTheyAre) {
    World world(no_gravity());
    Mesh mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 2, 2, 2);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_KINEMATIC;
    d.linear_velocity[0] = 0.5;  // m/s
    const lfem_body k = add_body(world, d, mesh);
    const double o[3] = {-1, 0.05, 0.05}, dir[3] = {1, 0, 0};
    Hit h = cast(world, o, dir);
    ASSERT_TRUE(h.found);
    EXPECT_NEAR(h.h.distance, 1.0, kExact);
    for (int call = 1; call <= 3; ++call) {
        ASSERT_EQ(lfem_world_step(world, 0.2), LFEM_OK);
        h = cast(world, o, dir);
        ASSERT_TRUE(h.found);
        EXPECT_TRUE(same_body(h.h.body, k));
        EXPECT_NEAR(h.h.distance, 1.0 + 0.5 * 0.2 * call, kExact) << "call " << call;
    }
}

TEST(Queries, FilterAndMaxDistanceAreRespected) {
    World world(no_gravity());
    Mesh mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 1, 1, 1);
    lfem_body_def d = lfem_body_def_default();
    d.category_bits = 2, d.mask_bits = 0xFFFFFFFFu & ~4u;
    const lfem_body body = add_body(world, d, mesh);
    const double o[3] = {-1, 0.03, 0.06}, dir[3] = {1, 0, 0};  // off the faces' diagonals
    EXPECT_TRUE(cast(world, o, dir).found);  // the default filter: category 1, every mask bit
    lfem_query_filter f = lfem_query_filter_default();
    f.mask_bits = 1;  // sees only category 1
    EXPECT_FALSE(cast(world, o, dir, HUGE_VAL, f).found);
    f.mask_bits = 2, f.category_bits = 4;  // sees category 2, but the body's mask refuses 4
    EXPECT_FALSE(cast(world, o, dir, HUGE_VAL, f).found);
    f.category_bits = 1;
    EXPECT_TRUE(cast(world, o, dir, HUGE_VAL, f).found);
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    EXPECT_EQ(overlap(world, lo, hi, f).size(), 1u);
    f.mask_bits = 1;
    EXPECT_EQ(overlap(world, lo, hi, f).size(), 0u);
    // The face lies at exactly 1 m: within max_distance 1 (inclusive), not within 1 - 1e-9.
    const Hit at = cast(world, o, dir, 1.0);
    ASSERT_TRUE(at.found);
    EXPECT_TRUE(same_body(at.h.body, body));
    EXPECT_FALSE(cast(world, o, dir, 1.0 - 1e-9).found);
    EXPECT_EQ(cast_all(world, o, dir, 1.05).size(), 1u);
    EXPECT_EQ(cast_all(world, o, dir, 1.2).size(), 2u);
    // Away from the body: nothing.
    const double away[3] = {-1, 0, 0};
    EXPECT_FALSE(cast(world, o, away).found);
}

TEST(Queries, AllHitsComeNearestFirst) {
    World world(no_gravity());
    Mesh mesh;
    std::vector<lfem_body> bodies;
    // Five cubes along x in shuffled slot order, a sphere shape between two of them.
    const double at[5] = {3.0, 1.0, 4.0, 0.0, 2.0};
    for (double x : at) {
        Mesh m;
        make_box_mesh(m, 0.2, 0.2, 0.2, 2, 2, 2, x, -0.1, -0.1);
        bodies.push_back(add_body(world, lfem_body_def_default(), m));
    }
    const lfem_body s = static_body(world);
    lfem_shape_def d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_SPHERE;
    d.center[0] = 2.6, d.radius = 0.1;
    add_shape(world, s, d);
    const double o[3] = {-1, 0.013, -0.021}, dir[3] = {1, 0, 0};
    const std::vector<lfem_ray_hit> hits = cast_all(world, o, dir);
    ASSERT_EQ(hits.size(), 12u);  // in and out of five cubes and the sphere
    for (std::size_t i = 1; i < hits.size(); ++i) EXPECT_LE(hits[i - 1].distance, hits[i].distance);
    const double chord = std::sqrt(0.01 - 0.013 * 0.013 - 0.021 * 0.021);
    EXPECT_NEAR(hits[6].distance, 3.6 - chord, kExact);  // after three cubes: the sphere
    EXPECT_EQ(hits[6].shape, 0u);
    EXPECT_NEAR(hits[0].distance, 1.0, kExact);
    EXPECT_NEAR(hits[11].distance, 5.2, kExact);
    // The nearest is the first of them.
    const Hit h = cast(world, o, dir);
    ASSERT_TRUE(h.found);
    EXPECT_TRUE(same_body(h.h.body, bodies[3]));
    EXPECT_EQ(h.h.distance, hits[0].distance);
    // Too small a buffer: the count, and nothing written.
    std::vector<lfem_ray_hit> few(4);
    few[0].distance = -1;
    uint32_t count = 0;
    EXPECT_EQ(lfem_world_cast_ray_all(world, o, dir, HUGE_VAL, lfem_query_filter_default(), few.data(), 4, &count),
              LFEM_BUFFER_TOO_SMALL);
    EXPECT_EQ(count, 12u);
    EXPECT_EQ(few[0].distance, -1);
}

// "No limit" (max_distance HUGE_VAL) means the same as a limit beyond every surface: a plane's
// solid has no far side, so a ray from above meets it once, at the distance to the plane, and a
// ray that starts inside it and goes deeper meets nothing (an engine integration saw a second
// hit at distance inf, point (nan, nan, -inf), and a hit at inf for the ray from inside).
TEST(Queries, NoLimitMeetsAPlaneOnceAndNeverAtInfinity) {
    World world(no_gravity());
    const lfem_body s = static_body(world);
    add_shape(world, s, lfem_shape_def_default());  // the plane z = 0, solid below
    const double above[3] = {0.3, -0.2, 2.0}, down[3] = {0, 0, -1};
    for (double limit : {HUGE_VAL, 10.0}) {
        const std::vector<lfem_ray_hit> hits = cast_all(world, above, down, limit);
        ASSERT_EQ(hits.size(), 1u) << "limit " << limit;
        EXPECT_EQ(hits[0].distance, 2.0);
        expect_near3(hits[0].point, 0.3, -0.2, 0.0, 0.0, "the point on the plane");
        expect_near3(hits[0].normal, 0, 0, 1, kExact, "the plane's normal");
        const Hit h = cast(world, above, down, limit);
        ASSERT_TRUE(h.found);
        EXPECT_EQ(h.h.distance, 2.0);
        // From inside the solid, deeper: nothing to meet. Upwards: the surface, on the way out.
        const double inside[3] = {0, 0, -1}, up[3] = {0, 0, 1};
        EXPECT_TRUE(cast_all(world, inside, down, limit).empty()) << "limit " << limit;
        EXPECT_FALSE(cast(world, inside, down, limit).found);
        const std::vector<lfem_ray_hit> out = cast_all(world, inside, up, limit);
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(out[0].distance, 1.0);
        // A ray along the plane, above it, never meets it.
        const double along[3] = {1, 0, 0};
        EXPECT_TRUE(cast_all(world, above, along, limit).empty());
    }
}

TEST(Queries, BoxesFindExactlyTheBodiesTheyOverlap) {
    World world(no_gravity());
    Mesh mesh;
    make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
    const lfem_body soft = add_body(world, lfem_body_def_default(), mesh);  // [0, 0.2] x [0, 0.1]^2
    const lfem_body s = static_body(world);
    lfem_shape_def d = lfem_shape_def_default();
    d.type = LFEM_SHAPE_SPHERE;
    d.center[0] = 1.0, d.radius = 0.2;
    add_shape(world, s, d);
    const lfem_body p = static_body(world);
    d = lfem_shape_def_default();
    d.center[2] = -1.0;  // the half-space z <= -1
    add_shape(world, p, d);
    lfem_body_def kd = lfem_body_def_default();
    kd.type = LFEM_BODY_KINEMATIC;
    Mesh km;
    make_box_mesh(km, 0.1, 0.1, 0.1, 1, 1, 1, 3, 0, 0);
    const lfem_body kin = add_body(world, kd, km);
    kd.type = LFEM_BODY_RIGID;
    Mesh rm;
    make_box_mesh(rm, 0.1, 0.1, 0.1, 1, 1, 1, 5, 0, 0);
    const lfem_body rigid = add_body(world, kd, rm);
    const auto expect = [&](const double lo[3], const double hi[3], std::vector<lfem_body> want, const char* what) {
        const std::vector<lfem_body> got = overlap(world, lo, hi);
        ASSERT_EQ(got.size(), want.size()) << what;
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_TRUE(same_body(got[i], want[i])) << what;
    };
    {
        const double lo[3] = {0.15, 0.05, 0.05}, hi[3] = {0.3, 0.2, 0.2};
        expect(lo, hi, {soft}, "a corner of the soft body");
    }
    {
        const double lo[3] = {0.051, 0.032, 0.041}, hi[3] = {0.06, 0.04, 0.05};
        expect(lo, hi, {soft}, "wholly inside the soft body");
    }
    {
        const double lo[3] = {0.4, 0, 0}, hi[3] = {0.7, 0.1, 0.1};
        expect(lo, hi, {}, "between the bodies");
    }
    {
        const double lo[3] = {1.2, -0.1, -0.1}, hi[3] = {1.3, 0.1, 0.1};
        expect(lo, hi, {s}, "touching the sphere's surface");
        const double lo2[3] = {1.2 + 1e-9, -0.1, -0.1}, hi2[3] = {1.3, 0.1, 0.1};
        expect(lo2, hi2, {}, "a nanometre off the sphere");
    }
    {
        const double lo[3] = {1.14, 0.14, -0.01}, hi[3] = {1.2, 0.2, 0.01};  // corner 0.198 m from the centre
        expect(lo, hi, {s}, "a corner inside the sphere");
        const double lo2[3] = {1.15, 0.15, -0.01}, hi2[3] = {1.2, 0.2, 0.01};  // nearest corner 0.2121 m away
        expect(lo2, hi2, {}, "beside the sphere, inside its box");
    }
    {
        const double lo[3] = {0, 0, -3}, hi[3] = {0.1, 0.1, -2};
        expect(lo, hi, {p}, "below the plane");
    }
    {
        const double lo[3] = {2.95, 0.02, 0.02}, hi[3] = {3.01, 0.03, 0.03};
        expect(lo, hi, {kin}, "a face of the kinematic body");
    }
    {
        const double lo[3] = {-10, -10, -10}, hi[3] = {10, 10, 10};
        expect(lo, hi, {soft, s, p, kin, rigid}, "everything, in body order");
    }
}

TEST(Queries, CostFollowsWhatTheRayMeetsNotTheScene) {
    // Rows of n soft cubes (4^3 cells, 192 boundary triangles each, 1 m apart); a ray across the
    // first cube and a box inside it reach that body alone and test the same few of its
    // triangles (those of the tree's leaves the ray passes) however many cubes there are.
    uint64_t primitives[3] = {0, 0, 0};
    const uint32_t rows[3] = {4, 32, 256};
    for (int r = 0; r < 3; ++r) {
        World world(no_gravity());
        for (uint32_t i = 0; i < rows[r]; ++i) {
            Mesh m;
            make_box_mesh(m, 0.2, 0.2, 0.2, 4, 4, 4, double(i), 0, 0);
            add_body(world, lfem_body_def_default(), m);
        }
        ASSERT_EQ(lfem_world_step(world, 1e-3), LFEM_OK);
        const double o[3] = {0.05, -1, 0.07}, dir[3] = {0, 1, 0};
        lfem_profile before{}, after{};
        ASSERT_EQ(lfem_world_get_profile(world, &before), LFEM_OK);
        ASSERT_TRUE(cast(world, o, dir).found);
        const double lo[3] = {0.05, 0.05, 0.05}, hi[3] = {0.06, 0.06, 0.06};
        EXPECT_EQ(overlap(world, lo, hi).size(), 1u);
        ASSERT_EQ(lfem_world_get_profile(world, &after), LFEM_OK);
        EXPECT_EQ(after.queries - before.queries, 3u);       // ray, then the box's count and list
        EXPECT_EQ(after.query_bodies - before.query_bodies, 3u);
        EXPECT_EQ(after.query_refits - before.query_refits, 1u);  // the first cube's tree, once
        primitives[r] = after.query_primitives - before.query_primitives;
        // Stepping moves the cubes: the next ray refits the one tree it meets, once.
        ASSERT_EQ(lfem_world_step(world, 1e-3), LFEM_OK);
        ASSERT_EQ(lfem_world_get_profile(world, &before), LFEM_OK);
        ASSERT_TRUE(cast(world, o, dir).found);
        ASSERT_TRUE(cast(world, o, dir).found);
        ASSERT_EQ(lfem_world_get_profile(world, &after), LFEM_OK);
        EXPECT_EQ(after.query_refits - before.query_refits, 1u);
        EXPECT_EQ(after.query_bodies - before.query_bodies, 2u);
        std::printf("%u cubes (%u triangles): a ray and a box reached 3 bodies and tested %llu triangles\n",
                    rows[r], rows[r] * 192u, (unsigned long long)primitives[r]);
    }
    EXPECT_EQ(primitives[0], primitives[1]);
    EXPECT_EQ(primitives[1], primitives[2]);
    EXPECT_LT(primitives[0], 3u * 192u / 4u);  // each query: under a quarter of the one cube's triangles
}

namespace {

// A scene with every body type in contact: a soft cube on a static floor, a rigid box on the
// cube, a kinematic plate sliding beside them, a skin on the cube.
void contact_scene(lfem_world* w, std::vector<lfem_body>& bodies) {
    Mesh floor, cube, box, plate;
    make_box_mesh(floor, 0.8, 0.8, 0.1, 4, 4, 1, -0.4, -0.4, -0.1);
    make_box_mesh(cube, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.0);
    make_box_mesh(box, 0.06, 0.06, 0.04, 2, 2, 1, -0.03, -0.03, 0.101);
    make_box_mesh(plate, 0.1, 0.1, 0.02, 2, 2, 1, 0.1, -0.05, 0.05);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    bodies.push_back(add_body(w, d, floor));
    d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 2e5;
    d.angular_velocity[2] = 1.0;
    bodies.push_back(add_body(w, d, cube));
    d = lfem_body_def_default();
    d.type = LFEM_BODY_RIGID;
    d.density = 3000;
    bodies.push_back(add_body(w, d, box));
    d = lfem_body_def_default();
    d.type = LFEM_BODY_KINEMATIC;
    d.linear_velocity[1] = 0.3;
    bodies.push_back(add_body(w, d, plate));
    const double c[3] = {0, 0, 0.05};
    const SkinMesh skin = sphere_skin(c, 0.045, 2);
    ASSERT_EQ(lfem_body_add_skin(w, bodies[1], skin.x.data(), skin.vertices(), skin.tri.data(), skin.triangles(),
                                 nullptr),
              LFEM_OK);
}

// Everything the queries answer for a fixed set of rays and boxes, as bytes.
std::vector<unsigned char> query_answers(lfem_world* w) {
    std::vector<unsigned char> out;
    for (int i = 0; i < 8; ++i) {
        const double o[3] = {-0.3 + 0.07 * i, -0.2, 0.3}, dir[3] = {0.1 * i - 0.3, 1.0, -1.2};
        for (lfem_ray_hit h : cast_all(w, o, dir)) {
            h.body.generation = 0;  // process-wide: another world's bodies have others
            const unsigned char* p = reinterpret_cast<const unsigned char*>(&h);
            out.insert(out.end(), p, p + sizeof h);
        }
        const double lo[3] = {-0.1 + 0.03 * i, -0.05, 0.0}, hi[3] = {-0.05 + 0.03 * i, 0.05, 0.2};
        for (const lfem_body& b : overlap(w, lo, hi)) out.push_back(uint8_t(b.index));
    }
    return out;
}

std::vector<unsigned char> contacts_of(lfem_world* w) {
    uint32_t n = 0;
    lfem_world_query_contacts(w, nullptr, 0, &n);
    std::vector<lfem_contact> c(n);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), n, &n), LFEM_OK);
    for (lfem_contact& k : c) k.body_a.generation = k.body_b.generation = 0;
    const unsigned char* p = reinterpret_cast<const unsigned char*>(c.data());
    return std::vector<unsigned char>(p, p + c.size() * sizeof(lfem_contact));
}

}  // namespace

TEST(Queries, MakingThemChangesNothingAStepComputes) {
    // Two runs of the same scene, one queried after every call (rays, boxes and skins): every
    // readable byte of both is the same after every call. And the answers are the same on one
    // and on two threads.
    lfem_world_def one = lfem_world_def_default(), two = lfem_world_def_default();
    two.thread_count = 2;
    World quiet(one), asked(one), asked2(two);
    std::vector<lfem_body> bq, ba, ba2;
    contact_scene(quiet, bq);
    contact_scene(asked, ba);
    contact_scene(asked2, ba2);
    for (int call = 0; call < 30; ++call) {
        ASSERT_EQ(lfem_world_step(quiet, 1.0 / 120), LFEM_OK) << lfem_last_error();
        ASSERT_EQ(lfem_world_step(asked, 1.0 / 120), LFEM_OK) << lfem_last_error();
        ASSERT_EQ(lfem_world_step(asked2, 1.0 / 120), LFEM_OK) << lfem_last_error();
        const std::vector<unsigned char> answers = query_answers(asked);
        EXPECT_EQ(answers, query_answers(asked2)) << "call " << call;
        EXPECT_FALSE(answers.empty());
        ASSERT_EQ(fingerprint(quiet, bq), fingerprint(asked, ba)) << "call " << call;
        ASSERT_EQ(contacts_of(quiet), contacts_of(asked)) << "call " << call;
    }
    EXPECT_GT(stats(asked).contact_count, 0u);
    lfem_profile p{};
    ASSERT_EQ(lfem_world_get_profile(asked, &p), LFEM_OK);
    EXPECT_GT(p.queries, 0u);
    EXPECT_GT(p.query_refits, 0u);
    ASSERT_EQ(lfem_world_get_profile(quiet, &p), LFEM_OK);
    EXPECT_EQ(p.queries, 0u);
}

TEST(Queries, BadInputIsRefusedAndChangesNothing) {
    World world;
    std::vector<lfem_body> bodies;
    contact_scene(world, bodies);
    ASSERT_EQ(lfem_world_step(world, 0.01), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(world, bodies);
    const std::vector<unsigned char> answers = query_answers(world);
    int cases = 0;
    const auto refused = [&](lfem_status got, lfem_status expected, const std::string& what) {
        EXPECT_EQ(got, expected) << what << ": " << lfem_last_error();
        EXPECT_STRNE(lfem_last_error(), "") << what;
        EXPECT_EQ(before, fingerprint(world, bodies)) << what << " changed the world";
        ++cases;
    };
    const lfem_query_filter f = lfem_query_filter_default();
    const double o[3] = {0, 0, 1}, dir[3] = {0, 0, -1}, nan3[3] = {0, kNaN, 0}, zero[3] = {0, 0, 0};
    const double inf3[3] = {HUGE_VAL, 0, 0};
    lfem_ray_hit out{};
    out.distance = -3;
    int hit = 9;
    refused(lfem_world_cast_ray(nullptr, o, dir, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "world NULL");
    refused(lfem_world_cast_ray(world, nullptr, dir, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "origin NULL");
    refused(lfem_world_cast_ray(world, o, nullptr, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "direction NULL");
    refused(lfem_world_cast_ray(world, o, dir, 1, f, nullptr, &hit), LFEM_INVALID_ARGUMENT, "out NULL");
    refused(lfem_world_cast_ray(world, o, dir, 1, f, &out, nullptr), LFEM_INVALID_ARGUMENT, "hit NULL");
    refused(lfem_world_cast_ray(world, nan3, dir, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "NaN origin");
    refused(lfem_world_cast_ray(world, o, nan3, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "NaN direction");
    refused(lfem_world_cast_ray(world, o, inf3, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "infinite direction");
    refused(lfem_world_cast_ray(world, o, zero, 1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "zero direction");
    refused(lfem_world_cast_ray(world, o, dir, kNaN, f, &out, &hit), LFEM_INVALID_ARGUMENT, "NaN max_distance");
    refused(lfem_world_cast_ray(world, o, dir, -1, f, &out, &hit), LFEM_INVALID_ARGUMENT, "negative max_distance");
    EXPECT_EQ(out.distance, -3);
    EXPECT_EQ(hit, 9);
    uint32_t count = 77;
    lfem_ray_hit hits[2];
    hits[0].distance = -3;
    refused(lfem_world_cast_ray_all(world, o, dir, 1, f, hits, 2, nullptr), LFEM_INVALID_ARGUMENT, "all: count NULL");
    refused(lfem_world_cast_ray_all(world, o, dir, 1, f, nullptr, 2, &count), LFEM_INVALID_ARGUMENT,
            "all: out NULL with a capacity");
    refused(lfem_world_cast_ray_all(world, o, zero, 1, f, hits, 2, &count), LFEM_INVALID_ARGUMENT,
            "all: zero direction");
    EXPECT_EQ(count, 77u);
    const double down_long[3] = {0.001, 0.002, -1};
    refused(lfem_world_cast_ray_all(world, o, down_long, HUGE_VAL, f, hits, 1, &count), LFEM_BUFFER_TOO_SMALL,
            "all: capacity 1");
    EXPECT_GT(count, 1u);  // the count is given all the same
    EXPECT_EQ(hits[0].distance, -3);
    lfem_body found[2] = {{9, 9}, {9, 9}};
    const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1}, bad_hi[3] = {1, -2, 1};
    count = 77;
    refused(lfem_world_overlap_box(world, nullptr, hi, f, found, 2, &count), LFEM_INVALID_ARGUMENT, "box: lo NULL");
    refused(lfem_world_overlap_box(world, lo, nullptr, f, found, 2, &count), LFEM_INVALID_ARGUMENT, "box: hi NULL");
    refused(lfem_world_overlap_box(world, nan3, hi, f, found, 2, &count), LFEM_INVALID_ARGUMENT, "box: NaN lo");
    refused(lfem_world_overlap_box(world, lo, bad_hi, f, found, 2, &count), LFEM_INVALID_ARGUMENT, "box: lo above hi");
    refused(lfem_world_overlap_box(world, lo, hi, f, found, 2, nullptr), LFEM_INVALID_ARGUMENT, "box: count NULL");
    refused(lfem_world_overlap_box(world, lo, hi, f, nullptr, 2, &count), LFEM_INVALID_ARGUMENT,
            "box: out NULL with a capacity");
    EXPECT_EQ(count, 77u);
    refused(lfem_world_overlap_box(world, lo, hi, f, found, 2, &count), LFEM_BUFFER_TOO_SMALL, "box: capacity 2");
    EXPECT_EQ(count, 4u);
    EXPECT_EQ(found[0].index, 9u);
    EXPECT_EQ(found[1].generation, 9u);
    // A tiny and a huge direction are fine: only the direction counts.
    const double tiny[3] = {0, 0, -1e-300}, huge[3] = {0, 0, -1e300};
    lfem_ray_hit a{}, b{};
    int ha = 0, hb = 0;
    ASSERT_EQ(lfem_world_cast_ray(world, o, tiny, HUGE_VAL, f, &a, &ha), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_world_cast_ray(world, o, huge, HUGE_VAL, f, &b, &hb), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(ha, 1);
    EXPECT_EQ(hb, 1);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(answers, query_answers(world));  // and the failed calls left the answers alone
    std::printf("%d bad query inputs refused cleanly\n", cases);
}

// lfem_body_closest_point: the nearest point of a body's surface, against the closed form of a
// box [0, 0.2]^3: outside a face, the projection onto it; past an edge or corner, that edge or
// corner; inside, the nearest face. Exact up to round-off (1e-15 m); the triangle named lies in
// the plane of the face.
TEST(Queries, TheClosestSurfacePointOfABoxIsItsClosedForm) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    World w(wd);
    Mesh m;
    make_box_mesh(m, 0.2, 0.2, 0.2, 2, 2, 2, 0, 0, 0);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    struct Case {
        double p[3], q[3], d;
    };
    const Case cases[] = {
        {{0.5, 0.1, 0.07}, {0.2, 0.1, 0.07}, 0.3},                       // beyond the face x = 0.2
        {{0.3, 0.3, 0.3}, {0.2, 0.2, 0.2}, std::sqrt(3.0) * 0.1},          // past the corner
        {{0.1, -0.1, 0.3}, {0.1, 0.0, 0.2}, std::sqrt(2.0) * 0.1},         // past the edge y = 0, z = 0.2
        {{0.03, 0.1, 0.12}, {0.0, 0.1, 0.12}, 0.03},                     // inside, nearest the face x = 0
    };
    uint32_t nt = 0;
    ASSERT_EQ(lfem_body_get_boundary_triangle_count(w, b, &nt), LFEM_OK);
    std::vector<uint32_t> tri(3 * nt);
    ASSERT_EQ(lfem_body_get_boundary_triangles(w, b, tri.data(), nt), LFEM_OK);
    const std::vector<double> x = positions(w, b);
    for (const Case& c : cases) {
        double q[3], d = -1;
        uint32_t t = UINT32_MAX;
        ASSERT_EQ(lfem_body_closest_point(w, b, c.p, q, &t, &d), LFEM_OK) << lfem_last_error();
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(q[k], c.q[k], 1e-15);
        EXPECT_NEAR(d, c.d, 1e-15);
        ASSERT_LT(t, nt);
        // The point lies in the triangle's plane.
        const double* a = &x[3 * tri[3 * t]];
        const double* bb = &x[3 * tri[3 * t + 1]];
        const double* cc = &x[3 * tri[3 * t + 2]];
        const double u[3] = {bb[0] - a[0], bb[1] - a[1], bb[2] - a[2]}, v[3] = {cc[0] - a[0], cc[1] - a[1], cc[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double off = (q[0] - a[0]) * n[0] + (q[1] - a[1]) * n[1] + (q[2] - a[2]) * n[2];
        EXPECT_NEAR(off, 0.0, 1e-15);
    }
    // Refused, nothing written: a body of shapes alone, a NaN point, no output.
    const lfem_body floor = add_plane_floor(w);
    double q[3] = {7, 7, 7}, d = 7;
    uint32_t t = 7;
    const double p[3] = {0, 0, 1}, nan_p[3] = {NAN, 0, 0};
    EXPECT_EQ(lfem_body_closest_point(w, floor, p, q, &t, &d), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_closest_point(w, b, nan_p, q, &t, &d), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_closest_point(w, b, p, nullptr, &t, &d), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_closest_point(w, lfem_body{b.index, b.generation + 9}, p, q, &t, &d), LFEM_INVALID_HANDLE);
    EXPECT_TRUE(q[0] == 7 && q[1] == 7 && q[2] == 7 && t == 7 && d == 7);
}
