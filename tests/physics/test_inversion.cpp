// Inverted tets (issue 15): reported after each step (stats, per body), pushed back by the
// volume barrier once let go, and a body held inverted is reported as staying so, once per
// spell, through the warning counters; the counters survive a checkpoint and are cleared on
// request; bad arguments are refused without changing anything.
//
// The scene: one tet of 10 cm, three nodes fixed, the fourth driven through the opposite face
// at 0.5 m/s (prescribed velocity) and then held there. Its volume ratio is then exactly
// J = z / 0.1 (the tet's height over its rest height), which the tests compare against. The
// same with one 10-node tet: its mid-edge nodes on the base fixed, those of the three edges to
// the apex driven at half its speed, so that every one stays at the middle of its edge and the
// motion is affine: J = z / 0.1 at every quadrature point.
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

const double kTet[12] = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0.1};
const uint32_t kTetNodes[4] = {0, 1, 2, 3};
const uint32_t kBase[3] = {0, 1, 2}, kApex[1] = {3};

// The 10-node tet: corners, then the mid-edge nodes of edges 01, 12, 02 (the base) and 03, 13,
// 23 (to the apex), in the order of lfem_body_add_quadratic_mesh.
const double kTet10[30] = {0,    0,    0, 0.1,  0, 0, 0,    0.1,  0, 0, 0, 0.1, 0.05, 0, 0,
                           0.05, 0.05, 0, 0,    0.05, 0, 0, 0, 0.05, 0.05, 0, 0.05, 0, 0.05, 0.05};
const uint32_t kTet10Nodes[10] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
const uint32_t kBase10[6] = {0, 1, 2, 4, 5, 6}, kApexEdges[3] = {7, 8, 9};

lfem_body add_tet(lfem_world* w, lfem_model model, bool quadratic = false) {
    lfem_body_def d = lfem_body_def_default();
    d.model = model;
    d.young_modulus = 1e4;
    d.damping = 20;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_OK);
    if (quadratic) {
        EXPECT_EQ(lfem_body_add_quadratic_mesh(w, b, kTet10, 10, kTet10Nodes, 1), LFEM_OK) << lfem_last_error();
        EXPECT_EQ(lfem_body_fix_nodes(w, b, kBase10, 6), LFEM_OK);
    } else {
        EXPECT_EQ(lfem_body_add_mesh(w, b, kTet, 4, kTetNodes, 1), LFEM_OK) << lfem_last_error();
        EXPECT_EQ(lfem_body_fix_nodes(w, b, kBase, 3), LFEM_OK);
    }
    return b;
}

lfem_world_def no_gravity() {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    return wd;
}

lfem_warning warning(lfem_world* w, lfem_warning_kind kind) {
    lfem_warning out{};
    EXPECT_EQ(lfem_world_get_warning(w, kind, &out), LFEM_OK) << lfem_last_error();
    return out;
}

// Drives the apex from z = 0.1 to z = -0.05 (0.3 s at 0.5 m/s) and holds it there; returns
// the largest sub-step taken meanwhile.
double crush_and_hold(lfem_world* w, lfem_body b, bool quadratic = false) {
    const double down[3] = {0, 0, -0.5}, half[3] = {0, 0, -0.25};
    EXPECT_EQ(lfem_body_prescribe_node_velocity(w, b, kApex, 1, down), LFEM_OK);
    if (quadratic) {
        EXPECT_EQ(lfem_body_prescribe_node_velocity(w, b, kApexEdges, 3, half), LFEM_OK);
    }
    double largest = 0.0;
    for (int i = 0; i < 30; ++i) {
        EXPECT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
        largest = std::fmax(largest, stats(w).step_size);
    }
    EXPECT_EQ(lfem_body_fix_nodes(w, b, kApex, 1), LFEM_OK);
    if (quadratic) {
        EXPECT_EQ(lfem_body_fix_nodes(w, b, kApexEdges, 3), LFEM_OK);
    }
    return largest;
}

const lfem_model kModels[] = {LFEM_MODEL_PAPER, LFEM_MODEL_COROTATIONAL, LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_LINEAR};

