// Bodies of 10-node tets through the C API, against closed forms: the lumped masses (measured
// from the first step under node forces), a cantilever against Euler-Bernoulli with
// Timoshenko's shear term (no locking on one element through the depth), a block resting on a
// floor (the reaction is m g, nothing jitters) and on a block of 10-node tets, a free spin
// (angular momentum kept), a fast cube against a thin plate of 10-node tets (no tunnelling), the
// stable step's tightness, free vibration's energy, and a Gmsh file of 10-node tets to the
// boundary faces and a VTK frame.
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

double rms_velocity(lfem_world* w, lfem_body b) {
    const std::vector<double> v = velocities(w, b);
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s / (v.size() / 3));
}

// The summed contact force on body `on` (N): its nodes get the force, its triangles the opposite.
void contact_force_on(lfem_world* w, lfem_body on, double out[3]) {
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
    out[0] = out[1] = out[2] = 0;
    for (const lfem_contact& k : c) {
        const double sign = k.body_a.index == on.index ? 1.0 : (k.body_b.index == on.index ? -1.0 : 0.0);
        for (int d = 0; d < 3; ++d) out[d] += sign * k.force[d];
    }
}

lfem_body static_floor(lfem_world* w, Mesh& mesh, bool quadratic) {
    if (quadratic)
        make_quadratic_box_mesh(mesh, 1.0, 1.0, 0.1, 4, 4, 1, -0.5, -0.5, -0.1);
    else
        make_box_mesh(mesh, 1.0, 1.0, 0.1, 4, 4, 1, -0.5, -0.5, -0.1);
    lfem_body_def def = lfem_body_def_default();
    def.type = LFEM_BODY_STATIC;
    return add_body(w, def, mesh);
}

}  // namespace

// The first step from rest moves a free node by h^2 F / (2 m) (the velocity-Verlet start of
// central differences, no elastic force yet): so each node's mass is measured. Every one is
// positive, they sum to rho V, and each is the sub-tet lumping's rho V_e / 32 per tet at a corner,
// 7 rho V_e / 48 at a mid-edge node.
TEST(QuadraticTets, LumpedMassesArePositiveAndSumToRhoV) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh mesh;
    make_quadratic_box_mesh(mesh, 0.3, 0.2, 0.1, 3, 2, 1);
    lfem_body_def def = lfem_body_def_default();
    def.density = 2000.0;
    const lfem_body b = add_body(w, def, mesh);
    const uint32_t n = mesh.nodes();
    std::vector<uint32_t> all(n);
    std::iota(all.begin(), all.end(), 0u);
    std::vector<double> F(3 * n, 0.0);
    for (uint32_t i = 0; i < n; ++i) F[3 * i + 2] = 50.0;  // moves the nodes by ~1e-6 m
    ASSERT_EQ(lfem_body_set_node_forces(w, b, all.data(), n, F.data()), LFEM_OK);
    const double h = 1e-4;
    ASSERT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(stats(w).substeps_last_call, 1u);
    const std::vector<double> x = positions(w, b);
    const double* X = lfem_mesh_get_positions(mesh.m);
    const uint32_t* tets = lfem_mesh_get_tets(mesh.m);
    std::vector<double> expected(n, 0.0);
    for (uint32_t e = 0; e < mesh.tets(); ++e) {
        const double V = volume(std::vector<double>(X, X + 3 * n), tets + 10 * e, 1, 10);
        for (int a = 0; a < 10; ++a) expected[tets[10 * e + a]] += def.density * V * (a < 4 ? 1.0 / 32 : 7.0 / 48);
    }
    double total = 0, reported = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const double m = h * h * F[3 * i + 2] / (2 * (x[3 * i + 2] - X[3 * i + 2]));
        EXPECT_GT(m, 0.0) << "node " << i;
        // The displacement (~1e-6 m) is read as a difference of positions of up to 0.3 m:
        // 1e-10 relative.
        EXPECT_NEAR(m, expected[i], 1e-9 * expected[i]) << "node " << i;
        total += m;
    }
    ASSERT_EQ(lfem_body_get_mass(w, b, &reported), LFEM_OK);
    const double rhoV = def.density * 0.3 * 0.2 * 0.1;
    EXPECT_NEAR(total, rhoV, 1e-9 * rhoV);
    EXPECT_NEAR(reported, rhoV, 1e-12 * rhoV);
}

