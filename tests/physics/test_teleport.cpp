// Where a body is and teleports (issue 36): lfem_body_get_transform and _get_center_of_mass,
// lfem_body_set_transform and _set_positions. A teleport does no work, keeps the velocities,
// ends the body's pairs and keeps its handle and attachments. Bad input changes nothing.
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

std::vector<double> transform_of(lfem_world* w, lfem_body b) {
    std::vector<double> t(7);
    EXPECT_EQ(lfem_body_get_transform(w, b, t.data()), LFEM_OK) << lfem_last_error();
    return t;
}

// x = R X + t for a unit quaternion (w, x, y, z) and a translation.
std::array<double, 3> apply(const double* T, const double* X) {
    const double w = T[3], x = T[4], y = T[5], z = T[6];
    const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    std::array<double, 3> out{};
    for (int r = 0; r < 3; ++r) out[r] = R[3 * r] * X[0] + R[3 * r + 1] * X[1] + R[3 * r + 2] * X[2] + T[r];
    return out;
}

// The same rotation: q and -q are one.
double quaternion_gap(const double* a, const double* b) {
    double plus = 0, minus = 0;
    for (int k = 0; k < 4; ++k) plus += std::fabs(a[k] - b[k]), minus += std::fabs(a[k] + b[k]);
    return std::min(plus, minus);
}

int ends_with(lfem_world* w, lfem_body b) {
    int k = 0;
    for (const lfem_event& x : events_of(w))
        k += x.type == LFEM_EVENT_CONTACT_END && (x.body_a.index == b.index || x.body_b.index == b.index);
    return k;
}

}  // namespace

