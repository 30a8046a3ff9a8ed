// lfem_body_clear_node_forces: "Remove every external node force of the body." A free body
// under node forces proportional to its lumped masses accelerates rigidly at a = F/m + g; once
// they are cleared it falls freely at g, and another body's forces act on. Bad input is refused
// with the documented status and changes nothing, not even the forces.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// Node forces m_a a1 on every node of a box of 4-node tets (m_a = rho V / 4 from each of its
// tets, src/DESIGN.md), so that every node accelerates alike and nothing deforms: the central
// difference scheme then integrates the constant acceleration exactly (as in free fall).
struct Pushed {
    Mesh mesh;
    lfem_body body{};
};

void push(lfem_world* w, Pushed& p, double x0, const double a1[3]) {
    make_box_mesh(p.mesh, 0.1, 0.1, 0.1, 2, 2, 2, x0, 0.0, 0.0);
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    p.body = add_body(w, def, p.mesh);
    const double* X = lfem_mesh_get_positions(p.mesh.m);
    const std::vector<double> X0(X, X + 3 * std::size_t(p.mesh.nodes()));
    std::vector<double> forces(3 * std::size_t(p.mesh.nodes()), 0.0);
    for (uint32_t e = 0; e < p.mesh.tets(); ++e) {
        const uint32_t* t = lfem_mesh_get_tets(p.mesh.m) + 4 * e;
        const double m = def.density * volume(X0, t, 1) / 4;
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 3; ++k) forces[3 * t[j] + k] += m * a1[k];
    }
    std::vector<uint32_t> nodes(p.mesh.nodes());
    for (uint32_t i = 0; i < p.mesh.nodes(); ++i) nodes[i] = i;
    ASSERT_EQ(lfem_body_set_node_forces(w, p.body, nodes.data(), p.mesh.nodes(), forces.data()), LFEM_OK)
        << lfem_last_error();
}

// The largest difference (m/s) between any node's velocity and v.
double off_velocity(lfem_world* w, lfem_body b, const double v[3]) {
    const std::vector<double> u = velocities(w, b);
    double worst = 0;
    for (std::size_t i = 0; i < u.size(); ++i) worst = std::fmax(worst, std::fabs(u[i] - v[i % 3]));
    return worst;
}

const double kGravity[3] = {0.0, 0.0, -9.81};  // the default world's

}  // namespace