// The cantilever of test_cantilever.cpp (L/b = 10, nu = 0) on one cell through the depth and 10
// along. Linear tets need 100 x 10 cells for -2 %; quadratic ones do not lock in bending, and
// reach the Timoshenko deflection, Euler-Bernoulli's q L^4 / 8EI plus the shear term
// q L^2 / (2 kappa G A), here (E / 3 kappa G)(b / L)^2 = +0.8 % of it.
TEST(QuadraticTets, CantileverMatchesBeamTheoryOnOneElementThroughTheDepth) {
    World w;
    const double L = 0.5, b = 0.05, E = 6e8, rho = 1000.0, g = 9.81;
    Mesh mesh;
    make_quadratic_box_mesh(mesh, L, b, b, 10, 1, 1, 0, -b / 2, -b / 2);
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    def.young_modulus = E;
    def.poisson_ratio = 0.0;
    def.density = rho;
    const double I = b * b * b * b / 12.0, A = b * b;
    const double omega1 = 1.875104 * 1.875104 * std::sqrt(E * I / (rho * A * L * L * L * L));
    def.damping = 2.0 * omega1;  // critical for the first bending mode
    const lfem_body beam = add_body(w, def, mesh);
    const double lo[3] = {-1e-9, -1, -1}, hi[3] = {1e-9, 1, 1};
    const std::vector<uint32_t> clamped = nodes_in_box(w, beam, lo, hi);
    ASSERT_EQ(lfem_body_fix_nodes(w, beam, clamped.data(), uint32_t(clamped.size())), LFEM_OK);
    const double tlo[3] = {L - 1e-9, -1, -1}, thi[3] = {L + 1e-9, 1, 1};
    const std::vector<uint32_t> tip = nodes_in_box(w, beam, tlo, thi);
    ASSERT_EQ(lfem_world_step(w, 10.0 / omega1), LFEM_OK) << lfem_last_error();
    const std::vector<double> x = positions(w, beam);
    const double* x0 = lfem_mesh_get_positions(mesh.m);
    double sag = 0;
    for (uint32_t n : tip) sag += (x0[3 * n + 2] - x[3 * n + 2]) / tip.size();
    const double euler_bernoulli = rho * g * A * std::pow(L, 4) / (8 * E * I);
    const double shear = rho * g * A * L * L / (2 * (5.0 / 6.0) * (E / 2) * A);
    const double error = sag / euler_bernoulli - 1.0;
    std::printf("quadratic cantilever 10x1x1: tip deflection %.6g m, Euler-Bernoulli %.6g m (%+.2f %%), "
                "with shear %.6g m (%+.2f %%), %llu steps\n",
                sag, euler_bernoulli, 100 * error, euler_bernoulli + shear,
                100 * (sag / (euler_bernoulli + shear) - 1), (unsigned long long)stats(w).steps);
    EXPECT_LT(std::fabs(error), 0.01);  // the 1 %
    // Against Timoshenko: the coarse mesh and the fully clamped end (which also holds the
    // section's warping) stay within 0.5 %; the residual motion after w t = 10 is ~5e-4.
    EXPECT_NEAR(sag / (euler_bernoulli + shear), 1.0, 0.005);
}

