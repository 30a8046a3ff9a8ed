// Rigid shapes of static and kinematic bodies: a block rests on each of them carrying its
// weight, without sinking in; a kinematic plane carries a block along.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

lfem_body shape_body(lfem_world* w, const lfem_shape_def& s, lfem_body_type type = LFEM_BODY_STATIC) {
    lfem_body_def d = lfem_body_def_default();
    d.type = type;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(lfem_body_add_shape(w, b, &s, NULL), LFEM_OK) << lfem_last_error();
    return b;
}

double vertical_contact_force(lfem_world* w, lfem_body on) {
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
    double f = 0;
    for (const lfem_contact& k : c) {
        if (k.body_a.index == on.index) f += k.force[2];
        EXPECT_NE(k.shape, UINT32_MAX);  // these scenes touch shapes only
    }
    return f;
}

struct Rest {
    double force_error, rms, penetration;
};

// A soft 0.1 m block (4 x 4 x 4 cells) set down on a shape at z = top, settled
// with damping; measured over the last 0.2 s.
Rest rest_on(const lfem_shape_def& shape, double top, double block_offset_x = 0.0) {
    World w;
    shape_body(w, shape);
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 4, 4, 4, -0.05 + block_offset_x, -0.05, top);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.damping = 20.0;
    const lfem_body block = add_body(w, d, m);
    double mass = 0;
    lfem_body_get_mass(w, block, &mass);
    EXPECT_EQ(lfem_world_step(w, 1.0), LFEM_OK) << lfem_last_error();
    Rest r{0, 0, 0};
    for (int i = 0; i < 200; ++i) {
        EXPECT_EQ(lfem_world_step(w, 1e-3), LFEM_OK) << lfem_last_error();
        r.force_error = std::fmax(r.force_error, std::fabs(vertical_contact_force(w, block) / (mass * 9.81) - 1));
        r.penetration = std::fmax(r.penetration, stats(w).max_penetration);
        const std::vector<double> v = velocities(w, block);
        double s = 0;
        for (double x : v) s += x * x;
        r.rms = std::fmax(r.rms, std::sqrt(s / (v.size() / 3)));
    }
    return r;
}

}  // namespace

TEST(Shapes, BlockRestsOnAStaticPlane) {
    lfem_shape_def plane = lfem_shape_def_default();  // z = 0, facing +z
    const Rest r = rest_on(plane, 0.0);
    std::printf("block on plane: weight within %.2e, RMS velocity %.2e m/s, penetration %.2e m\n",
                r.force_error, r.rms, r.penetration);
    EXPECT_LT(r.force_error, 0.005);  // the 0.5 %
    EXPECT_LT(r.rms, 1e-6);           // no jitter
    EXPECT_LT(r.penetration, 1e-9);
}

TEST(Shapes, BlockRestsOnABoxASphereACapsuleAndAHull) {
    lfem_shape_def box = lfem_shape_def_default();
    box.type = LFEM_SHAPE_BOX;
    box.half_extents[0] = box.half_extents[1] = 0.2;
    box.half_extents[2] = 0.1;
    box.center[2] = -0.1;  // top face at z = 0
    lfem_shape_def sphere = lfem_shape_def_default();
    sphere.type = LFEM_SHAPE_SPHERE;
    sphere.radius = 0.3;
    sphere.center[2] = -0.3;  // top at z = 0: the block balances on its crown
    lfem_shape_def capsule = lfem_shape_def_default();
    capsule.type = LFEM_SHAPE_CAPSULE;
    capsule.radius = 0.1;
    capsule.half_length = 0.3;
    // Axis along x (local z turned 90 degrees about y): top line at z = 0.
    capsule.rotation[0] = std::cos(M_PI / 4);
    capsule.rotation[2] = std::sin(M_PI / 4);
    capsule.center[2] = -0.1;
    // A hull: a square frustum whose flat top (0.3 x 0.3) lies at z = 0.
    const double pts[] = {-0.15, -0.15, 0, 0.15, -0.15, 0, 0.15, 0.15, 0, -0.15, 0.15, 0,
                          -0.25, -0.25, -0.2, 0.25, -0.25, -0.2, 0.25, 0.25, -0.2, -0.25, 0.25, -0.2};
    lfem_shape_def hull = lfem_shape_def_default();
    hull.type = LFEM_SHAPE_CONVEX_HULL;
    hull.points = pts;
    hull.point_count = 8;
    const char* names[] = {"box", "sphere", "capsule", "hull"};
    const lfem_shape_def shapes[] = {box, sphere, capsule, hull};
    const int count = LFEM_WITH_CCD ? 4 : 3;  // no hulls without libccd (test_build_options.cpp)
    for (int i = 0; i < count; ++i) {
        const Rest r = rest_on(shapes[i], 0.0);
        std::printf("block on %s: weight within %.2e, RMS velocity %.2e m/s, penetration %.2e m\n", names[i],
                    r.force_error, r.rms, r.penetration);
        EXPECT_LT(r.force_error, 0.005) << names[i];
        // The settling is slower on a crown (sphere) than on a flat face: 1e-5 m/s bounds the
        // remaining rocking after 1 s at 20/s damping.
        EXPECT_LT(r.rms, 1e-5) << names[i];
        EXPECT_LT(r.penetration, 1e-8) << names[i];
    }
}

