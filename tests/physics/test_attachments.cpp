// Attachments (issue 17): nodes held at offsets in a target's frame by the links of the
// multiplier solve. Checked against closed forms and conservation laws; bad input is refused
// and changes nothing.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

const double kG = 9.81;

lfem_attachment attach(lfem_world* w, lfem_body body, const std::vector<uint32_t>& nodes, lfem_body target,
                       double break_force = 0.0) {
    lfem_attachment_def d = lfem_attachment_def_default();
    d.body = body;
    d.target = target;
    d.nodes = nodes.data();
    d.node_count = uint32_t(nodes.size());
    d.break_force = break_force;
    lfem_attachment a{};
    EXPECT_EQ(lfem_attachment_create(w, &d, &a), LFEM_OK) << lfem_last_error();
    return a;
}

std::vector<uint32_t> nodes_near_z(lfem_world* w, lfem_body b, double z) {
    const double lo[3] = {-1, -1, z - 1e-6}, hi[3] = {1, 1, z + 1e-6};
    return nodes_in_box(w, b, lo, hi);
}

// A soft bar 0.3 m long (0.03 x 0.03 section, 10 cells), hanging along -z from z = 0, its
// axis at x = x0. Corotational: its elastic forces are torque-free at any strain (the paper
// model's single frame is not, at the strains of a swinging rope).
lfem_body hanging_bar(lfem_world* w, Mesh& mesh, double damping = 10.0, double x0 = 0.0) {
    make_box_mesh(mesh, 0.03, 0.03, 0.3, 1, 1, 10, x0 - 0.015, -0.015, -0.3);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 2e5;
    d.damping = damping;
    return add_body(w, d, mesh);
}

std::array<double, 3> force_of(lfem_world* w, lfem_attachment a) {
    std::array<double, 3> f{};
    EXPECT_EQ(lfem_attachment_get_force(w, a, f.data()), LFEM_OK) << lfem_last_error();
    return f;
}