// A block of 10-node tets at rest on a static floor (of linear tets, then of 10-node tets, whose
// flat faces are then 4 sub-triangles each): the contact forces carry m g; no jitter; no
// penetration. The same bounds as the linear block's (test_resting_contact.cpp).
TEST(QuadraticTets, BlockRestsOnAFloorWithoutJitter) {
    for (bool quadratic_floor : {false, true}) {
        World w;
        Mesh floor_mesh, block_mesh;
        static_floor(w, floor_mesh, quadratic_floor);
        make_quadratic_box_mesh(block_mesh, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0);
        lfem_body_def def = lfem_body_def_default();
        def.young_modulus = 1e6;
        def.damping = 20.0;  // settles the ringing of the sudden load within ~0.5 s
        const lfem_body block = add_body(w, def, block_mesh);
        double mass = 0;
        lfem_body_get_mass(w, block, &mass);
        ASSERT_EQ(lfem_world_step(w, 1.0), LFEM_OK) << lfem_last_error();
        double worst_penetration = 0, worst_rms = 0, worst_force = 0;
        for (int i = 0; i < 200; ++i) {
            ASSERT_EQ(lfem_world_step(w, 1e-3), LFEM_OK) << lfem_last_error();
            double f[3];
            contact_force_on(w, block, f);
            worst_force = std::fmax(worst_force, std::fabs(f[2] / (mass * 9.81) - 1));
            worst_rms = std::fmax(worst_rms, rms_velocity(w, block));
            worst_penetration = std::fmax(worst_penetration, stats(w).max_penetration);
        }
        std::printf("resting quadratic block on a %s floor: normal force within %.2e of m g, RMS node velocity "
                    "<= %.2e m/s, penetration <= %.2e m, %u contacts\n",
                    quadratic_floor ? "quadratic" : "linear", worst_force, worst_rms, worst_penetration,
                    stats(w).contact_count);
        EXPECT_LT(worst_force, 0.005);
        EXPECT_LT(worst_rms, 1e-6);
        EXPECT_LT(worst_penetration, 1e-9);
    }
}

// A block of 10-node tets on a deformable one on the floor: the floor carries both weights, the
// upper block the lower block's sub-triangles; nothing sinks.
TEST(QuadraticTets, StackOfTwoQuadraticBlocksCarriesItsWeight) {
    World w;
    Mesh floor_mesh, cube[2];
    static_floor(w, floor_mesh, false);
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    def.young_modulus = 2e5;
    def.damping = 15.0;
    lfem_body bodies[2];
    for (int i = 0; i < 2; ++i) {
        make_quadratic_box_mesh(cube[i], 0.1, 0.1, 0.1, 2, 2, 2, -0.05 + 0.01 * i, -0.05, 0.101 * i + 0.001);
        bodies[i] = add_body(w, def, cube[i]);
    }
    for (int i = 0; i < 8; ++i) ASSERT_EQ(lfem_world_step(w, 0.25), LFEM_OK) << lfem_last_error();
    double weights = 0, upper = 0, f_upper[3];
    for (int i = 0; i < 2; ++i) {
        double m = 0;
        lfem_body_get_mass(w, bodies[i], &m);
        weights += m * 9.81;
        if (i == 1) upper = m * 9.81;
    }
    contact_force_on(w, bodies[1], f_upper);  // the upper block: held by the lower one alone
    double f_floor = 0;
    {
        uint32_t count = 0;
        lfem_world_query_contacts(w, nullptr, 0, &count);
        std::vector<lfem_contact> c(count);
        lfem_world_query_contacts(w, c.data(), count, &count);
        for (const lfem_contact& k : c)
            if (k.body_a.index == 0 || k.body_b.index == 0) f_floor += std::fabs(k.force[2]);
    }
    std::printf("stack of 2 quadratic blocks: floor carries %.5f of both weights, the lower block %.5f of the "
                "upper one's; penetration %.2e m\n",
                f_floor / weights, f_upper[2] / upper, stats(w).max_penetration);
    // Damped to rest over 2 s (15/s): the residual ringing is far below the 0.5 % bound.
    EXPECT_NEAR(f_floor, weights, 0.005 * weights);
    EXPECT_NEAR(f_upper[2], upper, 0.005 * upper);
    // The solve stops at 1e-9 of the 2.5 cm sub-triangle edges at rest; 1e-8 m allows for the
    // redundant two-pass constraints (as for the linear stack, test_resting_contact.cpp).
    EXPECT_LT(stats(w).max_penetration, 1e-8);
}