// A soft cube resting on a floor, teleported 1 m over and 0.5 m up, turned 90 degrees about z:
// its transform is then the one asked (round-off), its nodes are where that pose carries the
// rested shape, its velocities and strain energy are as before (a rigid move of an elastic body),
// the energy balance does not move, its pair with the floor ends, and it falls from there.
TEST(Teleport, ASoftCubeMovesToThePoseAskedKeepingItsShapeAndVelocities) {
    World w;
    Mesh floor, cube;
    make_box_mesh(floor, 2, 2, 0.1, 2, 2, 1, -1, -1, -0.1);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    add_body(w, fd, floor);
    make_box_mesh(cube, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0005);
    lfem_body_def d = lfem_body_def_default();
    d.damping = 20;
    const lfem_body b = add_body(w, d, cube);
    for (int i = 0; i < 30; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    // At rest on the floor: the fit is near the identity, the centre of mass at 5 cm.
    const std::vector<double> T0 = transform_of(w, b);
    double c[3];
    ASSERT_EQ(lfem_body_get_center_of_mass(w, b, c), LFEM_OK);
    EXPECT_NEAR(c[2], 0.05, 1e-3);
    EXPECT_LT(quaternion_gap(&T0[3], std::vector<double>{1, 0, 0, 0}.data()), 1e-6);
    const std::vector<double> x0 = positions(w, b), v0 = velocities(w, b);
    const lfem_world_stats s0 = stats(w);
    const double half = std::sqrt(0.5), T[7] = {1.0, 0.0, 0.5, half, 0, 0, half};
    ASSERT_EQ(lfem_body_set_transform(w, b, T), LFEM_OK) << lfem_last_error();
    const std::vector<double> T1 = transform_of(w, b);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(T1[k], T[k], 1e-14);
    EXPECT_LT(quaternion_gap(&T1[3], &T[3]), 1e-14);
    // Each node where the rigid move D = T T0^-1 takes it: D(x) = R R0^T (x - t0) + t.
    const std::vector<double> x1 = positions(w, b), v1 = velocities(w, b);
    const double inverse0[7] = {0, 0, 0, T0[3], -T0[4], -T0[5], -T0[6]};
    double worst = 0;
    for (size_t i = 0; i < x0.size(); i += 3) {
        const double rel[3] = {x0[i] - T0[0], x0[i + 1] - T0[1], x0[i + 2] - T0[2]};
        const std::array<double, 3> X = apply(inverse0, rel), expected = apply(T, X.data());
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(x1[i + k] - expected[k]));
    }
    EXPECT_LT(worst, 1e-14);
    for (size_t k = 0; k < v0.size(); ++k) EXPECT_EQ(v1[k], v0[k]);
    const lfem_world_stats s1 = stats(w);
    // A rigid move: the strain energy to round-off of the elastic forces (1e-12 of it), and the
    // balance (which books any change as the caller's work) to the same.
    EXPECT_NEAR(s1.strain_energy, s0.strain_energy, 1e-9 * s0.strain_energy + 1e-15);
    EXPECT_NEAR(s1.energy_error, s0.energy_error, 1e-9 * s0.strain_energy + 1e-15);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    EXPECT_EQ(ends_with(w, b), 1);  // its pair with the floor
    EXPECT_EQ(stats(w).contact_count, 0u);
    // It falls from there, from rest, as a damped body does: a = g - c v (damping c = 20/s on
    // every velocity), so its centre drops (g/c) (t - (1 - e^-ct)/c) in t = 16 calls; the
    // central differences' O(h) and the cube's ringing stay well inside 1 %.
    for (int i = 0; i < 15; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    double c2[3];
    ASSERT_EQ(lfem_body_get_center_of_mass(w, b, c2), LFEM_OK);
    const double t = 16.0 / 60, cd = 20.0, g = 9.81;
    const double drop = g / cd * (t - (1 - std::exp(-cd * t)) / cd);
    std::printf("teleported cube: dropped %.6g m in %.4g s (damped fall %.6g m)\n", 0.5 + c[2] - T0[2] - c2[2], t, drop);
    EXPECT_NEAR(0.5 + c[2] - T0[2] - c2[2], drop, 0.01 * drop);
    EXPECT_NEAR(c2[0], 1.0, 1e-6);
}

// A rigid box spinning in free flight, teleported: its transform is the one asked exactly, its
// centre's velocity and its spin (world frame) are kept, so every node moves as V + omega x r.
TEST(Teleport, ARigidBoxKeepsItsVelocityAndSpin) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    World w(wd);
    Mesh m;
    make_box_mesh(m, 0.2, 0.1, 0.05, 2, 2, 2, -0.1, -0.05, -0.025);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_RIGID;
    d.linear_velocity[0] = 1.0;
    d.angular_velocity[0] = 0.5, d.angular_velocity[2] = 2.0;
    const lfem_body b = add_body(w, d, m);
    ASSERT_EQ(lfem_world_step(w, 0.1), LFEM_OK);
    const std::vector<double> xa = positions(w, b), va = velocities(w, b);
    // Spin and centre velocity from two nodes' velocities: omega x (x1 - x0) = v1 - v0 for any
    // pair; recovered below by comparing with the prediction instead.
    double ca[3];
    ASSERT_EQ(lfem_body_get_center_of_mass(w, b, ca), LFEM_OK);
    const double q[7] = {3, -2, 1, 0.5, 0.5, 0.5, 0.5};  // 120 degrees about (1,1,1)
    ASSERT_EQ(lfem_body_set_transform(w, b, q), LFEM_OK) << lfem_last_error();
    const std::vector<double> T = transform_of(w, b);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(T[k], q[k], 1e-15 * 4);
    EXPECT_LT(quaternion_gap(&T[3], &q[3]), 1e-15 * 4);
    const std::vector<double> xb = positions(w, b), vb = velocities(w, b);
    const double* X = lfem_mesh_get_positions(m.m);
    double cb[3];
    ASSERT_EQ(lfem_body_get_center_of_mass(w, b, cb), LFEM_OK);
    // Nodes at R X + t (the mesh as added is the reference).
    double worst_x = 0;
    for (size_t i = 0; i < xb.size(); i += 3) {
        const std::array<double, 3> e = apply(q, &X[i]);
        for (int k = 0; k < 3; ++k) worst_x = std::max(worst_x, std::fabs(xb[i + k] - e[k]));
    }
    EXPECT_LT(worst_x, 1e-14);
    // v = V + omega x r before and after, with the same V and omega: fit omega from before
    // (two nodes off the centre along different axes give it), predict after.
    // Before: V = the mean velocity (the nodes' masses are symmetric about the centre).
    const size_t n = xa.size() / 3;
    double V[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) V[k] += va[3 * i + k] / double(n);
    double Vb[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) Vb[k] += vb[3 * i + k] / double(n);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(Vb[k], V[k], 1e-12);
    // omega from the relative velocities: v - V = omega x r; with r and w = v - V at two nodes,
    // omega = (r1 x w1 ... ) is solved in least squares by the normal equations below.
    auto omega_of = [&](const std::vector<double>& x, const std::vector<double>& v, const double* cm, const double* Vm) {
        // sum over nodes of [r]x^T [r]x omega = sum [r]x^T (-(v - V))... written as
        // A omega = b with A = sum (|r|^2 I - r r^T), b = sum r x (v - V).
        double A[9] = {0}, rhs[3] = {0};
        for (size_t i = 0; i < x.size() / 3; ++i) {
            const double r[3] = {x[3 * i] - cm[0], x[3 * i + 1] - cm[1], x[3 * i + 2] - cm[2]};
            const double u[3] = {v[3 * i] - Vm[0], v[3 * i + 1] - Vm[1], v[3 * i + 2] - Vm[2]};
            const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
            for (int a = 0; a < 3; ++a)
                for (int c = 0; c < 3; ++c) A[3 * a + c] += (a == c ? r2 : 0.0) - r[a] * r[c];
            rhs[0] += r[1] * u[2] - r[2] * u[1];
            rhs[1] += r[2] * u[0] - r[0] * u[2];
            rhs[2] += r[0] * u[1] - r[1] * u[0];
        }
        // Cramer's rule.
        auto det = [](const double* M) {
            return M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) + M[2] * (M[3] * M[7] - M[4] * M[6]);
        };
        const double D = det(A);
        std::array<double, 3> out{};
        for (int k = 0; k < 3; ++k) {
            double Mk[9];
            for (int i = 0; i < 9; ++i) Mk[i] = A[i];
            for (int r = 0; r < 3; ++r) Mk[3 * r + k] = rhs[r];
            out[k] = det(Mk) / D;
        }
        return out;
    };
    const std::array<double, 3> wa = omega_of(xa, va, ca, V), wb = omega_of(xb, vb, cb, Vb);
    std::printf("spin before (%.12g, %.12g, %.12g), after (%.12g, %.12g, %.12g)\n", wa[0], wa[1], wa[2], wb[0], wb[1], wb[2]);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(wb[k], wa[k], 1e-12);
}

