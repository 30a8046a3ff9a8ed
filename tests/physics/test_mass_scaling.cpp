// Mass scaling to a requested step (lfem_world_def.mass_scaling_step): the tets that would need
// a shorter step get added mass, and the automatic step is then at least the request.
#include <cmath>
#include <cstdio>
#include <vector>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// A bar of 10 x 2 x 2 cells (5 cm cells) with a sliver layer: the plane of nodes at x = 0.25 m
// moves to 0.2975 m, so the cells between it and x = 0.30 m are 2.5 mm thin and set a stable
// step about sqrt(1/20) of the others'.
// With 10-node tets (quadratic), the nodes of the two cell layers beside that plane move
// linearly with it, so every mid-edge node stays on the middle of its edge.
lfem_body add_bar_with_sliver(lfem_world* w, const lfem_body_def& d, bool quadratic = false) {
    Mesh m;
    if (quadratic)
        make_quadratic_box_mesh(m, 0.5, 0.1, 0.1, 10, 2, 2);
    else
        make_box_mesh(m, 0.5, 0.1, 0.1, 10, 2, 2);
    std::vector<double> x(lfem_mesh_get_positions(m.m), lfem_mesh_get_positions(m.m) + 3 * m.nodes());
    for (std::size_t i = 0; i < x.size(); i += 3) {
        if (std::fabs(x[i] - 0.25) < 1e-9)
            x[i] = 0.2975;
        else if (quadratic && x[i] > 0.2 && x[i] < 0.25)
            x[i] = 0.2 + (x[i] - 0.2) * (0.0975 / 0.05);
        else if (quadratic && x[i] > 0.25 && x[i] < 0.3)
            x[i] = 0.2975 + (x[i] - 0.25) * (0.0025 / 0.05);
    }
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_OK) << lfem_last_error();
    const auto add = quadratic ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh;
    EXPECT_EQ(add(w, b, x.data(), m.nodes(), lfem_mesh_get_tets(m.m), m.tets()), LFEM_OK) << lfem_last_error();
    return b;
}

lfem_world_def world_with_scaling(double step) {
    lfem_world_def wd = lfem_world_def_default();
    wd.mass_scaling_step = step;
    return wd;
}

// The sliver sets the limit: asking for a step three times the natural automatic one makes the
// automatic step at least that (the mediant argument of stable_step.h), adds mass only where it
// is needed (less than the whole body's mass times the factor), and the run stays stable:
// undamped, frictionless and free, its energy may not grow (10 % allows the wobble of measuring
// with mid-step velocities; an unstable step grows it by orders of magnitude in a few steps).
void reaches_the_request_and_stays_stable(bool quadratic) {
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 1e7;
    d.angular_velocity[2] = 3.0;  // spinning and, through the sliver's stiffness, vibrating
    d.linear_velocity[0] = 0.5;
    lfem_world_def plain = lfem_world_def_default();
    plain.gravity[2] = 0.0;
    World unscaled(plain);
    const lfem_body b0 = add_bar_with_sliver(unscaled, d, quadratic);
    const double natural = plain.step_safety * stable_step(unscaled);
    double mass0 = 0, added0 = -1;
    ASSERT_EQ(lfem_body_get_mass(unscaled, b0, &mass0), LFEM_OK);
    ASSERT_EQ(lfem_body_get_added_mass(unscaled, b0, &added0), LFEM_OK);
    EXPECT_EQ(added0, 0.0);

    lfem_world_def wd = world_with_scaling(3.0 * natural);
    wd.gravity[2] = 0.0;
    World w(wd);
    const lfem_body b = add_bar_with_sliver(w, d, quadratic);
    double mass = 0, added = 0;
    ASSERT_EQ(lfem_body_get_mass(w, b, &mass), LFEM_OK);
    ASSERT_EQ(lfem_body_get_added_mass(w, b, &added), LFEM_OK);
    EXPECT_GT(added, 0.0);
    EXPECT_NEAR(mass, mass0 + added, 1e-12 * mass);
    // Only the sliver's neighbourhood needs it: at most factor 9 (the square of 3) times the mass
    // of what is scaled, far less than 9 times the whole bar.
    EXPECT_LT(added, 2.0 * mass0);
    EXPECT_EQ(stats(w).added_mass, added);
    ASSERT_EQ(lfem_world_step(w, 3.0 * natural), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(stats(w).substeps_last_call, 1u);  // one sub-step of the requested size
    EXPECT_GE(stats(w).step_size, 3.0 * natural * (1 - 1e-12));
    const lfem_world_stats s0 = stats(w);
    const double e0 = s0.kinetic_energy + s0.strain_energy;
    double highest = e0;
    for (int i = 0; i < 2000; ++i) {
        ASSERT_EQ(lfem_world_step(w, 3.0 * natural), LFEM_OK) << lfem_last_error();
        const lfem_world_stats s = stats(w);
        highest = std::max(highest, s.kinetic_energy + s.strain_energy);
    }
    std::printf("%s tets: natural step %.3g s, requested %.3g s, added mass %.4g kg of %.4g kg, highest energy %.6g "
                "of %.6g J\n",
                quadratic ? "10-node" : "4-node", natural, 3.0 * natural, added, mass0, highest, e0);
    EXPECT_LT(highest, 1.1 * e0);
}

}  // namespace

