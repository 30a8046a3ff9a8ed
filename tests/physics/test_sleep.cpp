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

int count_events(lfem_world* w, lfem_event_type type) {
    uint32_t n = 0;
    lfem_world_get_events(w, nullptr, 0, &n);
    std::vector<lfem_event> e(n);
    if (n) {
        EXPECT_EQ(lfem_world_get_events(w, e.data(), n, &n), LFEM_OK);
    }
    int k = 0;
    for (const lfem_event& x : e) k += x.type == type;
    return k;
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