TEST(Shapes, KinematicPlaneCarriesABlockAlong) {
    // A floor moving sideways at 0.5 m/s under a block with friction: after it catches up
    // the block moves with the floor (stick), so its velocity equals the floor's.
    lfem_world_def wd = lfem_world_def_default();
    World w(wd);
    lfem_shape_def plane = lfem_shape_def_default();
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_KINEMATIC;
    fd.linear_velocity[0] = 0.5;
    fd.friction = 0.8;
    lfem_body floor{};
    ASSERT_EQ(lfem_body_create(w, &fd, &floor), LFEM_OK);
    ASSERT_EQ(lfem_body_add_shape(w, floor, &plane, NULL), LFEM_OK) << lfem_last_error();
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.friction = 0.8;
    d.damping = 10.0;
    const lfem_body block = add_body(w, d, m);
    ASSERT_EQ(lfem_world_step(w, 1.0), LFEM_OK) << lfem_last_error();
    double P[3], mass = 0;
    lfem_body_get_momentum(w, block, P, nullptr);
    lfem_body_get_mass(w, block, &mass);
    std::printf("kinematic plane at 0.5 m/s: block moves at %.5f m/s, penetration %.2e m\n", P[0] / mass,
                stats(w).max_penetration);
    // Damping (10/s) drags the block against the floor with 10 m v ~ 5 N per kg, balanced by
    // static friction (< mu g = 7.8 N/kg): it sticks, so it moves with the floor.
    EXPECT_NEAR(P[0] / mass, 0.5, 1e-3);
    EXPECT_LT(stats(w).max_penetration, 1e-8);
}

TEST(Shapes, BadShapesAreRefused) {
    World w;
    lfem_body_def dd = lfem_body_def_default();
    lfem_body soft{}, ground{};
    ASSERT_EQ(lfem_body_create(w, &dd, &soft), LFEM_OK);
    dd.type = LFEM_BODY_STATIC;
    ASSERT_EQ(lfem_body_create(w, &dd, &ground), LFEM_OK);
    lfem_shape_def s = lfem_shape_def_default();
    EXPECT_EQ(lfem_body_add_shape(w, soft, &s, NULL), LFEM_INVALID_ARGUMENT);  // deformable body
    s.type = LFEM_SHAPE_SPHERE;
    s.radius = 0.0;
    EXPECT_EQ(lfem_body_add_shape(w, ground, &s, NULL), LFEM_INVALID_ARGUMENT);
    s = lfem_shape_def_default();
    s.rotation[0] = 2.0;
    EXPECT_EQ(lfem_body_add_shape(w, ground, &s, NULL), LFEM_INVALID_ARGUMENT);  // not a unit quaternion
    const double flat[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    s = lfem_shape_def_default();
    s.type = LFEM_SHAPE_CONVEX_HULL;
    s.points = flat;
    s.point_count = 4;
    EXPECT_EQ(lfem_body_add_shape(w, ground, &s, NULL), LFEM_INVALID_ARGUMENT);  // coplanar
    EXPECT_NE(std::string(lfem_last_error()).find("coplanar"), std::string::npos);
    s.type = lfem_shape_type(42);
    EXPECT_EQ(lfem_body_add_shape(w, ground, &s, NULL), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_add_shape(w, ground, nullptr, NULL), LFEM_INVALID_ARGUMENT);
}

TEST(Shapes, BlockRestsOnAStaticTriangleMesh) {
    // Terrain as two triangles of a 1 m square at z = 0, facing up.
    World w;
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    lfem_body ground{};
    ASSERT_EQ(lfem_body_create(w, &fd, &ground), LFEM_OK);
    const double X[] = {-0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0};
    const uint32_t tris[] = {0, 1, 2, 0, 2, 3};
    ASSERT_EQ(lfem_body_add_triangle_mesh(w, ground, X, 4, tris, 2), LFEM_OK) << lfem_last_error();
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 4, 4, 4, -0.05, -0.05, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.damping = 20.0;
    const lfem_body block = add_body(w, d, m);
    double mass = 0;
    lfem_body_get_mass(w, block, &mass);
    ASSERT_EQ(lfem_world_step(w, 1.2), LFEM_OK) << lfem_last_error();
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    ASSERT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
    double fz = 0;
    for (const lfem_contact& k : c) fz += k.force[2];
    std::printf("block on a 2-triangle surface: weight within %.2e, penetration %.2e m\n",
                std::fabs(fz / (mass * 9.81) - 1), stats(w).max_penetration);
    EXPECT_NEAR(fz, mass * 9.81, 0.005 * mass * 9.81);
    EXPECT_LT(stats(w).max_penetration, 1e-9);
    // Bad surfaces are refused.
    lfem_body other{};
    ASSERT_EQ(lfem_body_create(w, &fd, &other), LFEM_OK);
    const uint32_t out_of_range[] = {0, 1, 7};
    EXPECT_EQ(lfem_body_add_triangle_mesh(w, other, X, 4, out_of_range, 1), LFEM_INVALID_MESH);
    const double line[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    const uint32_t one[] = {0, 1, 2};
    EXPECT_EQ(lfem_body_add_triangle_mesh(w, other, line, 3, one, 1), LFEM_INVALID_MESH);
    EXPECT_EQ(lfem_body_add_triangle_mesh(w, block, X, 4, tris, 2), LFEM_INVALID_ARGUMENT);  // deformable
}
