// Two thin plates (one cell thick, 1 cm) crossed edge on edge: a static one standing along x
// (30 x 10 cm, 12 x 1 x 4 cells, its top at z = 0) and a soft one (E 1e6) standing along y, its
// bottom 2 mm above, swung down onto it edge first. Where they cross (1 x 1 cm) no node of either
// lies over the other's edge face, so only their edges meet (the thin plate; shared by
// tests/physics/test_features.cpp and the known issue in test_known_issues.cpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/lfem_test_util.h"

namespace lfem_test {

struct ThinPlates {
    double deepest = 0;  // the deepest point of either plate's edges inside the other, any call (m)
    double element = 0;  // the soft plate's mean boundary edge (m)
    bool calls_ok = true;
};

// 20 calls of 1/60 s after the soft plate is set moving down at `speed` (m/s), its edge pass on
// or off (lfem_body_def.edge_contacts).
inline ThinPlates thin_plates_crossed(double speed, uint8_t edge_contacts) {
    World w;
    Mesh fixed, swung;
    make_box_mesh(fixed, 0.3, 0.01, 0.1, 12, 1, 4, -0.15, 0.0075, -0.1);
    make_box_mesh(swung, 0.01, 0.3, 0.1, 1, 12, 4, 0.0075, -0.15, 0.002);
    lfem_body_def sd = lfem_body_def_default();
    sd.type = LFEM_BODY_STATIC;
    const lfem_body base = add_body(w, sd, fixed);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.linear_velocity[2] = -speed;
    d.edge_contacts = edge_contacts;
    const lfem_body plate = add_body(w, d, swung);
    ThinPlates out;
    for (int frame = 0; frame < 20; ++frame) {
        out.calls_ok = out.calls_ok && lfem_world_step(w, 1.0 / 60.0) == LFEM_OK;
        const BodyShape s = body_shape(w, plate, swung), b = body_shape(w, base, fixed);
        out.deepest = std::max({out.deepest, deepest_edge_point(s, b), deepest_edge_point(b, s)});
        out.element = mean_boundary_edge(s);
    }
    return out;
}

}  // namespace lfem_test