TEST(MassScaling, AutomaticStepReachesTheRequestAndStaysStable) { reaches_the_request_and_stays_stable(false); }

// 10-node tets: each tet's frequency is that of its own lumped shares (rho V / 32 at a corner,
// 7 rho V / 48 at a mid-edge node), lambda_max(M_e^-1 K_e) of the 30 x 30 element, and the
// element inequality holds as for linear tets.
TEST(MassScaling, QuadraticTetsReachTheRequestAndStayStable) { reaches_the_request_and_stays_stable(true); }

// Added mass falls as every other mass does: x0 + v0 t + g t^2 / 2 at every node (the scaled
// mass acts fully, inertia and weight). Exact up to round-off: central differences integrate a
// constant acceleration exactly.
TEST(MassScaling, FreeFallIsExactWithAddedMass) {
    World w(world_with_scaling(1e-3));
    lfem_body_def d = lfem_body_def_default();
    d.linear_velocity[2] = 2.0;
    const lfem_body b = add_bar_with_sliver(w, d);
    double added = 0;
    ASSERT_EQ(lfem_body_get_added_mass(w, b, &added), LFEM_OK);
    ASSERT_GT(added, 0.0);
    const std::vector<double> x0 = positions(w, b);
    const double t = 0.25;
    ASSERT_EQ(lfem_world_step(w, t), LFEM_OK) << lfem_last_error();
    const std::vector<double> x = positions(w, b);
    double worst = 0;
    for (std::size_t i = 2; i < x.size(); i += 3) worst = std::max(worst, std::fabs(x[i] - (x0[i] + 2.0 * t - 0.5 * 9.81 * t * t)));
    EXPECT_LT(worst, 1e-12);  // m: round-off of 250 sub-steps
}

// Two scaled bodies collide in free flight: contact keeps them apart (the multipliers add no
// stiffness, so nothing changes for them) and linear momentum, with the added masses, is kept to
// round-off.
TEST(MassScaling, CollisionKeepsMomentumAndNoPenetration) {
    lfem_world_def wd = world_with_scaling(1e-3);
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh a, b;
    make_box_mesh(a, 0.1, 0.1, 0.1, 4, 4, 4, 0.0, 0.0, 0.0);
    make_box_mesh(b, 0.1, 0.1, 0.1, 2, 2, 2, 0.101, 0.01, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.friction = 0.0;
    d.linear_velocity[0] = 1.0;
    const lfem_body ba = add_body(w, d, a);
    d.linear_velocity[0] = -1.0;
    add_body(w, d, b);
    double added = 0;
    ASSERT_EQ(lfem_body_get_added_mass(w, ba, &added), LFEM_OK);
    ASSERT_GT(added, 0.0);  // the fine cube needed mass for 1 ms
    const double p0 = stats(w).linear_momentum[0];
    uint32_t most = 0;
    for (int i = 0; i < 60; ++i) {
        ASSERT_EQ(lfem_world_step(w, 1e-3), LFEM_OK) << lfem_last_error();
        most = std::max(most, stats(w).contact_count);
    }
    EXPECT_GT(most, 4u);
    const lfem_world_stats s = stats(w);
    // Round-off of the momentum of ~1 kg m/s per body over 60 calls: 1e-9 of it is generous.
    EXPECT_NEAR(s.linear_momentum[0], p0, 1e-9);
    EXPECT_LT(s.max_penetration, 1e-6);  // m: the solve's tolerance, not the added mass
}

TEST(MassScaling, BadStepIsRefused) {
    lfem_world_def wd = world_with_scaling(-1.0);
    lfem_world* w = nullptr;
    EXPECT_EQ(lfem_world_create(&wd, &w), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(w, nullptr);
    wd.mass_scaling_step = NAN;
    EXPECT_EQ(lfem_world_create(&wd, &w), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(w, nullptr);
}
