// A force at a point for one call (lfem_body_apply_force, issue 36): central differences give a
// body the force times the call's length as momentum, exactly (sum m dv = sum f h over the
// sub-steps, and the tet's weights sum to 1), and its moment about the origin up to how far the
// body moved while it pushed; the next call has no force. A pending force survives a checkpoint;
// it adds to the caller's lasting node forces, which stay. Bad input changes nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

double largest_move(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0.0;
    for (std::size_t i = 0; i < a.size(); i += 3)
        d = std::max(d, std::hypot(a[i] - b[i], a[i + 1] - b[i + 1], a[i + 2] - b[i + 2]));
    return d;
}

// One call of dt with the force F at p, from rest in zero gravity: dP = F dt to round-off
// (1e-12 of |F| dt: sums over the nodes); dL = p x F dt up to the moment of the force about
// where its nodes were: each node k moved by at most d, and carries w_k F with |w_k| summing to
// at most `weight_sum`, so the moment differs from p x F by at most weight_sum d |F| at any time.
void expect_force_for_one_call(lfem_world* w, lfem_body b, const double* p, const double* F, double dt,
                               double weight_sum, const char* what) {
    const Momenta before = momenta(w, b);
    const std::vector<double> x0 = positions(w, b);
    ASSERT_EQ(lfem_body_apply_force(w, b, p, F), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(momenta(w, b).P[0], before.P[0]) << what << ": a force is no impulse";
    ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
    const Momenta after = momenta(w, b);
    const double size = std::hypot(F[0], F[1], F[2]);
    const double d = largest_move(x0, positions(w, b));
    const double pxF[3] = {p[1] * F[2] - p[2] * F[1], p[2] * F[0] - p[0] * F[2], p[0] * F[1] - p[1] * F[0]};
    std::printf("%s: dP = (%.9g, %.9g, %.9g) N s for F dt = (%.9g, %.9g, %.9g); moved %.3g m\n", what,
                after.P[0] - before.P[0], after.P[1] - before.P[1], after.P[2] - before.P[2], F[0] * dt, F[1] * dt,
                F[2] * dt, d);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(after.P[k] - before.P[k], F[k] * dt, 1e-12 * size * dt) << what;
        EXPECT_NEAR(after.L[k] - before.L[k], pxF[k] * dt, weight_sum * d * size * dt + 1e-12 * size * dt) << what;
    }
    // The next call: no force, no change of momentum.
    ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
    const Momenta later = momenta(w, b);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(later.P[k], after.P[k], 1e-12 * size * dt) << what << ": the force stayed";
}

lfem_world_def weightless() {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    return wd;
}

}  // namespace

TEST(Forces, ASoftCubeFeelsTheForceForOneCall) {
    for (int quadratic = 0; quadratic < 2; ++quadratic) {
        World w(weightless());
        Mesh m;
        if (quadratic)
            make_quadratic_box_mesh(m, 0.2, 0.2, 0.2, 2, 2, 2, -0.1, -0.1, 0.0);
        else
            make_box_mesh(m, 0.2, 0.2, 0.2, 3, 3, 3, -0.1, -0.1, 0.0);
        lfem_body_def d = lfem_body_def_default();
        d.model = LFEM_MODEL_COROTATIONAL;
        const lfem_body b = add_body(w, d, m);
        // A call of another length first: the force's call then starts after sub-steps of
        // another h (its first sub-step's h_mid is not h).
        ASSERT_EQ(lfem_world_step(w, 0.0103), LFEM_OK) << lfem_last_error();
        const double p[3] = {0.031, -0.047, 0.083}, F[3] = {4.0, -1.0, 2.5};
        // Inside a tet the 4-node weights are >= 0 (sum 1); the 10-node ones reach -1/8 at
        // most at a corner and 1/2 at a mid-edge (|w| summing to at most 3).
        expect_force_for_one_call(w, b, p, F, 1.0 / 60, quadratic ? 3.0 : 1.0, quadratic ? "10-node cube" : "4-node cube");
    }
}

TEST(Forces, ARigidBoxFeelsTheForceAndItsMomentAtAPointOutsideIt) {
    World w(weightless());
    Mesh m;
    make_box_mesh(m, 0.2, 0.1, 0.05, 2, 2, 2, 0.5, -0.05, -0.025);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_RIGID;
    const lfem_body b = add_body(w, d, m);
    // 0.05 m beyond the box's end. A rigid motion's displacement is affine, so the point moves
    // by sum |w_k| d at most, as for a deformable body. The nearest tet's weights, extrapolated:
    // a negative one is at most the distance beyond its face over the tet's height there (0.05
    // m over no less than 0.02 m in cells of 0.1 x 0.05 x 0.025 m), so |w| sums to at most
    // 1 + 2 * 3 * 2.5 = 16.
    const double p[3] = {0.75, 0.04, 0.0}, F[3] = {0, 3.0, 1.0};
    expect_force_for_one_call(w, b, p, F, 1.0 / 60, 16.0, "rigid box");
}