TEST(NodeForces, ClearedForcesStopActingAndTheBodyFallsFreely) {
    World w;
    const double a1[3] = {2.0, -1.0, 15.0};  // m/s^2, from the node forces alone
    Pushed cleared, kept;
    push(w, cleared, 0.0, a1);
    push(w, kept, 1.0, a1);  // a metre away: no contact

    // Under the forces: every node's velocity gains (a1 + g) T over a call, exactly but for
    // round-off: velocities are position differences over a sub-step, (x' - x) / h, each off by
    // ~1e-16 m / 1e-3 s = 1e-13 m/s at these 1 m coordinates; 1e-10 m/s bounds a few hundred.
    const double T = 0.02;
    double v[3] = {0, 0, 0};
    for (int call = 0; call < 5; ++call) {
        ASSERT_EQ(lfem_world_step(w, T), LFEM_OK) << lfem_last_error();
        for (int k = 0; k < 3; ++k) v[k] += (a1[k] + kGravity[k]) * T;
        EXPECT_LT(off_velocity(w, cleared.body, v), 1e-10);
        EXPECT_LT(off_velocity(w, kept.body, v), 1e-10);
    }
    const double h = stats(w).step_size;

    ASSERT_EQ(lfem_body_clear_node_forces(w, cleared.body), LFEM_OK) << lfem_last_error();
    // The first call after: the closed form is v + g T, but central differences with mid-step
    // velocities take a load change at a call boundary as if it came half a sub-step earlier
    // (the mid-step velocity v(t - h/2) carries no record of a1 over the last half step), so the
    // velocity falls short by a1 h / 2. The bound is a whole sub-step's worth, a1 h, 20 times
    // below the a1 T = 0.3 m/s of forces still acting.
    double falls[3], pushed[3];
    for (int k = 0; k < 3; ++k) falls[k] = v[k] + kGravity[k] * T, pushed[k] = v[k] + (a1[k] + kGravity[k]) * T;
    ASSERT_EQ(lfem_world_step(w, T), LFEM_OK) << lfem_last_error();
    const double a1_max = std::fmax(std::fabs(a1[0]), std::fmax(std::fabs(a1[1]), std::fabs(a1[2])));
    std::printf("after the clear: off the free fall's velocity by %.3e m/s (largest a1 h/2 = %.3e m/s, h = %.3g s)\n",
                off_velocity(w, cleared.body, falls), a1_max * h / 2, h);
    EXPECT_LT(off_velocity(w, cleared.body, falls), a1_max * h);
    EXPECT_LT(off_velocity(w, kept.body, pushed), 1e-10);  // the other body's forces still act
    // From then on: free fall, exactly g per unit time (the velocity gains g T a call), and the
    // other body keeps accelerating at a1 + g.
    for (int call = 0; call < 5; ++call) {
        const std::vector<double> before = velocities(w, cleared.body), before_kept = velocities(w, kept.body);
        ASSERT_EQ(lfem_world_step(w, T), LFEM_OK) << lfem_last_error();
        const std::vector<double> after = velocities(w, cleared.body), after_kept = velocities(w, kept.body);
        double worst = 0, worst_kept = 0;
        for (std::size_t i = 0; i < after.size(); ++i) {
            worst = std::fmax(worst, std::fabs((after[i] - before[i]) / T - kGravity[i % 3]));
            worst_kept = std::fmax(worst_kept, std::fabs((after_kept[i] - before_kept[i]) / T - a1[i % 3] - kGravity[i % 3]));
        }
        EXPECT_LT(worst, 1e-8) << "m/s^2 off g, call " << call;  // round-off: 1e-10 m/s over T
        EXPECT_LT(worst_kept, 1e-8) << "m/s^2 off a1 + g, call " << call;
    }
    // Clearing a body without node forces is no error and changes nothing.
    const std::vector<unsigned char> before = fingerprint(w, {cleared.body, kept.body});
    EXPECT_EQ(lfem_body_clear_node_forces(w, cleared.body), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(before, fingerprint(w, {cleared.body, kept.body}));
}

// lfem.h: "A null pointer where one is required is answered with LFEM_INVALID_ARGUMENT", "a
// handle of a destroyed body (stale) or of another world (foreign) is answered with
// LFEM_INVALID_HANDLE", and "on failure nothing changes". The world's fingerprint (all a user
// can read) stays bitwise the same, and the forces still act: the body keeps accelerating at
// a1 + g after each refused call.
TEST(NodeForces, ClearRefusesBadInputAndClearsNothing) {
    World w, other;
    const double a1[3] = {0.0, 0.0, 12.0};
    Pushed p;
    push(w, p, 0.0, a1);
    lfem_body doomed{};
    {
        Mesh m;
        make_box_mesh(m, 0.1, 0.1, 0.1, 1, 1, 1, 2.0, 0.0, 0.0);
        doomed = add_body(w, lfem_body_def_default(), m);
        Mesh m2;
        make_box_mesh(m2, 0.1, 0.1, 0.1, 1, 1, 1);
        add_body(other, lfem_body_def_default(), m2);
    }
    ASSERT_EQ(lfem_body_destroy(w, doomed), LFEM_OK) << lfem_last_error();
    lfem_body alien{};  // a live body of the other world, not of this one
    {
        Mesh m3;
        make_box_mesh(m3, 0.1, 0.1, 0.1, 1, 1, 1);
        alien = add_body(other, lfem_body_def_default(), m3);
    }
    ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();

    const struct {
        lfem_world* world;
        lfem_body body;
        lfem_status expected;
        const char* what;
    } cases[] = {{nullptr, p.body, LFEM_INVALID_ARGUMENT, "null world"},
                 {w, doomed, LFEM_INVALID_HANDLE, "stale handle"},
                 {w, lfem_body{0, 0}, LFEM_INVALID_HANDLE, "null handle"},
                 {w, alien, LFEM_INVALID_HANDLE, "foreign handle"}};
    for (const auto& c : cases) {
        const std::vector<unsigned char> before = fingerprint(w, {p.body, doomed});
        const std::vector<double> v0 = velocities(w, p.body);
        EXPECT_EQ(lfem_body_clear_node_forces(c.world, c.body), c.expected) << c.what;
        EXPECT_STRNE(lfem_last_error(), "") << c.what;
        EXPECT_EQ(before, fingerprint(w, {p.body, doomed})) << c.what << " changed the world";
        const double T = 0.01;
        ASSERT_EQ(lfem_world_step(w, T), LFEM_OK) << lfem_last_error();
        const std::vector<double> v1 = velocities(w, p.body);
        double worst = 0;
        for (std::size_t i = 0; i < v1.size(); ++i)
            worst = std::fmax(worst, std::fabs((v1[i] - v0[i]) / T - a1[i % 3] - kGravity[i % 3]));
        EXPECT_LT(worst, 1e-8) << c.what << ": the forces no longer act (m/s^2 off a1 + g)";
    }
}
