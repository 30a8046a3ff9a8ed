// Sleeping (issue 17): bodies at rest stop being stepped, as a whole pile, cost nothing while
// asleep, keep their contacts, and wake when touched or changed. The energy balance stays
// closed (the kinetic energy a body has when it falls asleep is booked as dissipated).
#include <cmath>
#include <cstdio>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

lfem_world_def sleepy() {
    lfem_world_def wd = lfem_world_def_default();
    wd.enable_sleep = 1;
    return wd;
}

// A static floor and cubes of 10 cm (2^3 cells, damping 20) side by side and stacked.
struct Pile {
    Mesh floor;
    std::vector<Mesh> meshes;
    std::vector<lfem_body> cubes;
};

void build_pile(lfem_world* w, Pile& p, int columns, int height, double z0 = 0.0005) {
    make_box_mesh(p.floor, 2, 2, 0.1, 2, 2, 1, -1, -1, -0.1);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    add_body(w, fd, p.floor);
    p.meshes.resize(size_t(columns * height));
    lfem_body_def d = lfem_body_def_default();
    d.damping = 20;
    d.young_modulus = 1e5;
    for (int i = 0; i < columns; ++i)
        for (int k = 0; k < height; ++k) {
            Mesh& m = p.meshes[size_t(i * height + k)];
            make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, -0.6 + 0.15 * i, -0.05, z0 + 0.1005 * k);
            p.cubes.push_back(add_body(w, d, m));
        }
}

}  // namespace

TEST(Sleep, ASettledPileFallsAsleepAsAWholeAndCostsNothing) {
    World w(sleepy());
    Pile p;
    build_pile(w, p, 4, 2);
    int slept = 0, calls = 0;
    for (; calls < 300 && slept < int(p.cubes.size()); ++calls) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const int now = count_events(w, LFEM_EVENT_SLEEP);
        // A stack sleeps in one call, both cubes: they touch.
        EXPECT_TRUE(now == 0 || now % 2 == 0) << "call " << calls << ": " << now;
        slept += now;
    }
    ASSERT_EQ(slept, int(p.cubes.size()));
    for (lfem_body c : p.cubes) EXPECT_EQ(lfem_body_is_awake(w, c), 0);
    std::printf("pile of %zu cubes asleep after %d calls (%.2f s)\n", p.cubes.size(), calls, calls / 60.0);
    // Asleep: no element forces, no predictor, no commit; the positions do not change by a bit;
    // the contacts are kept (each cube still presses the floor or the cube below); the energy
    // balance holds.
    const lfem_world_stats before = stats(w);
    std::vector<std::vector<double>> x0;
    for (lfem_body c : p.cubes) x0.push_back(positions(w, c));
    ASSERT_EQ(lfem_world_reset_profile(w), LFEM_OK);
    for (int i = 0; i < 60; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    lfem_profile prof{};
    ASSERT_EQ(lfem_world_get_profile(w, &prof), LFEM_OK);
    EXPECT_EQ(prof.internal_forces.calls, 0u);
    EXPECT_EQ(prof.predictor.calls, 0u);
    EXPECT_EQ(prof.commit.calls, 0u);
    EXPECT_EQ(prof.narrow_phase.calls, 0u);
    EXPECT_EQ(prof.substeps, 60u);  // one sub-step a call: nothing asks for a shorter one
    for (size_t k = 0; k < p.cubes.size(); ++k) EXPECT_EQ(positions(w, p.cubes[k]), x0[k]);
    const lfem_world_stats after = stats(w);
    EXPECT_EQ(after.contact_count, before.contact_count);
    EXPECT_GT(after.contact_count, 0u);
    EXPECT_EQ(after.kinetic_energy, 0.0);
    // kinetic + strain + dissipated - work - initial: unchanged while asleep (nothing moves,
    // gravity does no work), and small overall (the step's own O(h) bookkeeping error).
    EXPECT_EQ(after.energy_error, before.energy_error);
}

