// Coulomb friction (eq. 7) on an incline. The incline is a horizontal static floor with
// gravity tilted by 30 degrees: the same physics, without a rotated mesh. A block slides when
// tan(30) = 0.577 > mu, accelerating at g (sin 30 - mu cos 30); it sticks when mu > 0.577.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

const double kAngle = M_PI / 6, kG = 9.81;

struct Incline {
    World w;
    Mesh floor_mesh, block_mesh;
    lfem_body block{};
    double mass = 0;

    Incline(double mu, double damping, double g_scale) : w(world_def(g_scale)) {
        make_box_mesh(floor_mesh, 2.0, 0.5, 0.1, 8, 2, 1, -0.5, -0.25, -0.1);
        lfem_body_def f = lfem_body_def_default();
        f.type = LFEM_BODY_STATIC;
        f.friction = mu;
        add_body(w, f, floor_mesh);
        make_box_mesh(block_mesh, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.0);
        lfem_body_def d = lfem_body_def_default();
        d.young_modulus = 1e6;
        d.friction = mu;
        d.damping = damping;
        block = add_body(w, d, block_mesh);
        lfem_body_get_mass(w, block, &mass);
    }
    static lfem_world_def world_def(double g_scale) {
        lfem_world_def wd = lfem_world_def_default();
        wd.gravity[0] = g_scale * kG * std::sin(kAngle);
        wd.gravity[2] = -g_scale * kG * std::cos(kAngle);
        return wd;
    }
    void set_gravity_scale(double g_scale) {
        const lfem_world_def wd = world_def(g_scale);
        ASSERT_EQ(lfem_world_set_gravity(w, wd.gravity), LFEM_OK);
    }
    double velocity_x() {
        double P[3];
        EXPECT_EQ(lfem_body_get_momentum(w, block, P, nullptr), LFEM_OK);
        return P[0] / mass;
    }
};

}  // namespace

TEST(Friction, BlockSlidesDownAThirtyDegreeInclineAtTheCoulombRate) {
    const double mu = 0.3;
    Incline s(mu, 0.0, 1.0);
    // Undamped: mass-proportional damping would also brake the slide itself. The normal force
    // rings after the sudden load, at the block's axial frequency (~1 kHz); averaged over
    // 0.4 s the ringing cancels, and the friction force mu N(t) averages to mu m g cos 30.
    ASSERT_EQ(lfem_world_step(s.w, 0.05), LFEM_OK) << lfem_last_error();
    const double t0 = stats(s.w).time, v0 = s.velocity_x();
    ASSERT_EQ(lfem_world_step(s.w, 0.4), LFEM_OK) << lfem_last_error();
    const double t1 = stats(s.w).time, v1 = s.velocity_x();
    const double a = (v1 - v0) / (t1 - t0);
    const double expected = kG * (std::sin(kAngle) - mu * std::cos(kAngle));
    std::printf("incline mu = 0.3: acceleration %.4f m/s^2, Coulomb %.4f m/s^2 (%+.2f %%), "
                "penetration %.2e m\n",
                a, expected, 100 * (a / expected - 1), stats(s.w).max_penetration);
    EXPECT_NEAR(a, expected, 0.01 * expected);  // the 1 %
    EXPECT_LT(stats(s.w).max_penetration, 1e-7);
}

TEST(Friction, BlockSticksOnAThirtyDegreeInclineWhenMuExceedsTheTangent) {
    const double mu = 0.7;
    Incline s(mu, 30.0, 0.0);
    // Load gently (src/DESIGN.md section 9): gravity ramps up over 0.3 s with damping on, so the
    // normal force never rings; then it settles for 0.3 s.
    for (int i = 1; i <= 300; ++i) {
        s.set_gravity_scale(i / 300.0);
        ASSERT_EQ(lfem_world_step(s.w, 1e-3), LFEM_OK) << lfem_last_error();
    }
    ASSERT_EQ(lfem_world_step(s.w, 0.3), LFEM_OK) << lfem_last_error();
    // The bottom face: nodes at the lowest layer.
    const std::vector<double> x0 = positions(s.w, s.block);
    ASSERT_EQ(lfem_world_step(s.w, 0.5), LFEM_OK) << lfem_last_error();
    const std::vector<double> x1 = positions(s.w, s.block);
    double slip = 0;
    for (size_t i = 0; i < x0.size() / 3; ++i)
        if (x0[3 * i + 2] < 1e-3) slip = std::fmax(slip, std::fabs(x1[3 * i] - x0[3 * i]));
    std::printf("incline mu = 0.7: bottom face slipped %.2e m in 0.5 s\n", slip);
    EXPECT_LT(slip, 1e-6);  // the bound
}

TEST(Friction, BlockSlidesDownARealThirtyDegreePlane) {
    // The same law on a literal incline: a static plane turned 30 degrees about y (its normal
    // (-sin 30, 0, cos 30)), vertical gravity, the block turned with it and set on it.
    World w;
    lfem_shape_def plane = lfem_shape_def_default();
    plane.rotation[0] = std::cos(-kAngle / 2);
    plane.rotation[2] = std::sin(-kAngle / 2);
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    f.friction = 0.3;
    lfem_body ground{};
    ASSERT_EQ(lfem_body_create(w, &f, &ground), LFEM_OK);
    ASSERT_EQ(lfem_body_add_shape(w, ground, &plane, NULL), LFEM_OK) << lfem_last_error();
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.0);
    const double axis[3] = {0, 1, 0};
    ASSERT_EQ(lfem_mesh_rotate(m.m, axis, -kAngle), LFEM_OK);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.friction = 0.3;
    const lfem_body block = add_body(w, d, m);
    double mass = 0;
    lfem_body_get_mass(w, block, &mass);
    const auto speed_down_slope = [&] {
        double P[3];
        EXPECT_EQ(lfem_body_get_momentum(w, block, P, nullptr), LFEM_OK);
        // Down the slope: (-cos 30, 0, -sin 30) for a plane rising towards +x.
        return -(P[0] * std::cos(kAngle) + P[2] * std::sin(kAngle)) / mass;
    };
    ASSERT_EQ(lfem_world_step(w, 0.05), LFEM_OK) << lfem_last_error();
    const double t0 = stats(w).time, v0 = speed_down_slope();
    ASSERT_EQ(lfem_world_step(w, 0.4), LFEM_OK) << lfem_last_error();
    const double a = (speed_down_slope() - v0) / (stats(w).time - t0);
    const double expected = kG * (std::sin(kAngle) - 0.3 * std::cos(kAngle));
    std::printf("real 30 degree plane, mu = 0.3: acceleration %.4f m/s^2 (%+.2f %%)\n", a,
                100 * (a / expected - 1));
    EXPECT_NEAR(a, expected, 0.01 * expected);
    EXPECT_LT(stats(w).max_penetration, 1e-7);
}