// A kinematic body with a shape: its nodes and its shape move with the pose (a ray finds the
// sphere where it went); a static body refuses to move.
TEST(Teleport, AKinematicBodyTakesItsShapesAlongAndAStaticOneRefuses) {
    World w;
    lfem_body_def kd = lfem_body_def_default();
    kd.type = LFEM_BODY_KINEMATIC;
    lfem_body k{};
    ASSERT_EQ(lfem_body_create(w, &kd, &k), LFEM_OK);
    lfem_shape_def sphere = lfem_shape_def_default();
    sphere.type = LFEM_SHAPE_SPHERE;
    sphere.radius = 0.1;
    ASSERT_EQ(lfem_body_add_shape(w, k, &sphere, nullptr), LFEM_OK) << lfem_last_error();
    const double T[7] = {0, 0, 2, 1, 0, 0, 0};
    ASSERT_EQ(lfem_body_set_transform(w, k, T), LFEM_OK) << lfem_last_error();
    const double origin[3] = {0, 0, 5}, down[3] = {0, 0, -1};
    lfem_ray_hit hit{};
    int found = 0;
    ASSERT_EQ(lfem_world_cast_ray(w, origin, down, 10.0, lfem_query_filter_default(), &hit, &found), LFEM_OK)
        << lfem_last_error();
    ASSERT_EQ(found, 1);
    EXPECT_NEAR(hit.point[2], 2.1, 1e-12);  // the sphere's top, moved up 2 m
    const lfem_body floor = add_plane_floor(w);
    const double before[7] = {0, 0, 0, 1, 0, 0, 0};
    EXPECT_EQ(lfem_body_set_transform(w, floor, before), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("static"), std::string::npos);
}

