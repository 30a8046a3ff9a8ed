// The same scene gives bitwise identical results on repeated runs: every loop runs in a fixed
// order (bodies by slot, nodes and tets by index, contacts by body and node), nothing depends
// on addresses or timing.
#include <algorithm>
#include <cstring>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

std::vector<unsigned char> run_scene() {
    World w;
    Mesh floor_mesh, a, b;
    make_box_mesh(floor_mesh, 0.6, 0.6, 0.1, 3, 3, 1, -0.3, -0.3, -0.1);
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    const lfem_body floor = add_body(w, f, floor_mesh);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 3e5;
    d.angular_velocity[0] = 2.0;
    make_box_mesh(a, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.02);
    make_box_mesh(b, 0.08, 0.08, 0.08, 2, 2, 2, -0.02, -0.04, 0.16);
    const lfem_body ba = add_body(w, d, a);
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    const lfem_body bb = add_body(w, d, b);
    uint32_t most = 0;  // the scene must exercise contact
    for (int i = 0; i < 60; ++i) {
        EXPECT_EQ(lfem_world_step(w, 0.005), LFEM_OK) << lfem_last_error();
        most = std::max(most, stats(w).contact_count);
    }
    EXPECT_GT(most, 10u);
    std::vector<unsigned char> out = fingerprint(w, {floor, ba, bb});
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    lfem_world_query_contacts(w, c.data(), count, &count);
    // Handles carry process-wide generations (so a handle of another world is recognised as
    // foreign): they differ between the two worlds by design; everything else must not.
    for (lfem_contact& k : c) k.body_a.generation = k.body_b.generation = 0;
    const unsigned char* p = reinterpret_cast<const unsigned char*>(c.data());
    out.insert(out.end(), p, p + count * sizeof(lfem_contact));
    return out;
}

}  // namespace

TEST(Determinism, RepeatedRunsAreBitwiseIdentical) {
    const std::vector<unsigned char> first = run_scene();
    const std::vector<unsigned char> second = run_scene();
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(0, std::memcmp(first.data(), second.data(), first.size()));
}

namespace {

// A cube dropped onto a wide static floor, beside it (1.5 m away, in a contact group of its
// own) optionally a second cube dropped later from higher up, still bouncing while the first
// rests. Returns the first cube's positions and velocities after `steps` steps of 1/60 s, and
// in `most` the most contact pairs carrying force at the end of a step.
std::vector<double> first_cube_after(bool with_second, int steps, uint32_t threads, uint32_t& most) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.time_step = 2e-4;  // fixed: the same sub-steps whether or not the second body is there
    World w(wd);
    Mesh floor_mesh, a, b;
    make_box_mesh(floor_mesh, 3.0, 1.0, 0.1, 12, 4, 1, -1.5, -0.5, -0.1);
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    add_body(w, f, floor_mesh);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 1e5;
    d.poisson_ratio = 0.45;
    make_box_mesh(a, 0.1, 0.1, 0.1, 3, 3, 3, -0.8, -0.05, 0.01);
    const lfem_body first = add_body(w, d, a);
    if (with_second) {
        make_box_mesh(b, 0.1, 0.1, 0.1, 3, 3, 3, 0.7, -0.05, 0.25);
        add_body(w, d, b);
    }
    most = 0;
    for (int i = 0; i < steps; ++i) {
        EXPECT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        most = std::max(most, stats(w).contact_count);
    }
    std::vector<double> out = positions(w, first);
    const std::vector<double> v = velocities(w, first);
    out.insert(out.end(), v.begin(), v.end());
    return out;
}

}  // namespace

// Each contact group (bodies joined by contact pairs, static bodies joining none) is solved to
// a tolerance of its own pairs' motion, in a task of its own: so a cube resting on the floor
// moves bitwise the same whether or not another cube lands and bounces elsewhere on it, on one
// thread or two. (A tolerance taken over the whole world's pairs loosened the resting cube's
// solve whenever the other one moved fast.)
TEST(Determinism, AContactGroupIsSolvedOnItsOwnPairs) {
    for (uint32_t threads : {1u, 2u}) {
        uint32_t most_alone = 0, most_beside = 0;
        const std::vector<double> alone = first_cube_after(false, 45, threads, most_alone);
        const std::vector<double> beside = first_cube_after(true, 45, threads, most_beside);
        EXPECT_EQ(most_alone, 16u);  // the first cube rests on its bottom face's 16 nodes
        EXPECT_GT(most_beside, 16u);  // and the second one landed
        // And it did rest on the floor (top at z = 0): no node below it beyond rounding, and its
        // mean node height (0.05 m at the drop's end height 0.01 m above) between the most a
        // 1 cm drop can compress it (m g h into a column of stiffness E A / L = 1e4 N/m, 1 kg:
        // 5.5 mm) less 1 mm and what energy allows it to bounce to (0.06 m).
        double lowest = 1.0, mean = 0.0;
        const size_t nodes = alone.size() / 6;
        for (size_t i = 0; i < nodes; ++i) lowest = std::min(lowest, alone[3 * i + 2]), mean += alone[3 * i + 2] / nodes;
        EXPECT_GT(lowest, -1e-6) << threads << " thread(s)";
        EXPECT_GT(mean, 0.05 - 0.0065) << threads << " thread(s)";
        EXPECT_LT(mean, 0.06) << threads << " thread(s)";
        ASSERT_EQ(alone.size(), beside.size());
        EXPECT_EQ(0, std::memcmp(alone.data(), beside.data(), alone.size() * sizeof(double))) << threads << " thread(s)";
    }
}
