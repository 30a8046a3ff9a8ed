// A body's settings changed after creation (issue 36): friction, damping, collision filter, user
// data, and skins removed, each checked against what the physics then does (closed forms), with
// bad values refused and the world unchanged.
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

double mean_velocity(lfem_world* w, lfem_body b, int k) {
    const std::vector<double> v = velocities(w, b);
    double sum = 0;
    for (size_t i = k; i < v.size(); i += 3) sum += v[i];
    return sum / double(v.size() / 3);
}

}  // namespace

// A rigid box sliding at 3 m/s on a plane (friction 0.5 each): with its friction set to 0 it
// keeps its speed (a frictionless contact pushes along z only); set to 2 (the pair's
// sqrt(2 * 0.5) = 1) it slows at mu g = g, to within a step's worth g h of the closed form.
TEST(BodySettings, FrictionChangedMidSlideTakesEffect) {
    World w;
    add_plane_floor(w);
    Mesh m;
    make_box_mesh(m, 0.2, 0.2, 0.1, 2, 2, 1, -0.1, -0.1, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_RIGID;
    d.linear_velocity[0] = 3.0;
    const lfem_body box = add_body(w, d, m);
    ASSERT_EQ(lfem_body_set_friction(w, box, 0.0), LFEM_OK) << lfem_last_error();
    for (int i = 0; i < 10; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_NEAR(mean_velocity(w, box, 0), 3.0, 1e-12);
    ASSERT_EQ(lfem_body_set_friction(w, box, 2.0), LFEM_OK);
    const double v0 = mean_velocity(w, box, 0), h = 1.0 / 60, g = 9.81;
    for (int i = 0; i < 10; ++i) ASSERT_EQ(lfem_world_step(w, h), LFEM_OK);
    const double v1 = mean_velocity(w, box, 0);
    std::printf("sliding box: %.6g -> %.6g m/s in 10 calls (mu g t = %.6g)\n", v0, v1, g * 10 * h);
    EXPECT_NEAR(v0 - v1, g * 10 * h, g * h);
}

// A soft cube drifting at 1 m/s without gravity, its damping set to 2/s: the drift decays as
// e^-ct (mass-proportional damping acts on the whole velocity), to O(h^2 c^3 t) of the central
// differences, far below 1e-4 at its sub-step.
TEST(BodySettings, DampingChangedTakesEffect) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    World w(wd);
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0);
    lfem_body_def d = lfem_body_def_default();
    d.linear_velocity[0] = 1.0;
    const lfem_body b = add_body(w, d, m);
    ASSERT_EQ(lfem_body_set_damping(w, b, 2.0), LFEM_OK) << lfem_last_error();
    for (int i = 0; i < 30; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const double v = mean_velocity(w, b, 0);
    std::printf("damped drift: %.8g m/s after 0.5 s (e^-1 = %.8g)\n", v, std::exp(-1.0));
    EXPECT_NEAR(v, std::exp(-1.0), 1e-4);
}

// A cube resting on a block; its mask set to miss the block's category: the pair ends (an event)
// and the cube falls freely through (g t^2 / 2 below, to the free fall's exactness); the user
// data set is the one read.
TEST(BodySettings, AFilterChangeEndsThePairAndTheBodyFallsThrough) {
    World w;
    Mesh floor, cube;
    make_box_mesh(floor, 0.4, 0.4, 0.05, 2, 2, 1, -0.2, -0.2, -0.05);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    fd.category_bits = 2;
    add_body(w, fd, floor);
    make_box_mesh(cube, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0005);
    lfem_body_def d = lfem_body_def_default();
    d.damping = 20;
    const lfem_body b = add_body(w, d, cube);
    for (int i = 0; i < 30; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    ASSERT_GT(stats(w).contact_count, 0u);
    int marker = 0;
    ASSERT_EQ(lfem_body_set_user_data(w, b, &marker), LFEM_OK);
    void* read = nullptr;
    ASSERT_EQ(lfem_body_get_user_data(w, b, &read), LFEM_OK);
    EXPECT_EQ(read, &marker);
    double c0[3], c1[3];
    ASSERT_EQ(lfem_body_get_center_of_mass(w, b, c0), LFEM_OK);
    ASSERT_EQ(lfem_body_set_filter(w, b, 1, ~2u), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(count_events(w, LFEM_EVENT_CONTACT_END), 1);
    EXPECT_EQ(stats(w).contact_count, 0u);
    for (int i = 0; i < 20; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    // Nothing holds it: from rest, a = g - c v (damping c = 20/s), so its centre drops
    // (g/c)(t - (1 - e^-ct)/c) in t = 21 calls, 0.147 m, through the 5 cm block; the central
    // differences' O(h) and the cube's ringing from its release stay inside 1 %.
    ASSERT_EQ(lfem_body_get_center_of_mass(w, b, c1), LFEM_OK);
    const double t = 21.0 / 60, cd = 20.0, g = 9.81, drop = g / cd * (t - (1 - std::exp(-cd * t)) / cd);
    std::printf("filtered cube: dropped %.6g m in %.4g s (damped free fall %.6g m)\n", c0[2] - c1[2], t, drop);
    EXPECT_NEAR(c0[2] - c1[2], drop, 0.01 * drop);
}

// Two skins, the first removed: the second is now skin 0 and reads as before.
TEST(BodySettings, ASkinRemovedLeavesTheOthers) {
    World w;
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 1, 1, 1, 0, 0, 0);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    const double tri_a[9] = {0.01, 0.01, 0.01, 0.05, 0.01, 0.01, 0.01, 0.05, 0.01};
    const double tri_b[12] = {0.02, 0.02, 0.09, 0.08, 0.02, 0.09, 0.02, 0.08, 0.09, 0.08, 0.08, 0.09};
    const uint32_t one[3] = {0, 1, 2}, two[6] = {0, 1, 2, 1, 3, 2};
    uint32_t index = 9;
    ASSERT_EQ(lfem_body_add_skin(w, b, tri_a, 3, one, 1, &index), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_body_add_skin(w, b, tri_b, 4, two, 2, &index), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(index, 1u);
    std::vector<double> before(12);
    ASSERT_EQ(lfem_body_get_skin_vertices(w, b, 1, before.data(), nullptr, 4), LFEM_OK);
    EXPECT_EQ(lfem_body_remove_skin(w, b, 2), LFEM_INVALID_ARGUMENT);
    ASSERT_EQ(lfem_body_remove_skin(w, b, 0), LFEM_OK) << lfem_last_error();
    uint32_t count = 0, vertices = 0, triangles = 0;
    ASSERT_EQ(lfem_body_get_skin_count(w, b, &count), LFEM_OK);
    EXPECT_EQ(count, 1u);
    ASSERT_EQ(lfem_body_get_skin_sizes(w, b, 0, &vertices, &triangles), LFEM_OK);
    EXPECT_EQ(vertices, 4u);
    EXPECT_EQ(triangles, 2u);
    std::vector<double> after(12);
    ASSERT_EQ(lfem_body_get_skin_vertices(w, b, 0, after.data(), nullptr, 4), LFEM_OK);
    EXPECT_EQ(after, before);
    EXPECT_EQ(lfem_body_remove_skin(w, lfem_body{b.index, b.generation + 3}, 0), LFEM_INVALID_HANDLE);
}

TEST(BodySettings, BadValuesAreRefusedAndChangeNothing) {
    World w;
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 1, 1, 1, 0, 0, 0.5);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(w, {b});
    EXPECT_EQ(lfem_body_set_friction(w, b, -0.1), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_friction(w, b, NAN), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_damping(w, b, -1.0), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_damping(w, b, INFINITY), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_friction(w, lfem_body{b.index, b.generation + 3}, 0.2), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_set_filter(nullptr, b, 1, 1), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_user_data(w, lfem_body{}, nullptr), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_remove_skin(w, b, 0), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(fingerprint(w, {b}), before);
}

// A material changed on a stretched cube (nu = 0, a uniform strain of 10 %: W = E eps^2 V / 2):
// four times the modulus holds four times the strain energy at the same shape, the difference is
// booked as the caller's work (the balance does not move), and the stable step halves (omega_max
// grows as sqrt(E) at a fixed nu: the stiffness scales, the Lanczos estimate with it).
TEST(BodySettings, AMaterialChangedCarriesItsEnergyAndItsStep) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    World w(wd);
    Mesh m;
    const lfem_body b = stretched_linear_cube(w, m, 1.1);
    const lfem_world_stats s0 = stats(w);
    double h0 = 0, h1 = 0;
    ASSERT_EQ(lfem_world_get_stable_step(w, &h0), LFEM_OK);
    ASSERT_EQ(lfem_body_set_material(w, b, 4e5, 0.0), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_world_get_stable_step(w, &h1), LFEM_OK);
    const lfem_world_stats s1 = stats(w);
    std::printf("material x4: strain energy %.12g -> %.12g J, stable step %.6g -> %.6g s\n", s0.strain_energy,
                s1.strain_energy, h0, h1);
    EXPECT_NEAR(s1.strain_energy, 2.0, 1e-12 * 2.0);
    EXPECT_NEAR(s1.external_work - s0.external_work, 1.5, 1e-12 * 2.0);
    EXPECT_NEAR(s1.energy_error, s0.energy_error, 1e-12 * 2.0);
    EXPECT_NEAR(h1 / h0, 0.5, 1e-9);
    // Refused: a rigid body, a bad modulus or ratio.
    Mesh r;
    make_box_mesh(r, 0.1, 0.1, 0.1, 1, 1, 1, 1, 0, 0);
    lfem_body_def rd = lfem_body_def_default();
    rd.type = LFEM_BODY_RIGID;
    const lfem_body rigid = add_body(w, rd, r);
    const std::vector<unsigned char> before = fingerprint(w, {b, rigid});
    EXPECT_EQ(lfem_body_set_material(w, rigid, 1e6, 0.3), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_material(w, b, 0.0, 0.3), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_material(w, b, 1e6, 0.5), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_material(w, b, NAN, 0.3), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(fingerprint(w, {b, rigid}), before);
}

// Under mass scaling a new material gets its added masses fitted as a body made of it would:
// the same masses, bit for bit, as a twin created with the new material, and the stable limit
// still at least mass_scaling_step / step_safety; the energy balance stays closed.
TEST(BodySettings, UnderMassScalingTheAddedMassFollowsTheMaterial) {
    lfem_world_def scaled = lfem_world_def_default();
    scaled.mass_scaling_step = 1e-4;
    scaled.gravity[2] = 0;
    World ws(scaled), twin(scaled);
    Mesh s, t;
    make_box_mesh(s, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0);
    make_box_mesh(t, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e11;  // steel: its natural limit (~1e-5 s) is below 1e-4 s: scaled
    d.density = 7800;
    const lfem_body bs = add_body(ws, d, s);
    d.young_modulus = 4e11;
    const lfem_body bt = add_body(twin, d, t);
    double added0 = 0, added1 = 0, added_twin = 0, h = 0;
    ASSERT_EQ(lfem_body_get_added_mass(ws, bs, &added0), LFEM_OK);
    const lfem_world_stats s0 = stats(ws);
    ASSERT_EQ(lfem_body_set_material(ws, bs, 4e11, 0.3), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_body_get_added_mass(ws, bs, &added1), LFEM_OK);
    ASSERT_EQ(lfem_body_get_added_mass(twin, bt, &added_twin), LFEM_OK);
    ASSERT_EQ(lfem_world_get_stable_step(ws, &h), LFEM_OK);
    std::printf("E x4 under mass scaling: added mass %.6g -> %.6g kg (a body made of it: %.6g), stable step %.6g s\n",
                added0, added1, added_twin, h);
    EXPECT_GT(added1, added0);
    EXPECT_EQ(added1, added_twin);
    double m1 = 0, m_twin = 0;
    lfem_body_get_mass(ws, bs, &m1);
    lfem_body_get_mass(twin, bt, &m_twin);
    EXPECT_EQ(m1, m_twin);
    EXPECT_GE(h, 1e-4 / scaled.step_safety * (1 - 1e-9));
    // At rest and unstrained: no energy moved, none booked.
    EXPECT_NEAR(stats(ws).energy_error, s0.energy_error, 1e-12);
    ASSERT_EQ(lfem_world_step(ws, 1e-3), LFEM_OK) << lfem_last_error();
}
