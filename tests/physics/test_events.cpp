// Contact events (issue 17): begin and end per pair of bodies, fetched after a step, with the
// pair's normal impulse and largest force. The impulse is checked against the cube's change of
// momentum (Newton's second law over the calls of the contact).
#include <cmath>
#include <cstdio>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

double momentum_z(lfem_world* w, lfem_body b) {
    double P[3];
    EXPECT_EQ(lfem_body_get_momentum(w, b, P, nullptr), LFEM_OK);
    return P[2];
}

// A 10 cm soft cube (the default material; the damping given, or the default one for 0)
// 0.5 mm above a static 40 x 40 x 5 cm block; returns the cube.
lfem_body cube_above_block(World& w, Mesh& floor, Mesh& cube, double damping) {
    make_box_mesh(floor, 0.4, 0.4, 0.05, 2, 2, 1, -0.2, -0.2, -0.05);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    add_body(w, fd, floor);
    make_box_mesh(cube, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0005);
    lfem_body_def d = lfem_body_def_default();
    if (damping > 0) d.damping = damping;
    return add_body(w, d, cube);
}

}  // namespace

// A stiff cube (E = 1e7 Pa, 2 cm) dropped at 1 m/s on a static block bounces: one begin, one
// end (and nothing in between). Over the calls from the one before the touch to the one that
// ends it, the floor's impulse on the cube is its change of momentum plus what gravity took:
// impulse = dP_z + m g t. The events carry the impulse of the calls they happen in; when the
// touch lasts several calls the calls in between carry none, so the test covers the touch
// with calls short enough to begin and end it in one call or two adjacent ones.
TEST(Events, ABouncingCubeBeginsAndEndsOneContactWithTheImpulseItsMomentumShows) {
    World w;
    Mesh floor, cube;
    make_box_mesh(floor, 0.2, 0.2, 0.05, 2, 2, 1, -0.1, -0.1, -0.05);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    fd.friction = 0;
    const lfem_body f = add_body(w, fd, floor);
    make_box_mesh(cube, 0.02, 0.02, 0.02, 2, 2, 2, -0.01, -0.01, 0.001);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e7;
    d.friction = 0;
    d.linear_velocity[2] = -1.0;
    const lfem_body c = add_body(w, d, cube);
    double mass = 0;
    lfem_body_get_mass(w, c, &mass);
    const double dt = 1e-3;
    int begins = 0, ends = 0, begin_call = -1, end_call = -1;
    double impulse = 0, largest = 0, P_before = 0, P_after = 0, t_begin = 0, t_end = 0;
    for (int call = 0; call < 40 && ends == 0; ++call) {
        const double P = momentum_z(w, c), t = stats(w).time;
        ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
        for (const lfem_event& e : events_of(w)) {
            ASSERT_TRUE(e.type == LFEM_EVENT_CONTACT_BEGIN || e.type == LFEM_EVENT_CONTACT_END) << e.type;
            // The pair, the lower slot first.
            EXPECT_EQ(e.body_a.index, std::min(f.index, c.index));
            EXPECT_EQ(e.body_b.index, std::max(f.index, c.index));
            if (e.type == LFEM_EVENT_CONTACT_BEGIN) {
                ++begins, begin_call = call, P_before = P, t_begin = t;
                impulse += e.normal_impulse;
            } else {
                ++ends, end_call = call, t_end = stats(w).time;
                if (end_call != begin_call) impulse += e.normal_impulse;  // the same call's once
            }
            largest = std::max(largest, e.max_force);
        }
        P_after = momentum_z(w, c);
    }
    ASSERT_EQ(begins, 1);
    ASSERT_EQ(ends, 1);
    ASSERT_LE(end_call - begin_call, 1) << "the touch outlasted two calls: shorten dt";
    const double expected = (P_after - P_before) + mass * 9.81 * (t_end - t_begin);
    std::printf("bounce: begin in call %d, end in call %d, impulse %.6g N s against dP + m g t = %.6g N s "
                "(m v = %.6g), largest force %.4g N\n",
                begin_call, end_call, impulse, expected, mass * 1.0, largest);
    // The impulse is what the solve applied; the momentum is read from the synchronized
    // velocities, whose difference over the same calls is exactly that impulse plus gravity's
    // up to round-off of the velocity sums (1e-12 of m v).
    EXPECT_NEAR(impulse, expected, 1e-9 * mass);
    EXPECT_GT(impulse, 1.0 * mass);   // at least the momentum it came with
    EXPECT_LT(impulse, 2.01 * mass);  // at most a perfect bounce (plus gravity's share)
    EXPECT_GE(largest * dt * 2, impulse);  // the peak is at least the mean over the calls
}