double norm3(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

// Held by a frame that never moves, the top of the bar is a support: the attachment carries the
// bar's weight, and the bar hangs exactly as one whose top nodes are fixed.
TEST(Attachments, ASoftBarHangingFromAFixedFrameCarriesItsWeight) {
    World held, fixed;
    Mesh m1, m2;
    const lfem_body a = hanging_bar(held, m1), b = hanging_bar(fixed, m2);
    const std::vector<uint32_t> top = nodes_near_z(held, a, 0.0);
    ASSERT_EQ(top.size(), 4u);
    const lfem_attachment att = attach(held, a, top, lfem_body{});
    ASSERT_EQ(lfem_body_fix_nodes(fixed, b, top.data(), uint32_t(top.size())), LFEM_OK);
    for (int i = 0; i < 180; ++i) {  // 3 s: damping 10 leaves e^-30 of the first swing
        ASSERT_EQ(lfem_world_step(held, 1.0 / 60), LFEM_OK) << lfem_last_error();
        ASSERT_EQ(lfem_world_step(fixed, 1.0 / 60), LFEM_OK);
    }
    double mass = 0;
    lfem_body_get_mass(held, a, &mass);
    const std::array<double, 3> f = force_of(held, att);
    std::printf("hanging bar: attachment force (%.6g, %.6g, %.6g) N, m g = %.6g N\n", f[0], f[1], f[2], mass * kG);
    // At rest the held nodes carry the weight: the rest of the bar is in equilibrium. What is
    // left of the swing (e^-30) and the solve's stopping tolerance (1e-9 of an edge at rest,
    // times the nodes' stiffness m/h^2) are far below 1e-6 of m g.
    EXPECT_NEAR(f[2], mass * kG, 1e-6 * mass * kG);
    EXPECT_NEAR(f[0], 0.0, 1e-6 * mass * kG);
    EXPECT_NEAR(f[1], 0.0, 1e-6 * mass * kG);
    // And it hangs as the fixed bar does: the held nodes are where fixed ones are, to the
    // solve's tolerance (its 1e-9 of an edge per step at rest, 3 cm edges: below 1e-9 m).
    const std::vector<double> xa = positions(held, a), xb = positions(fixed, b);
    double largest = 0;
    for (size_t k = 0; k < xa.size(); ++k) largest = std::max(largest, std::fabs(xa[k] - xb[k]));
    EXPECT_LT(largest, 1e-8);
}

// A rigid weight on a soft rope, thrown swinging without gravity: the attachment's forces act
// equal and opposite, so the linear momentum of rope and weight together is kept to round-off,
// while the weight stays on the rope's end. Angular momentum: the weight takes its share at
// the point of its predicted configuration (the solve's response of a rigid body is linear
// about it), so each sub-step the pair's two points differ by the weight's own correction,
// O(F h^2): a change of O(h) over the run, which halves when the step halves.
struct Flight {
    double dP = 0, p_scale = 0, dL = 0, l_scale = 0, worst_gap = 0, largest_force = 0;
};

Flight rope_and_weight(double time_step) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    wd.time_step = time_step;
    World w(wd);
    Mesh rope_mesh, weight_mesh;
    const lfem_body rope = hanging_bar(w, rope_mesh, 0.0);
    make_box_mesh(weight_mesh, 0.06, 0.06, 0.06, 1, 1, 1, -0.03, -0.03, -0.36);
    lfem_body_def rd = lfem_body_def_default();
    rd.type = LFEM_BODY_RIGID;
    rd.density = 3000;
    rd.linear_velocity[0] = 0.5;
    const lfem_body weight = add_body(w, rd, weight_mesh);
    const std::vector<uint32_t> bottom = nodes_near_z(w, rope, -0.3);
    const lfem_attachment att = attach(w, rope, bottom, weight);
    // The rope swings across: its top end moves, so the pair turns and stretches.
    std::vector<double> v(3 * rope_mesh.nodes(), 0.0);
    const std::vector<double> x0 = positions(w, rope);
    for (uint32_t i = 0; i < rope_mesh.nodes(); ++i) v[3 * i + 1] = 2.0 * (x0[3 * i + 2] + 0.3);  // 0 at the bottom
    EXPECT_EQ(lfem_body_set_velocities(w, rope, v.data(), rope_mesh.nodes()), LFEM_OK);
    auto momenta = [&](double P[3], double L[3]) {
        double p[3], l[3];
        for (int k = 0; k < 3; ++k) P[k] = L[k] = 0;
        for (lfem_body b : {rope, weight}) {
            lfem_body_get_momentum(w, b, p, l);
            for (int k = 0; k < 3; ++k) P[k] += p[k], L[k] += l[k];
        }
    };
    // Where each held node sits in the weight's frame (its node 0 and its rotation).
    auto in_weight_frame = [&](std::vector<double>& r) {
        double R[9];
        lfem_body_get_rotation(w, weight, R);
        const std::vector<double> x = positions(w, rope), xw = positions(w, weight);
        r.clear();
        for (uint32_t n : bottom)
            for (int i = 0; i < 3; ++i) {
                double s = 0;
                for (int k = 0; k < 3; ++k) s += R[3 * k + i] * (x[3 * n + k] - xw[k]);  // R^T (x - x_w0)
                r.push_back(s);
            }
    };
    double P0[3], L0[3], P[3], L[3];
    momenta(P0, L0);
    std::vector<double> r0, r;
    in_weight_frame(r0);
    Flight out;
    for (int i = 0; i < 60; ++i) {
        EXPECT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        out.largest_force = std::max(out.largest_force, norm3(force_of(w, att).data()));
        in_weight_frame(r);
        for (size_t k = 0; k < r.size(); ++k) out.worst_gap = std::max(out.worst_gap, std::fabs(r[k] - r0[k]));
    }
    momenta(P, L);
    const double dP[3] = {P[0] - P0[0], P[1] - P0[1], P[2] - P0[2]}, dL[3] = {L[0] - L0[0], L[1] - L0[1], L[2] - L0[2]};
    out.dP = norm3(dP), out.p_scale = norm3(P0), out.dL = norm3(dL), out.l_scale = norm3(L0);
    return out;
}