// A force on top of the caller's node forces: both act during the call, the node forces stay.
TEST(Forces, AForceAddsToTheNodeForcesWhichStay) {
    World w(weightless());
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    const uint32_t node = 0;
    const double f[3] = {0, 0, 2.0}, F[3] = {1.0, 0, 0}, p[3] = {0.05, 0.05, 0.05}, dt = 0.01;
    ASSERT_EQ(lfem_body_set_node_forces(w, b, &node, 1, f), LFEM_OK) << lfem_last_error();
    const Momenta m0 = momenta(w, b);
    ASSERT_EQ(lfem_body_apply_force(w, b, p, F), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(lfem_body_apply_force(w, b, p, F), LFEM_OK) << lfem_last_error();  // two add up
    ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
    const Momenta m1 = momenta(w, b);
    ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
    const Momenta m2 = momenta(w, b);
    // Round-off of sums over 27 nodes: 1e-12 N s.
    EXPECT_NEAR(m1.P[0] - m0.P[0], 2 * F[0] * dt, 1e-12);
    EXPECT_NEAR(m1.P[2] - m0.P[2], f[2] * dt, 1e-12);
    EXPECT_NEAR(m2.P[0] - m1.P[0], 0.0, 1e-12);
    EXPECT_NEAR(m2.P[2] - m1.P[2], f[2] * dt, 1e-12);
}

// A pending force is part of the world: a checkpoint saved before the call carries it, and the
// loaded world's call is the same, bit for bit.
TEST(Forces, APendingForceSurvivesACheckpoint) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    World w;
    add_plane_floor(w);
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0.2);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const double p[3] = {0.02, 0.05, 0.25}, F[3] = {0, 30.0, 0};
    ASSERT_EQ(lfem_body_apply_force(w, b, p, F), LFEM_OK) << lfem_last_error();
    const std::string path = ::testing::TempDir() + "lfem_pending_force.ckpt";
    ASSERT_EQ(lfem_world_save(w, path.c_str()), LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    std::remove(path.c_str());
    for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        ASSERT_EQ(lfem_world_step(loaded, 1.0 / 60), LFEM_OK);
        EXPECT_EQ(fingerprint(w, {b}), fingerprint(loaded, {b})) << "call " << k;
    }
    // And the force acted: the cube moved along +y (30 N on 1.1 kg for 1/60 s: 0.45 m/s).
    EXPECT_GT(velocities(loaded, b)[1], 0.2);
    lfem_world_destroy(loaded);
}

// Refused calls leave the world as a twin that never saw them: the next call is the same.
TEST(Forces, BadInputIsRefusedAndChangesNothing) {
    World w, twin;
    lfem_body floor[2], body[2];
    for (int k = 0; k < 2; ++k) {
        lfem_world* x = k ? twin.w : w.w;
        floor[k] = add_plane_floor(x);
        Mesh m;
        make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0.5);
        body[k] = add_body(x, lfem_body_def_default(), m);
        ASSERT_EQ(lfem_world_step(x, 1.0 / 60), LFEM_OK);
    }
    const lfem_body b = body[0];
    const double inside[3] = {0.05, 0.05, 0.55}, far[3] = {0.05, 0.05, 2.0}, F[3] = {1, 0, 0};
    const double nan3[3] = {NAN, 0, 0}, inf3[3] = {0, HUGE_VAL, 0};
    EXPECT_EQ(lfem_body_apply_force(w, b, far, F), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("farther than"), std::string::npos) << lfem_last_error();
    EXPECT_EQ(lfem_body_apply_force(w, b, inside, nan3), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_force(w, b, inside, inf3), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_force(w, b, nan3, F), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_force(w, b, nullptr, F), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_force(w, b, inside, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_force(w, floor[0], inside, F), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_force(w, lfem_body{b.index, b.generation + 5}, inside, F), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_apply_force(nullptr, b, inside, F), LFEM_INVALID_ARGUMENT);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    ASSERT_EQ(lfem_world_step(twin, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(fingerprint(w, {b}), fingerprint(twin, {body[1]}));
}