// The same balance right after the caller resets a body's velocities: the cube, touching the
// floor at rest (no gravity, no friction), is given 1 m/s into the floor by
// lfem_body_set_velocities and bounces within the call. A reset starts the body's central
// differences anew (its first interval is half a sub-step: velocity Verlet), so the first
// sub-step's force, the largest of the impact (it stops the face at once), changes the
// velocities over half a sub-step only. With gravity off and the internal forces summing to
// zero, the floor's impulse is exactly the change of the cube's momentum.
TEST(Events, AnImpactRightAfterSetVelocitiesReportsTheImpulseItsMomentumShows) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh floor, cube;
    make_box_mesh(floor, 0.2, 0.2, 0.05, 2, 2, 1, -0.1, -0.1, -0.05);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    fd.friction = 0;
    add_body(w, fd, floor);
    make_box_mesh(cube, 0.02, 0.02, 0.02, 2, 2, 2, -0.01, -0.01, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e7;
    d.friction = 0;
    const lfem_body c = add_body(w, d, cube);
    double mass = 0;
    lfem_body_get_mass(w, c, &mass);
    // A call at rest first, so that the world has stepped (and the cube has not moved).
    ASSERT_EQ(lfem_world_step(w, 1e-3), LFEM_OK) << lfem_last_error();
    std::vector<double> v(3 * cube.nodes(), 0.0);
    for (uint32_t i = 0; i < cube.nodes(); ++i) v[3 * i + 2] = -1.0;
    ASSERT_EQ(lfem_body_set_velocities(w, c, v.data(), cube.nodes()), LFEM_OK);
    const double P_before = momentum_z(w, c);
    ASSERT_EQ(lfem_world_step(w, 2e-3), LFEM_OK) << lfem_last_error();
    double impulse = 0;
    int begins = 0, ends = 0;
    for (const lfem_event& e : events_of(w)) {
        begins += e.type == LFEM_EVENT_CONTACT_BEGIN;
        ends += e.type == LFEM_EVENT_CONTACT_END;
        if (e.type == LFEM_EVENT_CONTACT_BEGIN) impulse = e.normal_impulse;
    }
    ASSERT_EQ(begins, 1);
    ASSERT_EQ(ends, 1) << "the bounce outlasted the call";
    const double expected = momentum_z(w, c) - P_before;
    std::printf("impact after a reset: impulse %.9g N s against dP %.9g N s (m v = %.6g)\n", impulse, expected,
                mass * 1.0);
    // Round-off of the velocity sums only (1e-12 of m v); a first sub-step counted over a whole
    // interval would add that sub-step's force times half a sub-step.
    EXPECT_NEAR(impulse, expected, 1e-9 * mass);
}

// A cube resting on the floor: one begin, then no events while it rests, and an end when it is
// lifted away (destroying a body ends its pairs silently).
TEST(Events, ARestingContactBeginsOnceAndEndsWhenTheCubeLeaves) {
    World w;
    Mesh floor, cube;
    const lfem_body c = cube_above_block(w, floor, cube, 20);
    int begins = 0, ends = 0;
    for (int call = 0; call < 60; ++call) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        for (const lfem_event& e : events_of(w)) begins += e.type == LFEM_EVENT_CONTACT_BEGIN, ends += e.type == LFEM_EVENT_CONTACT_END;
    }
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 0);
    // Thrown up at 2 m/s: it leaves the floor within the call.
    std::vector<double> v(3 * cube.nodes(), 0.0);
    for (uint32_t i = 0; i < cube.nodes(); ++i) v[3 * i + 2] = 2.0;
    ASSERT_EQ(lfem_body_set_velocities(w, c, v.data(), cube.nodes()), LFEM_OK);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<lfem_event> last = events_of(w);
    ASSERT_EQ(last.size(), 1u);
    EXPECT_EQ(last[0].type, LFEM_EVENT_CONTACT_END);
}