TEST(Attachments, ARigidWeightOnASoftRopeKeepsMomentumInFreeFlight) {
    const Flight f = rope_and_weight(0.0);
    std::printf("rope and weight: momentum change %.3g of |P| (%.3g kg m/s), angular %.3g of |L|, largest "
                "attachment force %.3g N, largest drift of a held node from its place on the weight %.3g m\n",
                f.dP / f.p_scale, f.p_scale, f.dL / f.l_scale, f.largest_force, f.worst_gap);
    // Round-off of 60 calls of about a thousand sub-steps, each ~1e-16 relative: 1e-11.
    EXPECT_LT(f.dP, 1e-11 * f.p_scale);
    EXPECT_GT(f.largest_force, 0.1);  // the weight was pulled along: the test is not vacuous
    // The held nodes stayed where they were attached on the weight, to the solve's stopping
    // tolerance (1e-3 of a step's relative motion: metres per second times a millisecond
    // sub-step, so ~1e-6 m; 1e-5 m bounds it with ten sweeps' worth).
    EXPECT_LT(f.worst_gap, 1e-5);
    // Angular momentum: first order in the step (see above).
    const Flight coarse = rope_and_weight(8e-4), fine = rope_and_weight(4e-4);
    std::printf("  angular momentum change %.3g at h = 8e-4 s, %.3g at 4e-4 s (ratio %.2f)\n", coarse.dL, fine.dL,
                fine.dL / coarse.dL);
    EXPECT_LT(fine.dL, 0.6 * coarse.dL);
    EXPECT_LT(coarse.dL, 1e-2 * coarse.l_scale);
}

// Held by a kinematic body moving at 0.2 m/s and turning, and by a frame the caller moves each
// frame: the held nodes are where the target's motion takes their offsets, at the end of every
// call (the frame is moved uniformly over the call's sub-steps and ends where it was set).
TEST(Attachments, HeldNodesFollowAKinematicBodyAndTheCallersFrame) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh bar_a, bar_b, hand;
    const lfem_body a = hanging_bar(w, bar_a), b = hanging_bar(w, bar_b, 10.0, 0.3);
    make_box_mesh(hand, 0.05, 0.05, 0.05, 1, 1, 1, -0.025, -0.025, 0.01);  // 1 cm above: no contact
    lfem_body_def kd = lfem_body_def_default();
    kd.type = LFEM_BODY_KINEMATIC;
    kd.linear_velocity[0] = 0.2;
    kd.angular_velocity[2] = 0.5;
    const lfem_body kin = add_body(w, kd, hand);
    const std::vector<uint32_t> top_a = nodes_near_z(w, a, 0.0), top_b = nodes_near_z(w, b, 0.0);
    attach(w, a, top_a, kin);
    lfem_attachment_def fd = lfem_attachment_def_default();  // the frame at the bar's axis
    fd.body = b, fd.nodes = top_b.data(), fd.node_count = uint32_t(top_b.size());
    fd.frame[0] = 0.3;
    lfem_attachment frame{};
    ASSERT_EQ(lfem_attachment_create(w, &fd, &frame), LFEM_OK) << lfem_last_error();
    const std::vector<double> xa0 = positions(w, a), xb0 = positions(w, b);
    // The kinematic body's centre: the mean of its 8 nodes at the start (it turns about it).
    std::vector<double> xk = positions(w, kin);
    double c0[3] = {0, 0, 0};  // (0, 0, 0.035) by symmetry
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) c0[k] += xk[3 * i + k] / 8;
    double worst_a = 0, worst_b = 0;
    for (int i = 1; i <= 30; ++i) {
        const double t = i / 60.0;
        // The caller's frame: up at 0.1 m/s, turned about x by 0.3 rad/s.
        const double angle = 0.3 * t, f[7] = {0.3, 0, 0.1 * t, std::cos(angle / 2), std::sin(angle / 2), 0, 0};
        ASSERT_EQ(lfem_attachment_set_frame(w, frame, f), LFEM_OK);
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const std::vector<double> xa = positions(w, a), xb = positions(w, b);
        const double turn = 0.5 * t, ca = std::cos(turn), sa = std::sin(turn);
        for (uint32_t n : top_a) {
            const double rx = xa0[3 * n] - c0[0], ry = xa0[3 * n + 1] - c0[1];
            const double ex = c0[0] + 0.2 * t + ca * rx - sa * ry, ey = c0[1] + ca * ry + sa * rx, ez = xa0[3 * n + 2];
            worst_a = std::max({worst_a, std::fabs(xa[3 * n] - ex), std::fabs(xa[3 * n + 1] - ey), std::fabs(xa[3 * n + 2] - ez)});
        }
        const double cb = std::cos(angle), sb = std::sin(angle);
        for (uint32_t n : top_b) {
            const double y = xb0[3 * n + 1], z = xb0[3 * n + 2];
            const double ex = xb0[3 * n], ey = cb * y - sb * z, ez = 0.1 * t + sb * y + cb * z;  // about x = 0.3
            worst_b = std::max({worst_b, std::fabs(xb[3 * n] - ex), std::fabs(xb[3 * n + 1] - ey), std::fabs(xb[3 * n + 2] - ez)});
        }
    }
    std::printf("held nodes off their target: %.3g m (kinematic body), %.3g m (caller's frame)\n", worst_a, worst_b);
    // An immovable target is met in one Gauss-Seidel update per node (H = 1/mhat exactly):
    // what is left is round-off of the positions (1e-16 of 0.1 m) and of the rotations.
    EXPECT_LT(worst_a, 1e-12);
    EXPECT_LT(worst_b, 1e-12);
}