// Node positions set at will: a cube stretched 10 % along x (nu = 0: no lateral stress) holds the
// strain energy E eps^2 V / 2 (linear tets take a uniform strain exactly), booked as the caller's
// work (the balance does not move); velocities are kept.
TEST(Teleport, SetPositionsStretchesACubeWithTheWorkBooked) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0;
    World w(wd);
    Mesh m;
    const lfem_body b = stretched_linear_cube(w, m, 1.0);  // at rest, unstretched
    std::vector<double> x = positions(w, b);
    const std::vector<double> v0 = velocities(w, b);
    const lfem_world_stats s0 = stats(w);
    for (size_t i = 0; i < x.size(); i += 3) x[i] *= 1.1;
    ASSERT_EQ(lfem_body_set_positions(w, b, x.data(), uint32_t(x.size() / 3)), LFEM_OK) << lfem_last_error();
    const lfem_world_stats s1 = stats(w);
    const double expected = 0.5 * 1e5 * 0.01 * 1e-3;
    std::printf("stretched cube: strain energy %.12g J (E eps^2 V / 2 = %.12g J)\n", s1.strain_energy, expected);
    EXPECT_NEAR(s1.strain_energy, expected, 1e-12 * expected);
    EXPECT_NEAR(s1.external_work - s0.external_work, expected, 1e-12 * expected);
    EXPECT_NEAR(s1.energy_error, s0.energy_error, 1e-12 * expected);
    EXPECT_EQ(velocities(w, b), v0);
    EXPECT_EQ(positions(w, b), x);
}

// Bad input is refused with the world as it was: the wrong node count, a NaN, a NULL pointer,
// a zero quaternion, a stale handle, a rigid body's nodes one by one.
TEST(Teleport, BadInputIsRefusedAndChangesNothing) {
    World w;
    Mesh m, r;
    make_box_mesh(m, 0.1, 0.1, 0.1, 1, 1, 1, 0, 0, 0.5);
    const lfem_body b = add_body(w, lfem_body_def_default(), m);
    make_box_mesh(r, 0.1, 0.1, 0.1, 1, 1, 1, 1, 0, 0.5);
    lfem_body_def rd = lfem_body_def_default();
    rd.type = LFEM_BODY_RIGID;
    const lfem_body rigid = add_body(w, rd, r);
    ASSERT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(w, {b, rigid});
    std::vector<double> x = positions(w, b);
    EXPECT_EQ(lfem_body_set_positions(w, b, x.data(), uint32_t(x.size() / 3) - 1), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_positions(w, b, nullptr, uint32_t(x.size() / 3)), LFEM_INVALID_ARGUMENT);
    x[4] = NAN;
    EXPECT_EQ(lfem_body_set_positions(w, b, x.data(), uint32_t(x.size() / 3)), LFEM_INVALID_ARGUMENT);
    std::vector<double> far = positions(w, b);  // finite, but a strain whose energy overflows
    far[0] = 1e200;
    EXPECT_EQ(lfem_body_set_positions(w, b, far.data(), uint32_t(far.size() / 3)), LFEM_INVALID_ARGUMENT);
    std::vector<double> xr = positions(w, rigid);
    EXPECT_EQ(lfem_body_set_positions(w, rigid, xr.data(), uint32_t(xr.size() / 3)), LFEM_INVALID_ARGUMENT);
    const double zero_q[7] = {0, 0, 0, 0, 0, 0, 0}, nan_t[7] = {NAN, 0, 0, 1, 0, 0, 0}, ok[7] = {0, 0, 0, 1, 0, 0, 0};
    EXPECT_EQ(lfem_body_set_transform(w, b, zero_q), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_transform(w, b, nan_t), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_transform(w, b, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_set_transform(w, lfem_body{b.index, b.generation + 7}, ok), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_set_transform(nullptr, b, ok), LFEM_INVALID_ARGUMENT);
    double out[7];
    EXPECT_EQ(lfem_body_get_transform(w, b, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_body_get_transform(w, lfem_body{b.index, b.generation + 7}, out), LFEM_INVALID_HANDLE);
    EXPECT_EQ(lfem_body_get_center_of_mass(w, b, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(fingerprint(w, {b, rigid}), before);
}