// A free body of 10-node tets spinning 10 turns: with one polar rotation per quadrature point
// the corotational stresses carry no torque, nor do neo-Hookean ones (frame-indifferent), so
// angular momentum is kept to round-off; the volume moves by the centrifugal ~4e-5 only.
TEST(QuadraticTets, FreeSpinKeepsAngularMomentum) {
    for (lfem_model model : {LFEM_MODEL_COROTATIONAL, LFEM_MODEL_NEO_HOOKEAN}) {
        lfem_world_def wd = lfem_world_def_default();
        wd.gravity[2] = 0.0;
        World w(wd);
        Mesh mesh;
        make_quadratic_box_mesh(mesh, 0.2, 0.1, 0.05, 2, 1, 1, -0.1, -0.05, -0.025);
        lfem_body_def def = lfem_body_def_default();
        def.model = model;
        def.young_modulus = 1e7;
        def.angular_velocity[2] = 2 * M_PI;
        const lfem_body b = add_body(w, def, mesh);
        const double V0 = volume(positions(w, b), lfem_mesh_get_tets(mesh.m), mesh.tets(), 10);
        const lfem_world_stats s0 = stats(w);
        for (int call = 0; call < 1000; ++call) ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
        const lfem_world_stats s = stats(w);
        double dL = 0, L0 = 0;
        for (int k = 0; k < 3; ++k) {
            dL += std::pow(s.angular_momentum[k] - s0.angular_momentum[k], 2);
            L0 += std::pow(s0.angular_momentum[k], 2);
        }
        const double dV = volume(positions(w, b), lfem_mesh_get_tets(mesh.m), mesh.tets(), 10) / V0 - 1;
        std::printf("quadratic spin (model %d): |dL|/|L| %.2e, volume of the corners' tets %+.2e, %llu steps\n",
                    int(model), std::sqrt(dL / L0), dV, (unsigned long long)s.steps);
        EXPECT_LT(std::sqrt(dL / L0), 1e-9);
        EXPECT_LT(std::fabs(dV), 1e-3);
    }
}

// The linear tets' tunnelling case (test_impact.cpp) with a cube and a plate of 10-node tets:
// the cube's mid-edge nodes are slaves, the plate's faces 4 flat triangles each.
TEST(QuadraticTets, FastCubeDoesNotPassThroughAThinPlate) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh plate_mesh, cube_mesh;
    make_quadratic_box_mesh(plate_mesh, 0.2, 0.2, 1e-4, 8, 8, 1, -0.1, -0.1, -1e-4);
    lfem_body_def p = lfem_body_def_default();
    p.type = LFEM_BODY_STATIC;
    p.friction = 0.0;
    add_body(w, p, plate_mesh);
    make_quadratic_box_mesh(cube_mesh, 0.02, 0.02, 0.02, 2, 2, 2, -0.01, -0.01, 0.005);
    lfem_body_def c = lfem_body_def_default();
    c.model = LFEM_MODEL_NEO_HOOKEAN;
    c.young_modulus = 1e9;
    c.friction = 0.0;
    c.linear_velocity[2] = -100.0;
    const lfem_body cube = add_body(w, c, cube_mesh);
    const double h = 0.9 * stable_step(w);
    double lowest = 1.0;
    for (int i = 0; i < 600; ++i) {
        ASSERT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
        const std::vector<double> x = positions(w, cube);
        for (size_t k = 2; k < x.size(); k += 3) lowest = std::fmin(lowest, x[k]);
    }
    double P[3];
    lfem_body_get_momentum(w, cube, P, nullptr);
    std::printf("100 m/s quadratic cube vs 0.1 mm quadratic plate: %.2f mm per step, lowest node z = %.3g m, "
                "momentum after %.4f kg m/s (upward)\n",
                100.0 * h * 1e3, lowest, P[2]);
    EXPECT_GT(100.0 * h, 1e-4);  // steps longer than the plate is thick
    EXPECT_GT(lowest, -1e-6);
    EXPECT_GT(P[2], 0.0);
}

