// A one-shot impulse at a world point (lfem_body_apply_impulse, issue 36): the body gains the
// impulse J as momentum and p x J as angular momentum about the origin, exactly (the tet's
// shape functions sum to 1 and reproduce the point); the kinetic energy it brings is booked as
// the caller's work. Bad input changes nothing.
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// dP = J and dL = p x J, to round-off of sums over the nodes (1e-12 of |J| times the body's
// size, 0.2 m, and of |p| |J|).
void expect_impulse(const Momenta& before, const Momenta& after, const double* p, const double* J, const char* what) {
    const double pxJ[3] = {p[1] * J[2] - p[2] * J[1], p[2] * J[0] - p[0] * J[2], p[0] * J[1] - p[1] * J[0]};
    const double size = std::sqrt(J[0] * J[0] + J[1] * J[1] + J[2] * J[2]);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(after.P[k] - before.P[k], J[k], 1e-12 * size) << what;
        EXPECT_NEAR(after.L[k] - before.L[k], pxJ[k], 1e-12 * size) << what;
    }
}

}  // namespace

TEST(Impulses, ASoftCubeGainsTheImpulseAndItsMomentAtThePoint) {
    for (int quadratic = 0; quadratic < 2; ++quadratic) {
        lfem_world_def wd = lfem_world_def_default();
        wd.gravity[2] = 0;
        World w(wd);
        Mesh m;
        if (quadratic)
            make_quadratic_box_mesh(m, 0.2, 0.2, 0.2, 2, 2, 2, -0.1, -0.1, 0.0);
        else
            make_box_mesh(m, 0.2, 0.2, 0.2, 3, 3, 3, -0.1, -0.1, 0.0);
        lfem_body_def d = lfem_body_def_default();
        d.model = LFEM_MODEL_COROTATIONAL;
        const lfem_body b = add_body(w, d, m);
        const double v0[3] = {0.1, 0, -0.2};
        std::vector<double> v(3 * node_count(w, b));
        for (size_t i = 0; i < v.size(); ++i) v[i] = v0[i % 3];
        ASSERT_EQ(lfem_body_set_velocities(w, b, v.data(), uint32_t(v.size() / 3)), LFEM_OK);
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        const Momenta before = momenta(w, b);
        const lfem_world_stats s0 = stats(w);
        // Inside, off every axis; then on the surface (the top face, z = 0.2 m plus a hair).
        const double p[3] = {0.031, -0.047, 0.083}, J[3] = {0.4, -0.1, 0.25};
        ASSERT_EQ(lfem_body_apply_impulse(w, b, p, J), LFEM_OK) << lfem_last_error();
        // The cube has moved during the step: the point is taken where the nodes are now.
        const Momenta after = momenta(w, b);
        expect_impulse(before, after, p, J, quadratic ? "10-node" : "4-node");
        const lfem_world_stats s1 = stats(w);
        const double dK = s1.kinetic_energy - s0.kinetic_energy;
        std::printf("%s cube: kinetic energy +%.6g J, work booked +%.6g J\n", quadratic ? "10-node" : "4-node", dK,
                    s1.external_work - s0.external_work);
        EXPECT_NEAR(s1.external_work - s0.external_work, dK, 1e-12 * std::fabs(dK) + 1e-15);
        EXPECT_NEAR(s1.energy_error, s0.energy_error, 1e-12 * std::fabs(dK) + 1e-15);
        const double top[3] = {0.0, 0.02, 0.2 + 0.2 * v0[2] / 60 + 1e-6};
        EXPECT_EQ(lfem_body_apply_impulse(w, b, top, J), LFEM_OK) << lfem_last_error();
    }
}

TEST(Impulses, ARigidBoxGainsTheImpulseAndItsMoment) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    World w(wd);
    Mesh m;
    make_box_mesh(m, 0.2, 0.1, 0.05, 2, 2, 2, 0.5, -0.05, -0.025);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_RIGID;
    d.angular_velocity[2] = 1.0;
    const lfem_body b = add_body(w, d, m);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const Momenta before = momenta(w, b);
    const double p[3] = {0.65, 0.04, 0.0}, J[3] = {0, 0.3, 0.1};  // anywhere: a rigid body takes it whole
    ASSERT_EQ(lfem_body_apply_impulse(w, b, p, J), LFEM_OK) << lfem_last_error();
    expect_impulse(before, momenta(w, b), p, J, "rigid");
}

TEST(Impulses, BadInputIsRefusedAndChangesNothing) {
    World w;
    const lfem_body floor = add_plane_floor(w);
    Mesh m;
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0.5);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(w, {b});
    const double inside[3] = {0.05, 0.05, 0.55}, far[3] = {0.05, 0.05, 2.0}, J[3] = {1, 0, 0};
    const double nan3[3] = {NAN, 0, 0};
    EXPECT_EQ(lfem_body_apply_impulse(w, b, far, J), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("farther than"), std::string::npos) << lfem_last_error();
    EXPECT_EQ(lfem_body_apply_impulse(w, b, inside, nan3), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_impulse(w, b, nan3, J), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_impulse(w, b, nullptr, J), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_impulse(w, b, inside, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_impulse(w, floor, inside, J), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_apply_impulse(w, lfem_body{b.index, b.generation + 5}, inside, J), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_apply_impulse(nullptr, b, inside, J), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(fingerprint(w, {b}), before);
}
