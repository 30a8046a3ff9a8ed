// Known issues (README, "Known issues") as tests of the correct physics, which fail today. They
// are their own program, registered in ctest with WILL_FAIL (tests/CMakeLists.txt): ctest
// passes them while their assertion fails, and fails them once the issue is fixed, the sign to
// drop WILL_FAIL. An expected failure must fail for the reason it names and no other, so
// everything the scene needs to be what it claims (the calls succeed, the stack stands, the
// sub-step really halved) is checked with require(), which aborts the program, and a crash
// fails in ctest whatever WILL_FAIL says; only the issue's own assertion is a test failure. Each
// has a control, a scene as near as can be without the cause, registered as an ordinary test:
// it passes the same bounds, so they are fair.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "physics/lfem_test_util.h"
#include "physics/thin_plates.h"

using namespace lfem_test;

namespace {

void require(bool ok, const char* what) {
    if (ok) return;
    std::fflush(stdout);
    std::fprintf(stderr, "precondition failed, the scene is not what the test claims: %s (%s)\n", what,
                 lfem_last_error());
    std::abort();
}

struct StackMotion {
    double rms[3] = {0, 0, 0};       // m/s, each cube's largest RMS node speed over the window
    double yaw_rate[3] = {0, 0, 0};  // rad/s, each cube's largest |yaw rate| over the window
};

// The yaw rate (rad/s) of a body's nodes about the vertical line through their mean: the
// least-squares rigid rotation about z of their velocities relative to the mean velocity.
double yaw_rate(const std::vector<double>& x, const std::vector<double>& v) {
    const std::size_t n = x.size() / 3;
    double cx = 0, cy = 0, vx = 0, vy = 0;
    for (std::size_t i = 0; i < n; ++i) cx += x[3 * i] / n, cy += x[3 * i + 1] / n, vx += v[3 * i] / n, vy += v[3 * i + 1] / n;
    double moment = 0, inertia = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double rx = x[3 * i] - cx, ry = x[3 * i + 1] - cy;
        moment += rx * (v[3 * i + 1] - vy) - ry * (v[3 * i] - vx);
        inertia += rx * rx + ry * ry;
    }
    return moment / inertia;
}

// The stack of three of tests/physics/test_resting_contact.cpp (soft corotational cubes of 3^3
// cells, E 2e5, damping 15 /s, friction 0.5, each 1 cm sideways of the one below, dropped 1 mm
// onto a static floor), or its lower `cubes` cubes. Settled for 2 s in calls of 0.25 s (the
// automatic sub-step h), then stepped in calls of h / 2, one sub-step each: the sub-step halves.
// The motion of the cubes is watched from 1.5 s to 1.75 s after the switch.
StackMotion stack_after_the_substep_halves(int cubes) {
    const double friction = 0.5;
    World w;
    Mesh floor_mesh, cube[3];
    make_box_mesh(floor_mesh, 1.0, 1.0, 0.1, 4, 4, 1, -0.5, -0.5, -0.1);
    lfem_body_def floor_def = lfem_body_def_default();
    floor_def.type = LFEM_BODY_STATIC;
    floor_def.friction = friction;
    add_body(w, floor_def, floor_mesh);
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    def.young_modulus = 2e5;
    def.damping = 15.0;
    def.friction = friction;
    lfem_body bodies[3];
    for (int i = 0; i < cubes; ++i) {
        make_box_mesh(cube[i], 0.1, 0.1, 0.1, 3, 3, 3, -0.05 + 0.01 * i, -0.05, 0.101 * i + 0.001);
        bodies[i] = add_body(w, def, cube[i]);
        require(node_count(w, bodies[i]) == 64, "a cube of 3^3 cells");
    }
    for (int call = 0; call < 8; ++call) require(lfem_world_step(w, 0.25) == LFEM_OK, "settling step");
    const double h = stats(w).step_size;
    auto stack_stands = [&] {  // each cube's centre a squashed cube height above the one below
        bool stands = true;
        double below = -0.05;  // the floor's "centre" for the bottom cube's 3 cm
        for (int i = 0; i < cubes; ++i) {
            const std::vector<double> x = positions(w, bodies[i]);
            double z = 0;
            for (std::size_t k = 2; k < x.size(); k += 3) z += x[k] / (x.size() / 3);
            stands = stands && z - below > (i == 0 ? 0.08 : 0.07);
            below = z;
        }
        return stands;
    };
    require(stack_stands(), "the stack stands after settling");

    StackMotion motion;
    const int calls = int(std::lround(1.75 / (h / 2))), watched = int(std::lround(0.25 / (h / 2)));
    for (int call = 0; call < calls; ++call) {
        require(lfem_world_step(w, h / 2) == LFEM_OK, "step after the switch");
        require(stats(w).substeps_last_call == 1 && std::fabs(stats(w).step_size / h - 0.5) < 1e-12,
                "one sub-step of h / 2 per call");
        if (call < calls - watched) continue;
        for (int i = 0; i < cubes; ++i) {
            motion.rms[i] = std::fmax(motion.rms[i], rms_velocity(w, bodies[i]));
            motion.yaw_rate[i] = std::fmax(motion.yaw_rate[i], std::fabs(yaw_rate(positions(w, bodies[i]), velocities(w, bodies[i]))));
        }
    }
    require(stack_stands(), "the stack stands at the end");
    std::printf("stack of %d, friction %.1f, 1.5 to 1.75 s after the sub-step halved (%.3g s -> %.3g s): RMS node speed "
                "%.1e, %.1e, %.1e m/s; |yaw rate| %.1e, %.1e, %.1e rad/s (bottom to top); penetration %.1e m\n",
                cubes, friction, h, h / 2, motion.rms[0], motion.rms[1], motion.rms[2], motion.yaw_rate[0], motion.yaw_rate[1],
                motion.yaw_rate[2], stats(w).max_penetration);
    return motion;
}