// Destroying a body ends its pairs: an engine that tracks touching pairs from the events would
// otherwise keep them for ever. A cube resting on a second one on the floor, the lower cube
// destroyed: the next call reports exactly the ends of the two pairs the lower cube was in
// (with the floor, with the upper cube), naming it by its stale handle, and nothing else ends;
// the upper cube then falls. With sleeping on, the upper cube
// asleep on the lower one wakes and falls instead of hanging in the air.
TEST(Events, DestroyingABodyEndsItsPairsAndWakesWhatItHeld) {
    for (int sleeping = 0; sleeping < 2; ++sleeping) {
        lfem_world_def wd = lfem_world_def_default();
        wd.enable_sleep = uint8_t(sleeping);
        World w(wd);
        Mesh floor, lower, upper;
        const lfem_body low = cube_above_block(w, floor, lower, 20);
        make_box_mesh(upper, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.1015);
        lfem_body_def d = lfem_body_def_default();
        d.damping = 20;
        const lfem_body up = add_body(w, d, upper);
        for (int call = 0; call < 150 && (!sleeping || lfem_body_is_awake(w, up)); ++call)
            ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        if (sleeping) {
            ASSERT_EQ(lfem_body_is_awake(w, up), 0);
        }
        ASSERT_EQ(lfem_body_destroy(w, low), LFEM_OK);
        EXPECT_EQ(lfem_body_is_awake(w, up), 1);  // held up by nothing now
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        int ends_with_low = 0, other_ends = 0;
        for (const lfem_event& e : events_of(w)) {
            if (e.type != LFEM_EVENT_CONTACT_END) continue;
            const bool with_low = (e.body_a.index == low.index && e.body_a.generation == low.generation) ||
                                  (e.body_b.index == low.index && e.body_b.generation == low.generation);
            ends_with_low += with_low;
            other_ends += !with_low;
        }
        EXPECT_EQ(ends_with_low, 2) << (sleeping ? "asleep" : "awake");
        EXPECT_EQ(other_ends, 0);
        // The upper cube falls (g t^2 / 2 = 5 cm in 0.1 s) and lands on the floor.
        const std::vector<double> before = positions(w, up);
        for (int call = 0; call < 6; ++call) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
        const std::vector<double> after = positions(w, up);
        EXPECT_LT(after[2] - before[2], -0.03) << (sleeping ? "asleep" : "awake");
    }
}

// An impact's BEGIN event says how fast the bodies met, where, and along what normal, so that an
// engine can size a sound by it even when the impact's impulse spans two calls (issue 36: a
// rigid-only world takes one sub-step per 1/60 s call, and a box landing on a plane reported
// 0.91 of m v in the call it began and the rest in the next, with no event). A box dropped from
// H above a plane lands at sqrt(2 g H). Central differences under constant gravity are exact at
// the steps: the impact's sub-step [t_n, t_n + h] holds the landing time T, and the predicted
// mid-step velocity g (t_n + h_mid) is within g h/2 of g T (h_mid = h/2 on the first step,
// then h). Rigid alone (h = 1/60 s, one sub-step a call) and soft (its stable sub-step, a
// dozen a call; the cube falls undeformed, so its bottom nodes meet the plane as the rigid
// box's do). The point is a bottom node, on the plane; the normal points from the plane
// (body_a, the lower slot) toward the box (body_b): +z.
TEST(Events, AnImpactBeginsWithItsApproachSpeedPointAndNormal) {
    const double g = 9.81, H = 0.2, v_impact = std::sqrt(2 * g * H);
    for (int soft = 0; soft < 2; ++soft) {
        World w;
        const lfem_body plane = add_plane_floor(w);
        Mesh m;
        make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, H);
        lfem_body_def d = lfem_body_def_default();
        d.type = soft ? LFEM_BODY_DEFORMABLE : LFEM_BODY_RIGID;
        const lfem_body box = add_body(w, d, m);
        bool begun = false;
        for (int call = 0; call < 30 && !begun; ++call) {
            ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
            for (const lfem_event& e : events_of(w)) {
                if (e.type != LFEM_EVENT_CONTACT_BEGIN) continue;
                begun = true;
                const double h = stats(w).step_size;
                std::printf("%s box: approach %.6g m/s (sqrt(2 g H) = %.6g, g h / 2 = %.3g), point (%.3g, %.3g, %.3g), "
                            "normal (%.3g, %.3g, %.3g)\n",
                            soft ? "soft" : "rigid", e.approach_speed, v_impact, g * h / 2, e.point[0], e.point[1],
                            e.point[2], e.normal[0], e.normal[1], e.normal[2]);
                EXPECT_EQ(e.body_a.index, plane.index);
                EXPECT_EQ(e.body_b.index, box.index);
                EXPECT_NEAR(e.approach_speed, v_impact, g * h / 2 * (1 + 1e-9));
                EXPECT_NEAR(e.normal[2], 1.0, 1e-12);
                EXPECT_NEAR(e.normal[0], 0.0, 1e-12);
                EXPECT_NEAR(e.normal[1], 0.0, 1e-12);
                // On the plane, under the box, to the solve's tolerance (1e-3 of the step's
                // motion, v h; the rigid box's correction turns it by as much).
                const double tolerance = 1e-3 * v_impact * h;
                EXPECT_NEAR(e.point[2], 0.0, tolerance);
                EXPECT_LE(std::fabs(e.point[0]), 0.05 + tolerance);
                EXPECT_LE(std::fabs(e.point[1]), 0.05 + tolerance);
            }
        }
        EXPECT_TRUE(begun) << (soft ? "soft" : "rigid");
    }
}