void held_inverted_tet_is_reported_once_per_spell(bool quadratic) {
    for (lfem_model model : kModels) {
        World w(no_gravity());
        const lfem_body b = add_tet(w, model, quadratic);
        uint32_t inverted = 9;
        double min_J = 0, inverted_for = -1;
        ASSERT_EQ(lfem_body_get_inversion(w, b, &inverted, &min_J, &inverted_for), LFEM_OK);
        EXPECT_EQ(inverted, 0u);
        // At rest: exactly the reference (a 10-node tet's F_q = Ds_q J_q^-1 to round-off).
        EXPECT_NEAR(min_J, 1.0, quadratic ? 1e-14 : 0.0);
        EXPECT_EQ(inverted_for, 0.0);
        const double h = crush_and_hold(w, b, quadratic);
        const double z = positions(w, b)[11];
        EXPECT_NEAR(z, -0.05, 1e-12);  // prescribed: 0.3 s at 0.5 m/s
        // Held for 1 s more: inverted all along, J = z / 0.1 exactly (affine tet).
        const uint64_t steps_before = stats(w).steps;
        for (int i = 0; i < 100; ++i) ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK);
        ASSERT_EQ(lfem_body_get_inversion(w, b, &inverted, &min_J, &inverted_for), LFEM_OK);
        EXPECT_EQ(inverted, 1u) << model;
        EXPECT_NEAR(min_J, z / 0.1, 1e-12) << model;
        // It turned inside out at 0.2 s (z = 0): inverted for 1.1 s since, to within the
        // sub-step in which it turned.
        const lfem_world_stats s = stats(w);
        EXPECT_NEAR(inverted_for, 1.1, h + 1e-12) << model;
        EXPECT_EQ(s.inverted_tets, 1u);
        EXPECT_EQ(s.min_jacobian, min_J);
        const lfem_warning stays = warning(w, LFEM_WARNING_STAYS_INVERTED);
        EXPECT_EQ(stays.count, 1u) << model;  // one spell
        EXPECT_EQ(stays.last_body.index, b.index);
        EXPECT_EQ(stays.last_body.generation, b.generation);
        EXPECT_NEAR(stays.last_time, 0.2 + 0.5, h + s.step_size) << model;
        // Every sub-step since the turn counted once (one body).
        const lfem_warning each = warning(w, LFEM_WARNING_INVERTED_TETS);
        EXPECT_GE(each.count, s.steps - steps_before) << model;
        EXPECT_LE(each.count, s.steps) << model;
        EXPECT_EQ(each.last_time, s.time);
        EXPECT_EQ(warning(w, LFEM_WARNING_FALLEN_IN).count, 0u);
        EXPECT_EQ(warning(w, LFEM_WARNING_UNCONVERGED).count, 0u);

        // Let go: the material (Hooke's law on the strain, the barrier below J = 0.2) pushes
        // the apex back through the base; damped, the tet comes to rest at its shape.
        ASSERT_EQ(lfem_body_release_nodes(w, b, kApex, 1), LFEM_OK);
        if (quadratic) {
            ASSERT_EQ(lfem_body_release_nodes(w, b, kApexEdges, 3), LFEM_OK);
        }
        for (int i = 0; i < 300; ++i) ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK);
        ASSERT_EQ(lfem_body_get_inversion(w, b, &inverted, &min_J, &inverted_for), LFEM_OK);
        EXPECT_EQ(inverted, 0u) << model;
        EXPECT_EQ(inverted_for, 0.0) << model;
        EXPECT_NEAR(min_J, 1.0, 1e-3) << model;  // at rest again (damping 20 for 3 s: e^-60)
        EXPECT_EQ(warning(w, LFEM_WARNING_STAYS_INVERTED).count, 1u) << model;
        EXPECT_EQ(stats(w).inverted_tets, 0u);
    }
}

}  // namespace

TEST(Inversion, AHeldInvertedTetIsReportedAndStaysReportedOncePerSpell) {
    held_inverted_tet_is_reported_once_per_spell(false);
}

// A 10-node tet counts as inverted when J <= 0 at one of its quadrature points, its min J the
// smallest at them; the barrier acts at every point, and pushes it back as it does a 4-node tet.
TEST(Inversion, AHeldInvertedTenNodeTetIsReportedAndPushedBack) { held_inverted_tet_is_reported_once_per_spell(true); }

