// Attachments at any point, and compliant ones (issue 36): points of a body found by position
// (the tet around each, its shape functions' weights), held to the caller's frame, to a body, or
// to the same material point of another deformable body; rigidly or by a spring with a damper.
// Checked against closed forms: the force that carries a weight, a spring's static stretch m g /
// k, its period 2 pi sqrt(m / k) and its damped decay; bad input is refused and changes nothing.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

const double kG = 9.81;

struct Hold {
    std::vector<double> points;
    lfem_body target{};
    double stiffness = 0, damping = 0;
};

lfem_status try_attach(lfem_world* w, lfem_body body, const Hold& h, lfem_attachment* out) {
    lfem_attachment_def d = lfem_attachment_def_default();
    d.body = body;
    d.target = h.target;
    d.points = h.points.data();
    d.point_count = uint32_t(h.points.size() / 3);
    d.stiffness = h.stiffness, d.damping = h.damping;
    return lfem_attachment_create(w, &d, out);
}

lfem_attachment attach(lfem_world* w, lfem_body body, const Hold& h) {
    lfem_attachment a{};
    EXPECT_EQ(try_attach(w, body, h, &a), LFEM_OK) << lfem_last_error();
    return a;
}

std::array<double, 3> force_of(lfem_world* w, lfem_attachment a) {
    std::array<double, 3> f{};
    EXPECT_EQ(lfem_attachment_get_force(w, a, f.data()), LFEM_OK) << lfem_last_error();
    return f;
}

double mass_of(lfem_world* w, lfem_body b) {
    double m = 0;
    EXPECT_EQ(lfem_body_get_mass(w, b, &m), LFEM_OK);
    return m;
}

double centre_z(lfem_world* w, lfem_body b) {
    double c[3] = {0, 0, 0};
    EXPECT_EQ(lfem_body_get_center_of_mass(w, b, c), LFEM_OK) << lfem_last_error();
    return c[2];
}

// A stiff 0.1 m cube (E 1e7: its sag under its own weight, rho g L^2 / E ~ 1e-5 m, is far
// below what the tests measure) of 3^3 cells, its bottom at z = bottom.
lfem_body stiff_cube(lfem_world* w, Mesh& m, double bottom, double damping, lfem_model model = LFEM_MODEL_COROTATIONAL) {
    make_box_mesh(m, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, bottom);
    lfem_body_def d = lfem_body_def_default();
    d.model = model;
    d.young_modulus = 1e7;
    d.density = 1100;
    d.damping = damping;
    return add_body(w, d, m);
}

}  // namespace

