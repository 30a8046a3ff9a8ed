// What the caller reads of one body that takes computing: its stresses, its rotation, its
// inversion, the nodes in a box. (Plain values the shim copies straight from the body.)
#include <algorithm>

#include "world/world.h"

namespace lfem {

void World::von_mises_stress(const Body& b, double* out) const {
    if (!b.is_deformable()) {
        std::fill(out, out + b.ref.tet_count(), 0.0);  // rigid: no strain is modelled
        return;
    }
    compute_von_mises(element_mesh(b.ref), material_of(b), b.state.x.data(), b.state.tet_rotation.data(),
                      b.state.global.rotation, out);
}

void World::rotation_matrix(const Body& b, double out[9]) const {
    const bool framed = b.is_rigid() || b.is_paper() || b.is_kinematic();
    const Mat3 R = load_quaternion(b.state.global.rotation).toRotationMatrix();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = framed ? R(r, c) : (r == c);
}

Inversion World::inversion(const Body& b) const {
    Inversion out;
    if (!b.is_deformable() || !b.has_mesh()) return out;
    const BodyState& s = b.state;
    out.inverted_tets = s.inverted_tets;
    out.min_jacobian = s.min_jacobian;
    out.inverted_for = s.inverted_since >= 0.0 ? state_.counters.time - s.inverted_since : 0.0;
    return out;
}

std::vector<uint32_t> World::nodes_in_box(const Body& b, const double lo[3], const double hi[3]) const {
    std::vector<uint32_t> found;
    for (uint32_t api = 0; api < b.ref.node_count(); ++api) {  // ascending, as the caller numbers
        const double* x = &b.state.x[3 * std::size_t(b.ref.numbering.node(api))];
        bool inside = true;
        for (int k = 0; k < 3; ++k) inside = inside && x[k] >= lo[k] && x[k] <= hi[k];
        if (inside) found.push_back(api);
    }
    return found;
}

}  // namespace lfem
