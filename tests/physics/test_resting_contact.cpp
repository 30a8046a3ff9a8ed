// Bodies at rest on a static floor: the contact forces carry exactly the weight, nothing
// jitters, nothing sinks.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// A static floor: the box [-0.5, 0.5]^2 x [-0.1, 0], of 4-node or 10-node tets.
lfem_body add_floor(lfem_world* w, Mesh& mesh, double friction = 0.5, bool quadratic = false) {
    if (quadratic)
        make_quadratic_box_mesh(mesh, 1.0, 1.0, 0.1, 4, 4, 1, -0.5, -0.5, -0.1);
    else
        make_box_mesh(mesh, 1.0, 1.0, 0.1, 4, 4, 1, -0.5, -0.5, -0.1);
    lfem_body_def def = lfem_body_def_default();
    def.type = LFEM_BODY_STATIC;
    def.friction = friction;
    return add_body(w, def, mesh);
}

// A block (0.1 m, on the floor from rest) settled for 1 s, then watched for 0.2 s: the worst
// departure of its normal contact force from m g (relative), of its RMS node speed, and of
// the penetration.
struct Rest {
    double force = 0, rms = 0, penetration = 0;
    uint32_t contacts = 0;
};

Rest settle_and_watch(lfem_world* w, lfem_body block) {
    double mass = 0;
    lfem_body_get_mass(w, block, &mass);
    EXPECT_EQ(lfem_world_step(w, 1.0), LFEM_OK) << lfem_last_error();
    Rest r;
    for (int i = 0; i < 200; ++i) {  // another 0.2 s, every millisecond
        EXPECT_EQ(lfem_world_step(w, 1e-3), LFEM_OK) << lfem_last_error();
        double f[3];
        contact_force_on(w, block, f);
        r.force = std::fmax(r.force, std::fabs(f[2] / (mass * 9.81) - 1));
        r.rms = std::fmax(r.rms, rms_velocity(w, block));
        r.penetration = std::fmax(r.penetration, stats(w).max_penetration);
    }
    r.contacts = stats(w).contact_count;
    return r;
}

lfem_body_def block_def() {
    lfem_body_def def = lfem_body_def_default();
    def.young_modulus = 1e6;
    def.damping = 20.0;  // settles the ringing of the sudden load within ~0.5 s
    return def;
}

}  // namespace

TEST(RestingContact, BlockOnFloorCarriesItsWeightWithoutJitter) {
    World w;
    Mesh floor_mesh, block_mesh;
    add_floor(w, floor_mesh);
    make_box_mesh(block_mesh, 0.1, 0.1, 0.1, 4, 4, 4, -0.05, -0.05, 0.0);
    const Rest r = settle_and_watch(w, add_body(w, block_def(), block_mesh));
    std::printf("resting block: normal force within %.2e of m g, RMS node velocity <= %.2e m/s, "
                "penetration <= %.2e m, %u contacts, %u sweeps\n",
                r.force, r.rms, r.penetration, r.contacts, stats(w).solver_iterations);
    EXPECT_LT(r.force, 0.005);  // the 0.5 %
    EXPECT_LT(r.rms, 1e-6);     // no jitter
    // Penetration: the solve stops at 1e-9 of the 2.5 cm edges; 1e-9 m bounds it with margin.
    EXPECT_LT(r.penetration, 1e-9);
}

// The same with a block of 10-node tets (2 x 2 x 2 cells: the same 2.5 cm node spacing), on a
// floor of 4-node tets and on one of 10-node tets, whose flat faces contact sees as 4 triangles
// each: the same bounds, as quiet as the linear block. The composite element
// (def.composite_tets) alike.
TEST(RestingContact, QuadraticBlockOnFloorCarriesItsWeightWithoutJitter) {
    for (bool composite : {false, true})
    for (bool quadratic_floor : {false, true}) {
        World w;
        Mesh floor_mesh, block_mesh;
        add_floor(w, floor_mesh, 0.5, quadratic_floor);
        make_quadratic_box_mesh(block_mesh, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0);
        lfem_body_def def = block_def();
        def.composite_tets = composite;
        const Rest r = settle_and_watch(w, add_body(w, def, block_mesh));
        std::printf("resting block of 10-node%s tets on a floor of %s tets: normal force within %.2e of m g, RMS "
                    "node velocity <= %.2e m/s, penetration <= %.2e m, %u contacts\n",
                    composite ? " composite" : "", quadratic_floor ? "10-node" : "4-node", r.force, r.rms,
                    r.penetration, r.contacts);
        EXPECT_LT(r.force, 0.005);
        EXPECT_LT(r.rms, 1e-6);
        EXPECT_LT(r.penetration, 1e-9);
    }
}