// A body that reports its contacts (lfem_body_def.report_contacts) gets, every call, an event
// for each pair that stays in touch, with the pair's impulse over the call, its peak force and
// its active contacts. Two undamped cubes resting on a static block, one reporting: one PERSIST
// event a call, for its pair alone. Newton over the call: the floor's impulse on the cube is its
// change of momentum plus what gravity took, m g dt (no damping impulse; to round-off of the
// velocity sums, 1e-9 of m g dt); the count is that of the pair's contacts the contact query
// lists.
TEST(Events, AReportingBodyHearsOfEachPairThatStaysInTouch) {
    World w;
    Mesh floor, a_mesh, b_mesh;
    make_box_mesh(floor, 0.6, 0.4, 0.05, 2, 2, 1, -0.3, -0.2, -0.05);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    const lfem_body f = add_body(w, fd, floor);
    make_box_mesh(a_mesh, 0.1, 0.1, 0.1, 2, 2, 2, -0.2, -0.05, 0.0005);
    make_box_mesh(b_mesh, 0.1, 0.1, 0.1, 2, 2, 2, 0.1, -0.05, 0.0005);
    lfem_body_def d = lfem_body_def_default();
    d.damping = 0;  // Newton's balance below holds no damping impulse
    d.report_contacts = 1;
    const lfem_body a = add_body(w, d, a_mesh);
    d.report_contacts = 0;
    add_body(w, d, b_mesh);
    for (int call = 0; call < 60; ++call) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    double mass = 0;
    lfem_body_get_mass(w, a, &mass);
    const double dt = 1.0 / 60, P0 = momentum_z(w, a);
    ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK);
    const double P1 = momentum_z(w, a);
    const std::vector<lfem_event> events = events_of(w);
    ASSERT_EQ(events.size(), 1u);
    const lfem_event& e = events[0];
    EXPECT_EQ(e.type, LFEM_EVENT_CONTACT_PERSIST);
    EXPECT_EQ(e.body_a.index, f.index);
    EXPECT_EQ(e.body_b.index, a.index);
    const double expected = (P1 - P0) + mass * 9.81 * dt;
    std::printf("persisting pair: impulse %.9g N s against dP + m g dt = %.9g N s, %u contacts\n", e.normal_impulse,
                expected, e.contact_count);
    EXPECT_NEAR(e.normal_impulse, expected, 1e-9 * mass * 9.81 * dt);
    uint32_t n = 0;
    lfem_world_query_contacts(w, nullptr, 0, &n);
    std::vector<lfem_contact> contacts(n);
    ASSERT_EQ(lfem_world_query_contacts(w, contacts.data(), n, &n), LFEM_OK);
    uint32_t of_pair = 0;
    for (const lfem_contact& c : contacts)
        of_pair += (c.body_a.index == a.index && c.body_b.index == f.index) || (c.body_a.index == f.index && c.body_b.index == a.index);
    EXPECT_EQ(e.contact_count, of_pair);
    EXPECT_GT(of_pair, 0u);
    // A definition with report_contacts neither 0 nor 1 is refused.
    lfem_body_def bad = lfem_body_def_default();
    bad.report_contacts = 2;
    lfem_body out{};
    EXPECT_EQ(lfem_body_create(w, &bad, &out), LFEM_INVALID_ARGUMENT);
}

TEST(Events, TooSmallBuffersAndNullsAreRefused) {
    World w;
    Mesh floor, cube;
    cube_above_block(w, floor, cube, 0);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    uint32_t count = 99;
    lfem_event one{};
    EXPECT_EQ(lfem_world_get_events(w, nullptr, 0, &count), LFEM_BUFFER_TOO_SMALL);
    EXPECT_EQ(count, 1u);
    EXPECT_EQ(lfem_world_get_events(w, &one, 1, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_get_events(w, nullptr, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_get_events(nullptr, &one, 1, &count), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_get_events(w, &one, 1, &count), LFEM_OK);
    EXPECT_EQ(one.type, LFEM_EVENT_CONTACT_BEGIN);
}