TEST(Sleep, ACubeDroppedOnASleepingPileWakesIt) {
    World w(sleepy());
    Pile p;
    build_pile(w, p, 1, 1);
    for (int i = 0; i < 200 && lfem_body_is_awake(w, p.cubes[0]); ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    ASSERT_EQ(lfem_body_is_awake(w, p.cubes[0]), 0);
    const std::vector<double> resting = positions(w, p.cubes[0]);
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, -0.6, -0.05, 0.2);
    lfem_body_def d = lfem_body_def_default();
    d.damping = 20;
    d.young_modulus = 1e5;
    const lfem_body falling = add_body(w, d, m);
    int woke = 0;
    for (int i = 0; i < 30; ++i) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        woke += count_events(w, LFEM_EVENT_WAKE);
    }
    EXPECT_EQ(woke, 1);
    EXPECT_EQ(lfem_body_is_awake(w, p.cubes[0]), 1);
    // Woken, it carries the new cube: it is pressed into the floor a little more.
    EXPECT_NE(positions(w, p.cubes[0]), resting);
    // And the new cube never passed into the sleeping one while it was held like a static body.
    const std::vector<double> x = positions(w, falling);
    double lowest = HUGE_VAL;
    for (size_t k = 2; k < x.size(); k += 3) lowest = std::min(lowest, x[k]);
    EXPECT_GT(lowest, 0.09);
}