// The estimate of the stable limit is tight for 10-node tets too: 0.95 of it runs, 1.1 blows up.
TEST(QuadraticTets, StableLimitIsTight) {
    for (double factor : {0.95, 1.1}) {
        lfem_world_def wd = lfem_world_def_default();
        wd.allow_unstable_step = 1;
        World w(wd);
        Mesh mesh;
        make_quadratic_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
        lfem_body_def def = lfem_body_def_default();
        def.model = LFEM_MODEL_COROTATIONAL;
        def.young_modulus = 1e6;
        def.linear_velocity[0] = 0.5;
        def.angular_velocity[1] = 3.0;
        add_body(w, def, mesh);
        const double limit = stable_step(w);
        ASSERT_EQ(lfem_world_set_time_step(w, factor * limit), LFEM_OK);
        lfem_status status = LFEM_OK;
        for (int call = 0; call < 300 && status == LFEM_OK; ++call) status = lfem_world_step(w, 10 * factor * limit);
        if (factor < 1)
            EXPECT_EQ(status, LFEM_OK) << "factor " << factor << ": " << lfem_last_error();
        else
            EXPECT_EQ(status, LFEM_UNSTABLE) << "factor " << factor;
    }
}

// Undamped free vibration of a bar of 10-node tets, every model: the total energy only
// oscillates by the scheme's O((omega h)^2), within the 0.5 % of the linear tets' test.
TEST(QuadraticTets, FreeVibrationKeepsItsEnergy) {
    for (lfem_model model : {LFEM_MODEL_PAPER, LFEM_MODEL_COROTATIONAL, LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_LINEAR}) {
        lfem_world_def wd = lfem_world_def_default();
        wd.gravity[2] = 0.0;
        World w(wd);
        Mesh mesh;
        make_quadratic_box_mesh(mesh, 0.1, 0.1, 0.6, 1, 1, 6, -0.05, -0.05, 0.0);
        lfem_body_def def = lfem_body_def_default();
        def.model = model;
        def.young_modulus = 1e6;
        const lfem_body b = add_body(w, def, mesh);
        const std::vector<double> x = positions(w, b);
        std::vector<double> v(x.size());
        for (size_t i = 0; i < x.size() / 3; ++i) {  // twist and stretch, as test_energy.cpp
            const double z = x[3 * i + 2] / 0.6;
            v[3 * i + 0] = -1.0 * x[3 * i + 1] * (z - 0.5);
            v[3 * i + 1] = 1.0 * x[3 * i + 0] * (z - 0.5);
            v[3 * i + 2] = 0.05 * (z - 0.5);
        }
        ASSERT_EQ(lfem_body_set_velocities(w, b, v.data(), uint32_t(x.size() / 3)), LFEM_OK);
        const lfem_world_stats s0 = stats(w);
        const double E0 = s0.kinetic_energy + s0.strain_energy;
        const double h = 0.9 * stable_step(w);
        double worst = 0, strain_peak = 0;
        for (int step = 0; step < 1000; ++step) {
            ASSERT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
            const lfem_world_stats s = stats(w);
            worst = std::fmax(worst, std::fabs(s.kinetic_energy + s.strain_energy - E0) / E0);
            strain_peak = std::fmax(strain_peak, s.strain_energy);
        }
        std::printf("quadratic free vibration (model %d): largest relative energy change %.3g, strain energy "
                    "reached %.0f %% of the total\n",
                    int(model), worst, 100 * strain_peak / E0);
        EXPECT_GT(strain_peak, 0.2 * E0);
        EXPECT_LT(worst, 0.005);
    }
}