// Three soft cubes stacked on the floor (of 4-node tets, 3^3 cells, or of 10-node tets, 2^3).
void stack_of_three_comes_to_rest(bool quadratic) {
    World w;
    Mesh floor_mesh, cube[3];
    const lfem_body floor = add_floor(w, floor_mesh);
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    def.young_modulus = 2e5;  // soft: each cube squashes visibly under the ones above
    def.damping = 15.0;
    lfem_body bodies[3];
    for (int i = 0; i < 3; ++i) {
        // Each cube 1 mm above the one below (dropped into place), slightly offset sideways.
        if (quadratic)
            make_quadratic_box_mesh(cube[i], 0.1, 0.1, 0.1, 2, 2, 2, -0.05 + 0.01 * i, -0.05, 0.101 * i + 0.001);
        else
            make_box_mesh(cube[i], 0.1, 0.1, 0.1, 3, 3, 3, -0.05 + 0.01 * i, -0.05, 0.101 * i + 0.001);
        bodies[i] = add_body(w, def, cube[i]);
    }
    // Calls of 0.25 s, all with the same automatic sub-step. (Switching to much shorter calls,
    // whose sub-step is half as long, was seen to start a slow frictional yaw creep of the upper
    // cubes, ~1e-3 m/s: under investigation, see the README's known issues.)
    double worst_penetration = 0;
    for (int i = 0; i < 12; ++i) {
        ASSERT_EQ(lfem_world_step(w, 0.25), LFEM_OK) << lfem_last_error();
        if (i >= 8) worst_penetration = std::fmax(worst_penetration, stats(w).max_penetration);
    }
    // At rest: the kinetic energy left is below 1e-6 of the stack's potential energy
    // m g h (~3 J for three 1 kg cubes 0.1 m high), i.e. RMS speeds below ~1e-3 m/s.
    const double cube_mass = def.density * 0.1 * 0.1 * 0.1;  // kg, rho a^3
    const double potential = 3 * cube_mass * 9.81 * 0.1;
    const double kinetic = stats(w).kinetic_energy;
    // Each cube's lowest node sits on (not in) the one below: order kept, weights carried.
    // Each interface carries the weight of the cubes above it, upwards: the signed vertical force
    // of the floor on cube 0, of cube 0 on cube 1, of cube 1 on cube 2. At rest the net force
    // on each cube is zero, so these follow from the weights alone; 0.5 % (the resting block's
    // bound, the issue's) allows for the stack's residual motion (RMS node speeds of a few
    // 1e-4 m/s, at the cubes' ~100 rad/s: accelerations of ~1e-3 g). Sideways, friction carries
    // nothing on these level faces: below the same 0.5 %.
    double above[3] = {0, 0, 0}, weights = 0;  // N, the weight of the cubes above interface i
    for (int i = 2; i >= 0; --i) above[i] = weights += cube_mass * 9.81;
    const lfem_body below[3] = {floor, bodies[0], bodies[1]};
    const char* interface_name[3] = {"floor on cube 0", "cube 0 on cube 1", "cube 1 on cube 2"};
    for (int i = 0; i < 3; ++i) {
        double f[3];
        contact_force_between(w, bodies[i], below[i], f);
        std::printf("stack of 3 (%s tets): %s carries %.4f of the weight above, sideways %.1e of it\n",
                    quadratic ? "10-node" : "4-node", interface_name[i], f[2] / above[i], std::hypot(f[0], f[1]) / above[i]);
        EXPECT_NEAR(f[2], above[i], 0.005 * above[i]) << interface_name[i];
        EXPECT_LT(std::hypot(f[0], f[1]), 0.005 * above[i]) << interface_name[i];
    }
    // The floor's total, signed: the force on the floor from everything on it, downwards.
    double on_floor[3];
    contact_force_on(w, floor, on_floor);
    const double floor_force = -on_floor[2];
    std::printf("stack of 3 (%s tets): floor carries %.4f of the total weight, kinetic energy %.2e of m g h, "
                "penetration <= %.2e m\n",
                quadratic ? "10-node" : "4-node", floor_force / weights, kinetic / potential, worst_penetration);
    EXPECT_NEAR(floor_force, weights, 0.005 * weights);
    EXPECT_LT(kinetic, 1e-6 * potential);
    // At rest the solve stops once a sweep changes no pair's gap by more than 1e-3 of the motion
    // gravity gives a node in a sub-step, g h^2 (6e-9 m at the 10-node cubes' 0.77 ms, 1.6e-8 m
    // at the 4-node cubes' 1.26 ms). A pair still converging then has what the remaining sweeps
    // would have changed: below the last change over (1 - rate), ten of them at a rate of 0.9 a
    // sweep (the redundant two-pass constraints converge that slowly).
    const double h = stats(w).step_size;
    EXPECT_LT(worst_penetration, 10 * 1e-3 * 9.81 * h * h);
    // The order of the stack is kept: each cube's centre is above the one below by about a
    // cube height (squashed), never inside it.
    double z[3];
    for (int i = 0; i < 3; ++i) {
        const std::vector<double> x = positions(w, bodies[i]);
        z[i] = 0;
        for (size_t k = 2; k < x.size(); k += 3) z[i] += x[k] / (x.size() / 3);
    }
    EXPECT_GT(z[0], 0.03);
    EXPECT_GT(z[1] - z[0], 0.07);
    EXPECT_GT(z[2] - z[1], 0.07);
}

TEST(RestingContact, StackOfThreeSoftCubesComesToRestWithoutPenetration) { stack_of_three_comes_to_rest(false); }

// The upper cubes rest on the lower ones' 6-node faces (4 flat triangles each).
TEST(RestingContact, StackOfThreeQuadraticCubesComesToRestWithoutPenetration) { stack_of_three_comes_to_rest(true); }