TEST(Inversion, WarningsSurviveACheckpointAndAreClearedOnRequest) {
    const std::string path = ::testing::TempDir() + "lfem_inversion.ckpt";
    World w(no_gravity());
    const lfem_body b = add_tet(w, LFEM_MODEL_NEO_HOOKEAN);
    crush_and_hold(w, b);
    for (int i = 0; i < 60; ++i) ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK);
    const lfem_status saved = lfem_world_save(w, path.c_str());
    if (saved == LFEM_UNSUPPORTED) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    ASSERT_EQ(saved, LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    for (int k = 0; k < LFEM_WARNING_KIND_COUNT; ++k) {
        const lfem_warning a = warning(w, lfem_warning_kind(k)), c = warning(loaded, lfem_warning_kind(k));
        EXPECT_EQ(a.count, c.count) << k;
        EXPECT_EQ(a.last_time, c.last_time) << k;
        EXPECT_EQ(a.last_body.index, c.last_body.index) << k;
        EXPECT_EQ(a.last_body.generation, c.last_body.generation) << k;
    }
    uint32_t inverted = 0;
    double min_J = 0, since_a = 0, since_c = 0;
    ASSERT_EQ(lfem_body_get_inversion(w, b, nullptr, nullptr, &since_a), LFEM_OK);
    ASSERT_EQ(lfem_body_get_inversion(loaded, b, &inverted, &min_J, &since_c), LFEM_OK);
    EXPECT_EQ(inverted, 1u);
    EXPECT_EQ(since_a, since_c);
    // The spell goes on across the checkpoint: it is not reported a second time.
    for (int i = 0; i < 60; ++i) ASSERT_EQ(lfem_world_step(loaded, 0.01), LFEM_OK);
    EXPECT_EQ(warning(loaded, LFEM_WARNING_STAYS_INVERTED).count, 1u);
    ASSERT_EQ(lfem_world_clear_warnings(loaded), LFEM_OK);
    for (int k = 0; k < LFEM_WARNING_KIND_COUNT; ++k) {
        const lfem_warning c = warning(loaded, lfem_warning_kind(k));
        EXPECT_EQ(c.count, 0u);
        EXPECT_EQ(c.last_time, 0.0);
        EXPECT_EQ(c.last_body.generation, 0u);
    }
    lfem_world_destroy(loaded);
    std::remove(path.c_str());
}

TEST(Inversion, AContactSolveStoppedShortIsCounted) {
    // One sweep with a tolerance nothing meets: every sub-step in contact is unconverged.
    lfem_world_def wd = lfem_world_def_default();
    wd.contact_iterations = 1;
    wd.contact_tolerance = 1e-12;
    World w(wd);
    Mesh floor, cube;
    make_box_mesh(floor, 1, 1, 0.1, 2, 2, 1, -0.5, -0.5, -0.1);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    add_body(w, fd, floor);
    make_box_mesh(cube, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.linear_velocity[2] = -1;
    add_body(w, d, cube);
    for (int i = 0; i < 10; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const lfem_warning u = warning(w, LFEM_WARNING_UNCONVERGED);
    EXPECT_GT(u.count, 0u);
    EXPECT_LE(u.count, stats(w).steps);
    EXPECT_EQ(u.last_body.generation, 0u);  // about no body
}

TEST(Inversion, BadArgumentsAreRefusedAndChangeNothing) {
    World w(no_gravity());
    const lfem_body b = add_tet(w, LFEM_MODEL_PAPER);
    crush_and_hold(w, b);
    const std::vector<unsigned char> before = fingerprint(w, {b});
    lfem_warning out{};
    EXPECT_EQ(lfem_world_get_warning(w, lfem_warning_kind(LFEM_WARNING_KIND_COUNT), &out), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("kind"), std::string::npos) << lfem_last_error();
    EXPECT_EQ(lfem_world_get_warning(w, lfem_warning_kind(-1), &out), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_get_warning(w, LFEM_WARNING_FALLEN_IN, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_get_warning(nullptr, LFEM_WARNING_FALLEN_IN, &out), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_clear_warnings(nullptr), LFEM_INVALID_ARGUMENT);
    uint32_t n = 0;
    EXPECT_EQ(lfem_body_get_inversion(w, lfem_body{b.index, b.generation + 1}, &n, nullptr, nullptr),
              LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_get_inversion(nullptr, b, &n, nullptr, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(fingerprint(w, {b}), before);
}