// A stack that stands still with damping alpha = 15 /s: whatever the switch of sub-step
// stirred decays at least as e^(-alpha t / 2), by 1.3e-5 over 1.5 s, and nothing drives it
// (static friction holds the level faces; gravity is balanced). 1e-4 m/s is ten times below
// the creep's ~1e-3 m/s (README), and forty times above what the control keeps; the
// yaw-rate bound, 1e-3 rad/s, is 5e-5 m/s at the cubes' corners.
void expect_at_rest(const StackMotion& m, int cubes) {
    for (int i = 0; i < cubes; ++i) {
        EXPECT_LT(m.rms[i], 1e-4) << "cube " << i << " still moves";
        EXPECT_LT(m.yaw_rate[i], 1e-3) << "cube " << i << " still turns";
    }
}

// The thin plates swung together at `speed`: no edge point deeper in the other than 1 % of an
// element at any call (the issue's target).
void expect_plates_held(double speed) {
    const ThinPlates p = thin_plates_crossed(speed, 1);
    require(p.calls_ok, "every call succeeds");
    std::printf("thin plates at %.0f m/s: deepest edge point %.3f mm (%.2f %% of an element)\n", speed, 1e3 * p.deepest,
                100 * p.deepest / p.element);
    EXPECT_LT(p.deepest, 0.01 * p.element);
}

}  // namespace

// README, Known issues: between two deformable bodies both passes (nodes of A on faces of B and
// the reverse) carry friction, and where they press the same spot the two sets of friction
// forces load each other in a closed loop: a stack of soft cubes stepped with a sub-step that
// suddenly halves starts a slow yaw creep (~1e-3 m/s). Expected to fail (WILL_FAIL) until the
// fix: today the cubes keep RMS node speeds of ~1e-3 m/s and yaw rates of a few 1e-3 rad/s of
// changing sign, while the positions barely move (the yaw angles wander by a few 1e-5 rad),
// and the contacts keep 1e-5 to 3e-5 m of penetration (printed, not asserted: the stack of two
// below keeps 6e-11 m). At the sub-step it settled with, the same stack keeps 2e-4 to 4e-4 m/s.
// (Friction 0.2, 1 and 2 creep alike, at 1e-3 to 2e-2 m/s.)
TEST(KnownIssue, FrictionalStackComesToRestAfterTheSubStepHalves) {
    expect_at_rest(stack_after_the_substep_halves(3), 3);
}

// The control. Friction cannot simply be switched off: without it the offset cubes slide off
// each other and the stack falls apart. So it keeps the friction and drops the top cube: the
// lower two, one frictional contact between deformable bodies, come to rest under the same
// bounds after the same switch (RMS node speeds ~1e-6 m/s).
TEST(KnownIssue, StackOfTwoComesToRestAfterTheSubStepHalves) {
    expect_at_rest(stack_after_the_substep_halves(2), 2);
}

// README, Known issues: two thin plates crossed edge on edge (tests/physics/thin_plates.h), the
// soft one (E 1e6, wave speed 32 m/s) swung down at 15 m/s, half its wave speed: the edges sink
// 1.4 mm (4.9 % of an element) into each other, where at 10 m/s they stay within 0.06 mm. The
// soft plate's edge is squeezed to 60 % of its length where it lands, and the crossing runs
// past its nodes onto the next edges, folds among them; a pair taking over from its neighbour
// (handed_over, detect_features.cpp) brought 5.0 mm down to 1.4, and pairs are still let go
// there. Expected to fail (WILL_FAIL); the target is 1 % of an element.
TEST(KnownIssue, ThinPlatesAt15MetresASecond) { expect_plates_held(15.0); }

// The control: the same plates at 10 m/s, under the same bound (0.061 mm, 0.22 % of an element).
TEST(KnownIssue, ThinPlatesAt10MetresASecond) { expect_plates_held(10.0); }