TEST(Sleep, ChangesByTheCallerWakeABody) {
    World w(sleepy());
    Pile p;
    build_pile(w, p, 1, 1);
    const lfem_body c = p.cubes[0];
    auto settle = [&] {
        for (int i = 0; i < 200 && lfem_body_is_awake(w, c); ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        ASSERT_EQ(lfem_body_is_awake(w, c), 0);
    };
    settle();
    ASSERT_EQ(lfem_body_wake(w, c), LFEM_OK);
    EXPECT_EQ(lfem_body_is_awake(w, c), 1);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(count_events(w, LFEM_EVENT_WAKE), 1);  // reported with the next step's events
    settle();
    const uint32_t node = 0;
    const double force[3] = {0, 0, 1.0};
    ASSERT_EQ(lfem_body_set_node_forces(w, c, &node, 1, force), LFEM_OK);
    EXPECT_EQ(lfem_body_is_awake(w, c), 1);
    settle();
    const double g[3] = {0, 0, -5};
    ASSERT_EQ(lfem_world_set_gravity(w, g), LFEM_OK);
    EXPECT_EQ(lfem_body_is_awake(w, c), 1);
    // Bad handles.
    EXPECT_EQ(lfem_body_wake(w, lfem_body{c.index, c.generation + 3}), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_wake(nullptr, c), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_is_awake(w, lfem_body{c.index, c.generation + 3}), -1);
    EXPECT_EQ(lfem_body_is_awake(nullptr, c), -1);
}

// lfem_body_set_sleep_allowed: a cube kept from sleeping after creation stays awake where its
// twin sleeps; allowed again, it falls asleep.
TEST(Sleep, SleepAllowedChangedAfterCreation) {
    World w(sleepy());
    Pile p;
    build_pile(w, p, 2, 1);
    ASSERT_EQ(lfem_body_set_sleep_allowed(w, p.cubes[0], 0), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(lfem_body_set_sleep_allowed(w, p.cubes[0], 2), LFEM_INVALID_ARGUMENT);
    for (int i = 0; i < 200 && lfem_body_is_awake(w, p.cubes[1]); ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    ASSERT_EQ(lfem_body_is_awake(w, p.cubes[1]), 0);
    for (int i = 0; i < 60; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(lfem_body_is_awake(w, p.cubes[0]), 1);
    ASSERT_EQ(lfem_body_set_sleep_allowed(w, p.cubes[0], 1), LFEM_OK);
    for (int i = 0; i < 200 && lfem_body_is_awake(w, p.cubes[0]); ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(lfem_body_is_awake(w, p.cubes[0]), 0);
}

TEST(Sleep, OffByDefaultAndPerBody) {
    {
        World w;  // the default world: nothing sleeps
        Pile p;
        build_pile(w, p, 1, 1);
        for (int i = 0; i < 120; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        EXPECT_EQ(lfem_body_is_awake(w, p.cubes[0]), 1);
    }
    World w(sleepy());
    Mesh floor, m;
    make_box_mesh(floor, 2, 2, 0.1, 2, 2, 1, -1, -1, -0.1);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    add_body(w, fd, floor);
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0005);
    lfem_body_def d = lfem_body_def_default();
    d.damping = 20;
    d.enable_sleep = 0;
    const lfem_body c = add_body(w, d, m);
    for (int i = 0; i < 120; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(lfem_body_is_awake(w, c), 1);
    // Bad definitions.
    lfem_world_def bad = sleepy();
    lfem_world* out = nullptr;
    bad.enable_sleep = 2;
    EXPECT_EQ(lfem_world_create(&bad, &out), LFEM_INVALID_ARGUMENT);
    bad = sleepy(), bad.sleep_velocity = -1;
    EXPECT_EQ(lfem_world_create(&bad, &out), LFEM_INVALID_ARGUMENT);
    bad = sleepy(), bad.sleep_time = NAN;
    EXPECT_EQ(lfem_world_create(&bad, &out), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(out, nullptr);
    lfem_body_def bd = lfem_body_def_default();
    bd.enable_sleep = 3;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &bd, &b), LFEM_INVALID_ARGUMENT);
}

namespace {

// The soft cube of the piles (issue 34): 10 cm, 3^3 cells, E 1e5, nu 0.45, rho 1100, damping 5,
// friction 0.5.
lfem_body_def pile_cube() {
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e5;
    d.poisson_ratio = 0.45;
    d.density = 1100;
    d.damping = 5;
    d.friction = 0.5;
    return d;
}

// Steps 1/60 s calls until every body of `bodies` sleeps (at most `calls`); returns the calls
// taken and the most sleep events seen in one call.
int step_until_asleep(lfem_world* w, const std::vector<lfem_body>& bodies, int calls, int& most_in_one_call) {
    most_in_one_call = 0;
    for (int i = 1; i <= calls; ++i) {
        EXPECT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        most_in_one_call = std::max(most_in_one_call, count_events(w, LFEM_EVENT_SLEEP));
        bool all = true;
        for (lfem_body b : bodies) all = all && lfem_body_is_awake(w, b) == 0;
        if (all) return i;
    }
    return calls + 1;
}

double lowest_z(lfem_world* w, lfem_body b) {
    const std::vector<double> x = positions(w, b);
    double z = HUGE_VAL;
    for (size_t k = 2; k < x.size(); k += 3) z = std::min(z, x[k]);
    return z;
}

}  // namespace

// 32 soft cubes side by side, put down 1 mm above the floor (they land at 14 ms), each its own
// island. The rule asks each body's motion as a whole (the rigid motion of its momentum) and its
// vibration (the RMS of the rest) to stay under sleep_velocity for sleep_time (0.5 s): once the
// landing's bounce has been damped below 1 cm/s (about 0.3 s at damping 5 from the 0.14 m/s of
// a 1 mm fall: speeds decay as exp(-alpha t / 2) only for the slowest mode; the stiff ones are
// bled faster by the contact) each sleeps within 1.25 s. The rule before it (every node under
// 1 cm/s) put none of them to sleep within 1.25 s: a resting soft body's nodes ring faintly
// above that, at amplitudes of microns.
TEST(Sleep, ThirtyTwoSoftCubesSideBySideFallAsleepWithinASecondOfLanding) {
    World w(sleepy());
    Mesh floor;
    make_box_mesh(floor, 2, 2, 0.1, 2, 2, 1, -1, -1, -0.1);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    fd.friction = 0.5;
    add_body(w, fd, floor);
    std::vector<Mesh> meshes(32);
    std::vector<lfem_body> cubes;
    const lfem_body_def d = pile_cube();
    for (int i = 0; i < 32; ++i) {
        make_box_mesh(meshes[size_t(i)], 0.1, 0.1, 0.1, 3, 3, 3, -0.5 + 0.12 * (i % 8), -0.25 + 0.12 * (i / 8), 0.001);
        cubes.push_back(add_body(w, d, meshes[size_t(i)]));
    }
    int most = 0;
    const int calls = step_until_asleep(w, cubes, 75, most);
    std::printf("32 cubes side by side: all asleep after %d calls (%.2f s)\n", calls, calls / 60.0);
    EXPECT_LE(calls, 75);  // 1.25 s
    // Asleep where they rest: on the floor, not in it (the solve leaves at most nanometres), and
    // sagged under their own weight. A column under its own weight sags on average by
    // rho g a^2 / (3 E') (u(z) = rho g (a z - z^2 / 2) / E', averaged over the height): 3.6e-4 m
    // with E' = E when it may spread sideways freely, 9.5e-5 m with the confined modulus
    // E (1 - nu) / ((1 + nu)(1 - 2 nu)) = 3.79 E when it may not. The floor's friction holds
    // only the base: the mean height of the nodes lies between the two.
    const double a = 0.1, g = 9.81;
    const double free_sag = d.density * g * a * a / (3 * d.young_modulus);
    const double nu = d.poisson_ratio;
    const double confined_sag = free_sag * (1 + nu) * (1 - 2 * nu) / (1 - nu);
    for (lfem_body c : cubes) {
        EXPECT_GT(lowest_z(w, c), -1e-6);
        const std::vector<double> x = positions(w, c);
        double z = 0;
        for (size_t k = 2; k < x.size(); k += 3) z += x[k] / double(x.size() / 3);
        EXPECT_LT(a / 2 - z, free_sag);
        EXPECT_GT(a / 2 - z, confined_sag);
    }
}

// A pyramid of the cubes, put down in place: layers of 3 x 3, 2 x 2 and 1, each 1 mm
// above the last, each cube on the four below it (1 cm apart). It is one island (every cube
// touches the next): it falls asleep in one call, within 2 s, and a cube dropped on top wakes
// all of it in one call, not one layer a sub-step.
TEST(Sleep, APyramidFallsAsleepAsOneIslandAndWakesAsOne) {
    World w(sleepy());
    Mesh floor;
    make_box_mesh(floor, 2, 2, 0.1, 2, 2, 1, -1, -1, -0.1);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    fd.friction = 0.5;
    add_body(w, fd, floor);
    std::vector<Mesh> meshes(15);
    std::vector<lfem_body> cubes;
    const lfem_body_def d = pile_cube();
    for (int layer = 0; layer < 3; ++layer)
        for (int i = 0; i < (3 - layer) * (3 - layer); ++i) {
            const double corner = -0.16 + 0.055 * layer;
            make_box_mesh(meshes[cubes.size()], 0.1, 0.1, 0.1, 3, 3, 3, corner + 0.11 * (i % (3 - layer)),
                          corner + 0.11 * (i / (3 - layer)), 0.001 + 0.101 * layer);
            cubes.push_back(add_body(w, d, meshes[cubes.size()]));
        }
    int most = 0;
    const int calls = step_until_asleep(w, cubes, 120, most);  // 2 s
    std::printf("pyramid of 14: all asleep after %d calls (%.2f s), %d in one call\n", calls, calls / 60.0, most);
    EXPECT_LE(calls, 120);
    EXPECT_EQ(most, 14);
    // Asleep as built: each layer's lowest node above the one below's by nearly a cube height.
    double low[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    for (size_t k = 0; k < cubes.size(); ++k) {
        const size_t layer = k < 9 ? 0 : k < 13 ? 1 : 2;
        low[layer] = std::min(low[layer], lowest_z(w, cubes[k]));
    }
    EXPECT_GT(low[0], -1e-6);
    EXPECT_GT(low[1] - low[0], 0.09);
    EXPECT_GT(low[2] - low[1], 0.09);
    // A cube dropped 2 cm onto the top: the whole pyramid wakes in one call.
    Mesh m;
    const std::vector<double> top = positions(w, cubes[13]);  // the top
    double cx = 0, cy = 0, zmax = -HUGE_VAL;
    for (size_t k = 0; k < top.size(); k += 3) cx += top[k], cy += top[k + 1], zmax = std::max(zmax, top[k + 2]);
    cx /= double(top.size() / 3), cy /= double(top.size() / 3);
    make_box_mesh(m, 0.05, 0.05, 0.05, 2, 2, 2, cx - 0.025, cy - 0.025, zmax + 0.02);
    add_body(w, d, m);
    int woke_calls = 0, woke = 0;
    for (int i = 0; i < 30 && woke < 14; ++i) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        const int now = count_events(w, LFEM_EVENT_WAKE);
        woke += now;
        woke_calls += now > 0;
    }
    EXPECT_EQ(woke, 14);
    EXPECT_EQ(woke_calls, 1);
    for (lfem_body c : cubes) EXPECT_EQ(lfem_body_is_awake(w, c), 1);
}