// A body hanging from the caller's frame falls asleep as one hanging from a static body does
// (issue 36: it never slept), keeps reporting the weight its attachment carries, and wakes when
// the frame moves, its held nodes following the frame.
TEST(Attachments, ABodyHangingFromTheCallersFrameSleepsAndWakesWhenTheFrameMoves) {
    lfem_world_def wd = lfem_world_def_default();
    wd.enable_sleep = 1;
    World w(wd);
    Mesh m;
    const lfem_body bar = hanging_bar(w, m);
    const std::vector<uint32_t> top = nodes_near_z(w, bar, 0.0);
    const lfem_attachment att = attach(w, bar, top, lfem_body{});
    int calls = 0;
    while (calls < 600 && lfem_body_is_awake(w, bar)) {  // damping 10: the swing is gone in 3 s
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        ++calls;
    }
    std::printf("bar held by a frame: asleep after %d calls\n", calls);
    ASSERT_EQ(lfem_body_is_awake(w, bar), 0);
    // Asleep, it carries its weight (the last solve's multipliers) and stays where it is,
    // bitwise. It fell asleep still ringing below sleep_velocity v_s along its axis: the
    // stretch's swing about the static one is then at most v_s / omega_1, and the force's
    // at most M omega_1 v_s, for the first axial mode omega_1 = (pi / 2) c / L, c = sqrt(E / rho).
    double mass = 0;
    lfem_body_get_mass(w, bar, &mass);
    const double omega_1 = 0.5 * M_PI * std::sqrt(2e5 / 1000.0) / 0.3;
    EXPECT_NEAR(force_of(w, att)[2], mass * kG, mass * omega_1 * wd.sleep_velocity);
    const std::vector<double> x_asleep = positions(w, bar);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(positions(w, bar), x_asleep);
    // The frame moves 5 cm along x: the bar wakes at once and its held nodes are there at the
    // end of the next call (a held node meets an immovable target in one update: round-off).
    const double f[7] = {0.05, 0, 0, 1, 0, 0, 0};
    ASSERT_EQ(lfem_attachment_set_frame(w, att, f), LFEM_OK);
    double got[7];
    ASSERT_EQ(lfem_attachment_get_frame(w, att, got), LFEM_OK) << lfem_last_error();
    for (int k = 0; k < 7; ++k) EXPECT_EQ(got[k], f[k]);
    EXPECT_EQ(lfem_attachment_get_frame(w, att, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_is_awake(w, bar), 1);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<double> x = positions(w, bar);
    for (uint32_t n : top) EXPECT_NEAR(x[3 * n], x_asleep[3 * n] + 0.05, 1e-12);
}

// A weight that pulls harder than the attachment holds breaks it: the handle goes stale, an
// event says so with the force, and the bar falls freely from then on.
TEST(Attachments, BreaksAboveItsForceWithAnEvent) {
    World w;
    Mesh mesh;
    const lfem_body bar = hanging_bar(w, mesh);
    double mass = 0;
    lfem_body_get_mass(w, bar, &mass);
    const lfem_attachment att = attach(w, bar, nodes_near_z(w, bar, 0.0), lfem_body{}, 0.5 * mass * kG);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(lfem_attachment_is_valid(w, att), 0);
    uint32_t count = 0;
    std::vector<lfem_event> events(16);
    ASSERT_EQ(lfem_world_get_events(w, events.data(), 16, &count), LFEM_OK);
    int broken = 0;
    for (uint32_t i = 0; i < count; ++i)
        if (events[i].type == LFEM_EVENT_ATTACHMENT_BROKEN) {
            ++broken;
            EXPECT_EQ(events[i].attachment.index, att.index);
            EXPECT_EQ(events[i].attachment.generation, att.generation);
            EXPECT_EQ(events[i].body_a.index, bar.index);
            EXPECT_GT(events[i].max_force, 0.5 * mass * kG);
        }
    EXPECT_EQ(broken, 1);
    double f[3];
    EXPECT_EQ(lfem_attachment_get_force(w, att, f), LFEM_INVALID_HANDLE);
}

TEST(Attachments, BadInputIsRefusedAndChangesNothing) {
    World w;
    Mesh mesh, block;
    const lfem_body bar = hanging_bar(w, mesh);
    make_box_mesh(block, 0.1, 0.1, 0.1, 1, 1, 1, 0.2, 0, 0);
    const lfem_body soft = add_body(w, lfem_body_def_default(), block);
    const std::vector<uint32_t> top = nodes_near_z(w, bar, 0.0);
    const lfem_attachment good = attach(w, bar, top, lfem_body{});
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(w, {bar, soft});
    lfem_attachment out{};
    auto refused = [&](lfem_attachment_def d, lfem_status status, const char* what) {
        EXPECT_EQ(lfem_attachment_create(w, &d, &out), status) << what;
        EXPECT_STRNE(lfem_last_error(), "") << what;
    };
    lfem_attachment_def d = lfem_attachment_def_default();
    d.body = bar, d.nodes = top.data(), d.node_count = uint32_t(top.size());
    EXPECT_EQ(lfem_attachment_create(w, nullptr, &out), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_attachment_create(w, &d, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_attachment_create(nullptr, &d, &out), LFEM_INVALID_ARGUMENT);
    lfem_attachment_def bad = d;
    bad.internal_value = 0;
    refused(bad, LFEM_INVALID_ARGUMENT, "not from the default");
    bad = d, bad.body = lfem_body{bar.index, bar.generation + 100};
    refused(bad, LFEM_INVALID_HANDLE, "stale body");
    bad = d, bad.target = bar;
    refused(bad, LFEM_INVALID_ARGUMENT, "target is the body");
    bad = d, bad.target = soft;
    refused(bad, LFEM_INVALID_ARGUMENT, "deformable target");
    bad = d, bad.target = lfem_body{soft.index, soft.generation + 7};
    refused(bad, LFEM_INVALID_ARGUMENT, "stale target");
    bad = d, bad.node_count = 0;
    refused(bad, LFEM_INVALID_ARGUMENT, "no nodes");
    bad = d, bad.nodes = nullptr;
    refused(bad, LFEM_INVALID_ARGUMENT, "nodes NULL");
    const uint32_t twice[2] = {top[0], top[0]}, far[1] = {mesh.nodes()};
    bad = d, bad.nodes = twice, bad.node_count = 2;
    refused(bad, LFEM_INVALID_ARGUMENT, "a node twice");
    bad = d, bad.nodes = far, bad.node_count = 1;
    refused(bad, LFEM_INVALID_ARGUMENT, "node out of range");
    bad = d, bad.frame[0] = NAN;
    refused(bad, LFEM_INVALID_ARGUMENT, "NaN frame");
    bad = d, bad.frame[3] = 0.0;
    refused(bad, LFEM_INVALID_ARGUMENT, "zero quaternion");
    bad = d, bad.break_force = -1.0;
    refused(bad, LFEM_INVALID_ARGUMENT, "negative break force");
    const double nan_frame[7] = {0, 0, 0, NAN, 0, 0, 0};
    EXPECT_EQ(lfem_attachment_set_frame(w, good, nan_frame), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_attachment_set_frame(w, good, nullptr), LFEM_INVALID_ARGUMENT);
    const lfem_attachment stale{good.index, good.generation + 1};
    const double frame[7] = {0, 0, 0, 1, 0, 0, 0};
    EXPECT_EQ(lfem_attachment_set_frame(w, stale, frame), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_attachment_destroy(w, stale), LFEM_INVALID_HANDLE);
    double f[3];
    EXPECT_EQ(lfem_attachment_get_force(w, good, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_attachment_get_force(w, stale, f), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_attachment_is_valid(w, stale), 0);
    EXPECT_EQ(lfem_attachment_is_valid(nullptr, good), 0);
    EXPECT_EQ(fingerprint(w, {bar, soft}), before);
    // Destroying the body takes its attachment with it.
    ASSERT_EQ(lfem_body_destroy(w, bar), LFEM_OK);
    EXPECT_EQ(lfem_attachment_is_valid(w, good), 0);
}

// Attachments are part of the state: a run continued from a checkpoint, and a run on 2
// threads, give bitwise the same as one that never stopped, on 1 thread.
TEST(Attachments, CheckpointsAndThreadsKeepEveryBit) {
    auto run = [](uint32_t threads, bool through_checkpoint) {
        lfem_world_def wd = lfem_world_def_default();
        wd.thread_count = threads;
        World w(wd);
        Mesh rope_mesh, weight_mesh;
        const lfem_body rope = hanging_bar(w, rope_mesh, 1.0);
        make_box_mesh(weight_mesh, 0.06, 0.06, 0.06, 1, 1, 1, -0.03, -0.03, -0.36);
        lfem_body_def rd = lfem_body_def_default();
        rd.type = LFEM_BODY_RIGID;
        const lfem_body weight = add_body(w, rd, weight_mesh);
        attach(w, rope, nodes_near_z(w, rope, -0.3), weight);
        attach(w, rope, nodes_near_z(w, rope, 0.0), lfem_body{});
        for (int i = 0; i < 10; ++i) EXPECT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        lfem_world* from = w;
        lfem_world* loaded = nullptr;
        const std::string path = ::testing::TempDir() + "lfem_attachments.ckpt";
        if (through_checkpoint) {
            const lfem_status saved = lfem_world_save(w, path.c_str());
            if (saved == LFEM_UNSUPPORTED) return std::vector<unsigned char>();  // built without files
            EXPECT_EQ(saved, LFEM_OK) << lfem_last_error();
            EXPECT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
            from = loaded;
        }
        for (int i = 0; i < 10; ++i) EXPECT_EQ(lfem_world_step(from, 1.0 / 60), LFEM_OK);
        std::vector<unsigned char> out = fingerprint(from, {rope, weight});
        lfem_world_destroy(loaded);
        std::remove(path.c_str());
        return out;
    };
    const std::vector<unsigned char> reference = run(1, false);
    EXPECT_EQ(run(2, false), reference);
    const std::vector<unsigned char> restored = run(1, true);
    if (!restored.empty()) {
        EXPECT_EQ(restored, reference);
    }
}