// A Gmsh file of 10-node tets (type 11) through the API: its mesh, the body's 6-node boundary
// faces (the cube's six unit squares: mid-edge nodes on the middles of their edges, area 6),
// the flat triangles contact uses (4 a face), and a VTK frame of quadratic cells.
TEST(QuadraticTets, GmshFileBoundaryFacesAndVtkFrame) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without file I/O (LFEM_WITH_IO=OFF)";
    Mesh mesh;
    ASSERT_EQ(lfem_mesh_load_gmsh((std::string(LFEM_TEST_DATA_DIR) + "/cube10_v41.msh").c_str(), &mesh.m), LFEM_OK)
        << lfem_last_error();
    ASSERT_EQ(mesh.nodes_per_tet(), 10u);
    World w;
    const lfem_body b = add_body(w, lfem_body_def_default(), mesh);
    uint32_t width = 0, faces = 0, triangles = 0, tets = 0;
    ASSERT_EQ(lfem_body_get_nodes_per_tet(w, b, &width), LFEM_OK);
    ASSERT_EQ(lfem_body_get_boundary_face_count(w, b, &faces), LFEM_OK);
    ASSERT_EQ(lfem_body_get_boundary_triangle_count(w, b, &triangles), LFEM_OK);
    ASSERT_EQ(lfem_body_get_tet_count(w, b, &tets), LFEM_OK);
    EXPECT_EQ(width, 10u);
    EXPECT_EQ(tets, mesh.tets());
    EXPECT_EQ(triangles, 4 * faces);
    std::vector<uint32_t> f(6 * faces);
    ASSERT_EQ(lfem_body_get_boundary_faces(w, b, f.data(), faces), LFEM_OK);
    const std::vector<double> x = positions(w, b);
    double area = 0;
    for (uint32_t k = 0; k < faces; ++k) {
        const double* p[6];
        for (int i = 0; i < 6; ++i) p[i] = &x[3 * f[6 * k + i]];
        for (int i = 0; i < 3; ++i)
            for (int d = 0; d < 3; ++d) EXPECT_NEAR(p[3 + i][d], 0.5 * (p[i][d] + p[(i + 1) % 3][d]), 1e-12);
        const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        // Outward: the normal points away from the cube's centre (0.5, 0.5, 0.5).
        EXPECT_GT(n[0] * (p[0][0] - 0.5) + n[1] * (p[0][1] - 0.5) + n[2] * (p[0][2] - 0.5), 0.0);
    }
    EXPECT_NEAR(area, 6.0, 1e-12);
    const std::string pvd = ::testing::TempDir() + "lfem_quadratic_frame.pvd";
    lfem_vtk_series* series = nullptr;
    ASSERT_EQ(lfem_vtk_series_create(pvd.c_str(), &series), LFEM_OK);
    ASSERT_EQ(lfem_vtk_series_write_frame(series, w), LFEM_OK) << lfem_last_error();
    lfem_vtk_series_destroy(series);
    const std::string vtu = ::testing::TempDir() + "lfem_quadratic_frame_000000.vtu";
    FILE* in = std::fopen(vtu.c_str(), "r");
    ASSERT_NE(in, nullptr);
    std::string text;
    for (int c; (c = std::fgetc(in)) != EOF;) text.push_back(char(c));
    std::fclose(in);
    std::size_t cells24 = 0;
    const std::size_t types = text.find("Name=\"types\"");
    for (std::size_t at = text.find("          24\n", types); at != std::string::npos; at = text.find("          24\n", at + 1))
        ++cells24;
    EXPECT_EQ(cells24, tets);
    std::remove(vtu.c_str());
    std::remove(pvd.c_str());
}
