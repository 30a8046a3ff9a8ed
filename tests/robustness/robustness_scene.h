// One scene that exercises every kind of state a world holds: a static box mesh and a static
// sphere shape, a kinematic plank, a rigid box, a corotational and a neo-Hookean soft body
// (one with fixed nodes and node forces, one spinning, one with a skin), a corotational body of
// 10-node tets with a skin, a destroyed body (a free slot), and contact between all of them. The checkpoint, out-of-memory and thread tests all run it. With
// `cells` = 10 the corotational body has 6000 tets and 1331 nodes: enough for many element
// blocks and colours and two node blocks, so every parallel loop of a multi-threaded world
// really splits.
#pragma once

#include <algorithm>
#include <vector>

#include "physics/lfem_test_util.h"

namespace lfem_test {

struct RobustnessScene {
    World w;
    std::vector<lfem_body> bodies;

    explicit RobustnessScene(uint32_t thread_count = 1, uint32_t cells = 3) : w(def(thread_count)) {
        Mesh floor_mesh, plank, rigid, a, b, spare, small;
        make_box_mesh(floor_mesh, 0.6, 0.6, 0.1, 3, 3, 1, -0.3, -0.3, -0.1);
        lfem_body_def f = lfem_body_def_default();
        f.type = LFEM_BODY_STATIC;
        bodies.push_back(add_body(w, f, floor_mesh));
        lfem_shape_def sphere = lfem_shape_def_default();
        sphere.type = LFEM_SHAPE_SPHERE;
        sphere.radius = 0.05;
        sphere.center[0] = 0.2;
        EXPECT_EQ(lfem_body_add_shape(w, bodies[0], &sphere, NULL), LFEM_OK) << lfem_last_error();

        lfem_body_def k = lfem_body_def_default();
        k.type = LFEM_BODY_KINEMATIC;
        k.linear_velocity[1] = 0.1;
        make_box_mesh(plank, 0.1, 0.1, 0.02, 2, 2, 1, 0.12, -0.05, 0.0);
        bodies.push_back(add_body(w, k, plank));

        // A body created and destroyed again: its slot is free in the saved world.
        make_box_mesh(spare, 0.05, 0.05, 0.05, 1, 1, 1, 0.0, 0.0, 1.0);
        const lfem_body gone = add_body(w, lfem_body_def_default(), spare);
        EXPECT_EQ(lfem_body_destroy(w, gone), LFEM_OK);

        lfem_body_def r = lfem_body_def_default();
        r.type = LFEM_BODY_RIGID;
        r.density = 500;
        make_box_mesh(rigid, 0.06, 0.06, 0.06, 1, 1, 1, 0.17, -0.03, 0.04);
        bodies.push_back(add_body(w, r, rigid));

        lfem_body_def d = lfem_body_def_default();
        d.model = LFEM_MODEL_COROTATIONAL;
        d.young_modulus = 3e5;
        d.angular_velocity[0] = 2.0;
        make_box_mesh(a, 0.1, 0.1, 0.1, cells, cells, cells, -0.05, -0.05, 0.02);
        bodies.push_back(add_body(w, d, a));
        const double force[3] = {0.5, 0.0, 0.0};
        const uint32_t node = 0;
        EXPECT_EQ(lfem_body_set_node_forces(w, bodies.back(), &node, 1, force), LFEM_OK);
        add_skin_to(bodies.back(), 0.0, 0.0, 0.07);

        d.model = LFEM_MODEL_NEO_HOOKEAN;
        d.angular_velocity[0] = 0.0;
        make_box_mesh(b, 0.08, 0.08, 0.08, 2, 2, 2, -0.02, -0.04, 0.16);
        bodies.push_back(add_body(w, d, b));

        lfem_body_def p = lfem_body_def_default();  // the paper model, one node held
        p.damping = 0.5;
        make_box_mesh(small, 0.05, 0.05, 0.05, 1, 1, 1, -0.2, 0.1, 0.0);
        bodies.push_back(add_body(w, p, small));
        const uint32_t held = 0;
        EXPECT_EQ(lfem_body_fix_nodes(w, bodies.back(), &held, 1), LFEM_OK);

        Mesh quadratic;  // 10-node tets: quadrature-point rotations, 6-node faces
        d.model = LFEM_MODEL_COROTATIONAL;
        d.angular_velocity[2] = 1.0;
        make_quadratic_box_mesh(quadratic, 0.06, 0.06, 0.06, 1, 1, 2, -0.2, -0.2, 0.002);
        bodies.push_back(add_body(w, d, quadratic));
        add_skin_to(bodies.back(), -0.17, -0.17, 0.03);  // bound to all ten nodes of its tets

        Mesh composite;  // the composite 10-node element: its table chosen again from the def on load
        d.composite_tets = 1;
        d.angular_velocity[2] = -1.0;
        make_quadratic_box_mesh(composite, 0.05, 0.05, 0.05, 1, 1, 1, -0.2, 0.2, 0.002);
        bodies.push_back(add_body(w, d, composite));
    }

    static lfem_world_def def(uint32_t thread_count) {
        lfem_world_def d = lfem_world_def_default();
        d.thread_count = thread_count;
        return d;
    }

    // Steps n times by dt and returns the largest contact count seen (the scene must touch).
    uint32_t run(int n, double dt = 0.005) {
        uint32_t most = 0;
        for (int i = 0; i < n; ++i) {
            EXPECT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
            most = std::max(most, stats(w).contact_count);
        }
        return most;
    }

    std::vector<unsigned char> state() const { return fingerprint(w, bodies); }

    // A small render mesh about (x, y, z): a tetrahedron's surface, one vertex just outside
    // the body when it is near a face.
    void add_skin_to(lfem_body b, double x, double y, double z) {
        const double p[12] = {x - 0.03, y - 0.03, z - 0.03, x + 0.03, y - 0.03, z - 0.03,
                              x - 0.03, y + 0.03, z - 0.03, x - 0.03, y - 0.03, z + 0.04};
        const uint32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
        EXPECT_EQ(lfem_body_add_skin(w, b, p, 4, t, 4, nullptr), LFEM_OK) << lfem_last_error();
    }
};

}  // namespace lfem_test