// Four points inside the cube near its top (not nodes: off the node grid), held to the
// caller's fixed frame: at rest they carry its weight m g (the rest is in equilibrium).
TEST(PointAttachments, PointsInsideCarryTheWeight) {
    for (lfem_model model : {LFEM_MODEL_COROTATIONAL, LFEM_MODEL_NEO_HOOKEAN}) {
        World w;
        Mesh m;
        const lfem_body cube = stiff_cube(w, m, -0.1, 20.0, model);
        Hold h;
        h.points = {0.013, 0.021, -0.011, -0.017, 0.008, -0.014, 0.022, -0.019, -0.009, -0.011, -0.012, -0.016};
        const lfem_attachment a = attach(w, cube, h);
        const double z0 = centre_z(w, cube);
        for (int i = 0; i < 120; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const double mg = mass_of(w, cube) * kG;
        const std::array<double, 3> f = force_of(w, a);
        std::printf("%s: points carry (%.6g, %.6g, %.6g) N, m g = %.6g N; the centre sank %.3g m\n", model_name(model), f[0],
                    f[1], f[2], mg, z0 - centre_z(w, cube));
        // Damping 20 for 2 s leaves e^-40 of the start. The solve stops once its updates move
        // the nodes by less than 1e-3 of what gravity moves them in a sub-step (g h h_mid): a
        // force of 1e-3 of the held nodes' weight at most is left unbalanced.
        EXPECT_NEAR(f[2], mg, 1e-3 * mg);
        EXPECT_NEAR(f[0], 0.0, 1e-3 * mg);
        EXPECT_NEAR(f[1], 0.0, 1e-3 * mg);
        // Held rigidly: the stiff cube hardly moves (its sag is ~1e-5 m).
        EXPECT_LT(std::fabs(z0 - centre_z(w, cube)), 1e-4);
    }
}

// One point at the top of the cube, on a spring of k = 200 N/m to the caller's frame: at rest
// it stretches by m g / k (the cube hangs below its point, which holds no torque); undamped it
// swings up and down with the period 2 pi sqrt(m / k); with a damper of ratio zeta each period
// leaves exp(-2 pi zeta / sqrt(1 - zeta^2)) of the amplitude.
TEST(PointAttachments, ASpringStretchesSwingsAndDecaysAsItsClosedForm) {
    const double k = 200.0;
    for (double zeta : {0.0, 0.1}) {
        World w;
        Mesh m;
        const lfem_body cube = stiff_cube(w, m, -0.1, 0.0);
        const double mass = mass_of(w, cube);
        Hold h;
        h.points = {0.0, 0.0, -0.001};
        h.stiffness = k;
        h.damping = 2.0 * zeta * std::sqrt(k * mass);
        const lfem_attachment a = attach(w, cube, h);
        // Released from where it hangs unstretched: it falls, the spring catches it, and its
        // centre swings about z0 - m g / k with amplitude m g / k.
        const double z0 = centre_z(w, cube), stretch = mass * kG / k, dt = 1.0 / 600;
        std::vector<double> z;
        for (int i = 0; i < 1200; ++i) {  // 2 s: four periods of 0.47 s
            ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
            z.push_back(centre_z(w, cube) - (z0 - stretch));
        }
        // The times the centre crosses its rest height going up (linear between samples).
        std::vector<double> up;
        for (std::size_t i = 1; i < z.size(); ++i)
            if (z[i - 1] < 0.0 && z[i] >= 0.0) up.push_back(dt * (double(i) + z[i - 1] / (z[i - 1] - z[i])));
        ASSERT_GE(up.size(), 3u);
        const double period = (up.back() - up.front()) / double(up.size() - 1);
        const double wn = std::sqrt(k / mass), expected = 2.0 * M_PI / (wn * std::sqrt(1.0 - zeta * zeta));
        // Each period's lowest point against the one before.
        std::vector<double> lows;
        for (std::size_t p = 0; p + 1 < up.size(); ++p) {
            double low = 0.0;
            for (std::size_t i = 0; i < z.size(); ++i)
                if (dt * double(i + 1) > up[p] && dt * double(i + 1) < up[p + 1]) low = std::min(low, z[i]);
            lows.push_back(low);
        }
        const double ratio = lows.back() / lows.front(), periods = double(lows.size() - 1);
        const double expected_ratio = std::exp(-2.0 * M_PI * zeta / std::sqrt(1.0 - zeta * zeta) * periods);
        std::printf("zeta %.1f: period %.6f s (closed form %.6f), amplitude %.6g m (m g / k = %.6g), after %.0f "
                    "periods x %.4f (closed form %.4f)\n",
                    zeta, period, expected, -lows.front(), stretch, periods, ratio, expected_ratio);
        // The spring is implicit (its force at the end of each sub-step h): stable at any
        // stiffness, it takes (omega h)^2 / 2 of the energy... of the amplitude's square each
        // sub-step, a decay of exp(-omega^2 h t / 2) (h from the stats: the world's sub-step).
        const double h_sub = stats(w).step_size, t_first = 1.5 * expected, t_span = periods * expected;
        const double numerical = std::exp(-wn * wn * h_sub * t_span / 2.0);
        // Released from rest a stretch m g / k above its rest height, its troughs are at w_d t =
        // pi, 3 pi, ..., each exactly stretch e^(-zeta w_n t) below it; the first one listed is
        // the second trough (t = 1.5 periods).
        const double first = stretch * std::exp(-zeta * wn * t_first) * std::exp(-wn * wn * h_sub * t_first / 2.0);
        std::printf("  sub-step %.3g s: the implicit spring's own decay over %.0f periods x %.4f\n", h_sub, periods,
                    numerical);
        // The period: the implicit spring shifts it by O((omega h)^2) ~ 1e-6; the cube's own
        // vibration (its lowest mode near 1 kHz) rides on the centre by ~1e-5 m; sampling at 600
        // Hz and crossing by straight lines: 0.1 % on the period, 0.5 % on the amplitudes.
        EXPECT_NEAR(period, expected, 1e-3 * expected);
        EXPECT_NEAR(-lows.front(), first, 5e-3 * stretch);
        EXPECT_NEAR(ratio, expected_ratio * numerical, 5e-3);
        if (zeta > 0.0) continue;
        // And at rest (the undamped run's mean force over whole periods carries m g): the
        // spring's force is -k times its stretch; read the last sub-step's.
        const std::array<double, 3> f = force_of(w, a);
        EXPECT_NEAR(f[2], k * (-(z.back()) + stretch), 1e-3 * mass * kG + k * 1e-4);
    }
}

// A cube hangs from another cube by points between them: the upper cube is held by its top
// nodes, the lower one by four points in the 1 cm gap between them (within reach of both: each
// bound to the tets of both). At rest the points carry the lower cube's weight; a spring-held
// one sinks by its weight over 4 k more than a rigidly held one.
TEST(PointAttachments, ACubeHangsFromAnotherCubesMaterialPoints) {
    double sank_rigid = 0.0;
    for (double k : {0.0, 5000.0}) {
        World w;
        Mesh mu, ml;
        const lfem_body upper = stiff_cube(w, mu, 0.005, 20.0);
        const lfem_body lower = stiff_cube(w, ml, -0.105, 20.0);
        const double lo[3] = {-1, -1, 0.105 - 1e-6}, hi[3] = {1, 1, 0.105 + 1e-6};
        const std::vector<uint32_t> top = nodes_in_box(w, upper, lo, hi);
        ASSERT_EQ(lfem_body_fix_nodes(w, upper, top.data(), uint32_t(top.size())), LFEM_OK);
        Hold h;
        h.points = {0.02, 0.02, 0.0, -0.02, 0.02, 0.0, -0.02, -0.02, 0.0, 0.02, -0.02, 0.0};
        h.target = upper;
        h.stiffness = k;
        const lfem_attachment a = attach(w, lower, h);
        const double z0 = centre_z(w, lower);
        for (int i = 0; i < 120; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const double mg = mass_of(w, lower) * kG;
        const std::array<double, 3> f = force_of(w, a);
        const double sank = z0 - centre_z(w, lower);
        std::printf("k %.0f N/m: the points carry %.6g N of m g = %.6g N; the lower cube sank %.4g m (m g / 4k = %.4g)\n",
                    k, f[2], mg, sank, k > 0 ? mg / (4 * k) : 0.0);
        // Damping 20 for 2 s: e^-40 of the start; the solve's stopping rule leaves 1e-3 of the
        // held nodes' weight (PointsInsideCarryTheWeight).
        EXPECT_NEAR(f[2], mg, 1e-3 * mg);
        if (k == 0.0) {
            sank_rigid = sank;  // the cubes' own stretch: ~2e-5 m at E 1e7
            EXPECT_LT(sank, 1e-4);
        } else {
            // The rigid run's sinking is the same elastic stretch; the spring's is on top.
            EXPECT_NEAR(sank - sank_rigid, mg / (4 * k), 0.01 * mg / (4 * k));
        }
    }
}

// Two cubes in zero gravity joined by points in the gap between them, pulled apart and
// sheared: the links' forces are equal and opposite, so the momentum of the pair is what it was
// (the tets' weights sum to 1 on either side), and the joined points stay together: the cubes'
// centres keep their distance (rigid) or come back to it (spring).
TEST(PointAttachments, TwoSoftBodiesJoinedKeepTheirMomentum) {
    for (double k : {0.0, 2000.0}) {
        lfem_world_def wd = lfem_world_def_default();
        wd.gravity[2] = 0;
        World w(wd);
        Mesh ma, mb;
        const lfem_body a = stiff_cube(w, ma, 0.005, 0.0);
        const lfem_body b = stiff_cube(w, mb, -0.105, 0.0);
        Hold h;
        h.points = {0.02, 0.02, 0.0, -0.02, 0.02, 0.0, -0.02, -0.02, 0.0, 0.02, -0.02, 0.0};
        h.target = a;
        h.stiffness = k;
        h.damping = k > 0 ? 10.0 : 0.0;
        attach(w, b, h);
        const uint32_t n = node_count(w, a);
        std::vector<double> va(3 * n), vb(3 * n);
        for (uint32_t i = 0; i < n; ++i) va[3 * i] = 0.3, va[3 * i + 2] = 0.5, vb[3 * i + 1] = -0.2, vb[3 * i + 2] = -0.4;
        ASSERT_EQ(lfem_body_set_velocities(w, a, va.data(), n), LFEM_OK);
        ASSERT_EQ(lfem_body_set_velocities(w, b, vb.data(), n), LFEM_OK);
        const Momenta pa = momenta(w, a), pb = momenta(w, b);
        double ca[3], cb[3];
        lfem_body_get_center_of_mass(w, a, ca);
        lfem_body_get_center_of_mass(w, b, cb);
        const double d0 = std::hypot(ca[0] - cb[0], ca[1] - cb[1], ca[2] - cb[2]);
        for (int i = 0; i < 60; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const Momenta qa = momenta(w, a), qb = momenta(w, b);
        const double P0 = std::hypot(pa.P[0] + pb.P[0], pa.P[1] + pb.P[1], pa.P[2] + pb.P[2]);
        lfem_body_get_center_of_mass(w, a, ca);
        lfem_body_get_center_of_mass(w, b, cb);
        const double d1 = std::hypot(ca[0] - cb[0], ca[1] - cb[1], ca[2] - cb[2]);
        std::printf("k %.0f: momentum change (%.3g, %.3g, %.3g) N s of %.3g; centres %.6f m apart (were %.6f)\n", k,
                    qa.P[0] + qb.P[0] - pa.P[0] - pb.P[0], qa.P[1] + qb.P[1] - pa.P[1] - pb.P[1],
                    qa.P[2] + qb.P[2] - pa.P[2] - pb.P[2], P0, d1, d0);
        // Round-off of sums over the nodes: 1e-12 N s.
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(qa.P[c] + qb.P[c], pa.P[c] + pb.P[c], 1e-12) << "k " << k;
        // Undamped cubes: the pull's relative kinetic energy, 1/2 (m/2) 0.9^2 = 0.22 J, rings
        // in their stretch, K = E A / L = 1e6 N/m, by up to sqrt(2 * 0.22 / 1e6) = 0.7 mm (the
        // rigid joint); the spring (k = 2000 N/m, damper 10 N s/m, 4 points, reduced mass
        // 0.55 kg) has taken up the pull in the 1 s: its swing decays as e^-(40 / 1.1 * t).
        EXPECT_NEAR(d1, d0, 1e-3) << "k " << k;
    }
}

// A compliant attachment to another deformable body goes through a checkpoint: the loaded
// world steps bit for bit as the saved one.
TEST(PointAttachments, ACheckpointKeepsThem) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    World w;
    Mesh mu, ml;
    const lfem_body upper = stiff_cube(w, mu, 0.0, 1.0);
    const lfem_body lower = stiff_cube(w, ml, -0.1, 1.0);
    Hold h;
    h.points = {0.02, 0.02, 0.0, -0.02, -0.02, 0.0};
    h.target = upper, h.stiffness = 3000, h.damping = 5;
    attach(w, lower, h);
    for (int i = 0; i < 5; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::string path = ::testing::TempDir() + "lfem_point_attachments.ckpt";
    ASSERT_EQ(lfem_world_save(w, path.c_str()), LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    std::remove(path.c_str());
    for (int i = 0; i < 5; ++i) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        ASSERT_EQ(lfem_world_step(loaded, 1.0 / 60), LFEM_OK);
    }
    EXPECT_EQ(fingerprint(w, {upper, lower}), fingerprint(loaded, {upper, lower}));
    lfem_world_destroy(loaded);
}

TEST(PointAttachments, BadInputIsRefusedAndChangesNothing) {
    World w;
    Mesh m, mo;
    const lfem_body cube = stiff_cube(w, m, 0.0, 1.0);
    const lfem_body other = stiff_cube(w, mo, 1.0, 1.0);  // a metre above
    lfem_body empty{};
    lfem_body_def d = lfem_body_def_default();
    ASSERT_EQ(lfem_body_create(w, &d, &empty), LFEM_OK);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(w, {cube, other});
    lfem_attachment out{7, 7};
    Hold inside;
    inside.points = {0.0, 0.0, 0.05};
    auto refused = [&](const Hold& h, lfem_body body, const char* what, const char* message) {
        EXPECT_EQ(try_attach(w, body, h, &out), LFEM_INVALID_ARGUMENT) << what;
        EXPECT_NE(std::string(lfem_last_error()).find(message), std::string::npos) << what << ": " << lfem_last_error();
        EXPECT_EQ(out.index, 7u) << what;
    };
    Hold far = inside;
    far.points[2] = 0.5;
    refused(far, cube, "far from the body", "farther than");
    Hold nan = inside;
    nan.points[0] = NAN;
    refused(nan, cube, "NaN point", "points");
    Hold negative = inside;
    negative.stiffness = -1;
    refused(negative, cube, "negative stiffness", "stiffness");
    Hold damper = inside;
    damper.damping = 3;
    refused(damper, cube, "a damper without a spring", "damping");
    Hold to_other = inside;
    to_other.target = other;
    refused(to_other, cube, "a target body out of reach", "farther than");
    Hold to_empty = inside;
    to_empty.target = empty;
    refused(to_empty, cube, "a target without tets", "def->target");
    refused(inside, empty, "a body without tets", "def->body");
    // Nodes and points together, and neither.
    lfem_attachment_def both = lfem_attachment_def_default();
    const uint32_t node = 0;
    both.body = cube, both.nodes = &node, both.node_count = 1, both.points = inside.points.data(), both.point_count = 1;
    EXPECT_EQ(lfem_attachment_create(w, &both, &out), LFEM_INVALID_ARGUMENT);
    lfem_attachment_def neither = lfem_attachment_def_default();
    neither.body = cube;
    EXPECT_EQ(lfem_attachment_create(w, &neither, &out), LFEM_INVALID_ARGUMENT);
    lfem_attachment_def null_points = lfem_attachment_def_default();
    null_points.body = cube, null_points.point_count = 1;
    EXPECT_EQ(lfem_attachment_create(w, &null_points, &out), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(out.index, 7u);
    EXPECT_EQ(fingerprint(w, {cube, other}), before);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);  // and no attachment acts: both fall freely
}

// A body held by a spring that fell asleep, saved and loaded: the loaded world has stepped
// nothing yet, and its first call builds the spring's link from where the sleeping body stands
// (not from a predictor's record it does not have); it stays asleep and unmoved, bit for bit.
TEST(PointAttachments, ASleepingSpringHeldBodyLoadsAndSteps) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    lfem_world_def wd = lfem_world_def_default();
    wd.enable_sleep = 1;
    World w(wd);
    Mesh m;
    const lfem_body cube = stiff_cube(w, m, -0.1, 40.0);
    Hold h;
    h.points = {0.0, 0.0, -0.01};
    h.stiffness = 2000, h.damping = 2.0 * std::sqrt(2000.0 * 1.1);
    attach(w, cube, h);
    int calls = 0;
    while (lfem_body_is_awake(w, cube) == 1 && calls < 600) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        ++calls;
    }
    ASSERT_EQ(lfem_body_is_awake(w, cube), 0) << "not asleep after " << calls << " calls";
    const std::string path = ::testing::TempDir() + "lfem_sleeping_spring.ckpt";
    ASSERT_EQ(lfem_world_save(w, path.c_str()), LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    std::remove(path.c_str());
    const std::vector<double> x0 = positions(loaded, cube);
    for (int i = 0; i < 3; ++i) {
        ASSERT_EQ(lfem_world_step(loaded, 1.0 / 60), LFEM_OK) << lfem_last_error();
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    }
    EXPECT_EQ(positions(loaded, cube), x0);
    EXPECT_EQ(lfem_body_is_awake(loaded, cube), 0);
    // Woken, the loaded world steps on as the saved one.
    ASSERT_EQ(lfem_body_wake(loaded, cube), LFEM_OK);
    ASSERT_EQ(lfem_body_wake(w, cube), LFEM_OK);
    for (int i = 0; i < 3; ++i) {
        ASSERT_EQ(lfem_world_step(loaded, 1.0 / 60), LFEM_OK) << lfem_last_error();
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    }
    EXPECT_EQ(fingerprint(w, {cube}), fingerprint(loaded, {cube}));
    lfem_world_destroy(loaded);
}
