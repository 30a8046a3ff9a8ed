// Impacts: no tunnelling at high speed, and no energy created by a collision.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

// quadratic: the plate and the cube of 10-node tets (the cube's mid-edge nodes are slaves, the
// plate's faces 4 flat triangles each), the cube on 2^3 cells.
void fast_cube_against_thin_plate(bool quadratic) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    // A static plate 0.1 mm thick; a 2 cm plastic cube (E = 1e9 Pa) at 100 m/s, a tenth of its
    // wave speed. Its stable step, ~4e-6 s, carries it 0.4 mm per step: four times the plate's
    // thickness, so only the swept path (x^n -> x*) can catch it.
    Mesh plate_mesh, cube_mesh;
    make_box_mesh(plate_mesh, 0.2, 0.2, 1e-4, 8, 8, 1, -0.1, -0.1, -1e-4);
    if (quadratic) {
        ASSERT_EQ(lfem_mesh_make_quadratic(plate_mesh.m), LFEM_OK);
    }
    lfem_body_def p = lfem_body_def_default();
    p.type = LFEM_BODY_STATIC;
    p.friction = 0.0;
    add_body(w, p, plate_mesh);
    if (quadratic)
        make_quadratic_box_mesh(cube_mesh, 0.02, 0.02, 0.02, 2, 2, 2, -0.01, -0.01, 0.005);
    else
        make_box_mesh(cube_mesh, 0.02, 0.02, 0.02, 3, 3, 3, -0.01, -0.01, 0.005);
    lfem_body_def c = lfem_body_def_default();
    c.model = LFEM_MODEL_NEO_HOOKEAN;  // ~10 % strain on impact: beyond small strain
    c.young_modulus = 1e9;
    c.friction = 0.0;
    c.linear_velocity[2] = -100.0;
    const lfem_body cube = add_body(w, c, cube_mesh);
    const double h = 0.9 * stable_step(w);
    const double per_step = 100.0 * h;
    double lowest = 1.0, penetration = 0.0;
    for (int i = 0; i < (quadratic ? 600 : 400); ++i) {  // the 10-node cube's steps are shorter
        ASSERT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
        const std::vector<double> x = positions(w, cube);
        for (size_t k = 2; k < x.size(); k += 3) lowest = std::fmin(lowest, x[k]);
        penetration = std::fmax(penetration, stats(w).max_penetration);
    }
    double P[3];
    lfem_body_get_momentum(w, cube, P, nullptr);
    std::printf("100 m/s cube vs 0.1 mm plate (%s tets): %.2f mm per step, lowest node z = %.3g m, "
                "penetration <= %.2e m, momentum after %.4f kg m/s (upward)\n",
                quadratic ? "10-node" : "4-node", per_step * 1e3, lowest, penetration, P[2]);
    EXPECT_GT(per_step, 1e-4);      // the test is about tunnelling: steps longer than the plate
    EXPECT_GT(lowest, -1e-6);       // never below the plate's top face (z = 0)
    EXPECT_GT(P[2], 0.0);           // it bounced
}

TEST(Impact, FastSmallBodyDoesNotPassThroughAThinPlate) { fast_cube_against_thin_plate(false); }

TEST(Impact, FastSmallQuadraticBodyDoesNotPassThroughAThinQuadraticPlate) { fast_cube_against_thin_plate(true); }

TEST(Impact, ClosedFrictionlessUndampedCollisionNeverCreatesEnergy) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh a_mesh, b_mesh;
    make_box_mesh(a_mesh, 0.1, 0.1, 0.1, 4, 4, 4, -0.101, -0.05, -0.05);
    make_box_mesh(b_mesh, 0.1, 0.08, 0.08, 4, 3, 3, 0.001, -0.03, -0.02);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 1e6;
    d.friction = 0.0;
    d.linear_velocity[0] = 2.0;
    add_body(w, d, a_mesh);
    d.linear_velocity[0] = -1.0;
    d.angular_velocity[1] = 5.0;  // oblique, spinning: edges and faces both touch
    add_body(w, d, b_mesh);
    const lfem_world_stats s0 = stats(w);
    const double E0 = s0.kinetic_energy + s0.strain_energy;
    double worst = -1, contacts = 0;
    for (int i = 0; i < 400; ++i) {
        ASSERT_EQ(lfem_world_step(w, 2.5e-4), LFEM_OK) << lfem_last_error();
        const lfem_world_stats s = stats(w);
        worst = std::fmax(worst, (s.kinetic_energy + s.strain_energy) / E0 - 1);
        contacts = std::fmax(contacts, s.contact_count);
    }
    const lfem_world_stats s = stats(w);
    std::printf("closed collision: largest energy rise %+.2e of E0, final %+.2f %%, up to %.0f contacts\n",
                worst, 100 * ((s.kinetic_energy + s.strain_energy) / E0 - 1), contacts);
    EXPECT_GT(contacts, 10);
    // Never above the start, up to the measuring wobble of central differences: the energy
    // read at the integer step oscillates by ~(omega h)^2/4 of the strain energy in the
    // fastest excited modes, a few 1e-3 of the total here (0.24 % in the free vibration test).
    EXPECT_LT(worst, 5e-3);
    EXPECT_LT(s.kinetic_energy + s.strain_energy, E0);  // after the impact: strictly less
}

TEST(Impact, BodiesCreatedOverlappingSeparateGently) {
    // Two soft blocks created 3 mm into each other (an eighth of an element): the overlap is
    // removed over many steps, at most 1e-3 of an edge per step, instead of in one violent jump.
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh a_mesh, b_mesh;
    make_box_mesh(a_mesh, 0.1, 0.1, 0.1, 4, 4, 4, -0.1, -0.05, -0.05);
    make_box_mesh(b_mesh, 0.1, 0.1, 0.1, 4, 4, 4, -0.003, -0.05, -0.05);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.friction = 0.0;
    d.damping = 5.0;
    const lfem_body a = add_body(w, d, a_mesh);
    const lfem_body b = add_body(w, d, b_mesh);
    double fastest = 0;
    for (int i = 0; i < 400; ++i) {
        ASSERT_EQ(lfem_world_step(w, 5e-4), LFEM_OK) << lfem_last_error();
        for (lfem_body body : {a, b})
            for (double v : velocities(w, body)) fastest = std::fmax(fastest, std::fabs(v));
    }
    const std::vector<double> xa = positions(w, a), xb = positions(w, b);
    double a_right = -1, b_left = 1;
    for (size_t k = 0; k < xa.size(); k += 3) a_right = std::fmax(a_right, xa[k]);
    for (size_t k = 0; k < xb.size(); k += 3) b_left = std::fmin(b_left, xb[k]);
    std::printf("overlapping start: remaining overlap %.2e m, fastest node %.3f m/s, penetration %.2e m\n",
                a_right - b_left, fastest, stats(w).max_penetration);
    EXPECT_LT(a_right - b_left, 1e-5);  // separated (3 mm of overlap gone)
    // Gentle: pushing 3 mm apart at <= 2.5e-5 m per step of ~1e-4 s is ~0.25 m/s; an
    // explosive separation would reach the wave speed (~37 m/s).
    EXPECT_LT(fastest, 1.0);
}
