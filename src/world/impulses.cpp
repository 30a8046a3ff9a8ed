// A one-shot impulse at a world point (lfem_body_apply_impulse): the velocity change a hit gives,
// as engines apply it. A deformable body takes it on the nodes of the tet around the point, where
// the nodes are now, node k its share w_k J by the tet's shape functions at the point (the
// skin's weights: they sum to 1 and reproduce the point, so the body gains J as momentum and
// p x J as angular momentum about the origin, exactly); a rigid body as a whole, J / M and
// I^-1 (p - c) x J. The velocities change as lfem_body_set_velocities changes them: the change
// of kinetic energy is the caller's work.
#include <cstdio>

#include "common/error.h"
#include "rigid/rigid_body.h"
#include "skin/skin.h"
#include "world/world.h"

namespace lfem {

void World::apply_impulse(BodyHandle handle, const double point[3], const double impulse[3]) {
    const Body& body = bodies_.get(handle);
    if (!body.is_dynamic() || !body.has_mesh())
        throw Error(Status::invalid_argument, "an impulse moves a deformable or rigid body with a mesh");
    const uint32_t n = body.ref.node_count();
    std::vector<double> v(3 * std::size_t(n));
    synchronized_velocities(body, v.data());
    const Vec3 p(point), J(impulse);
    if (body.is_rigid()) {
        const Vec3 c(body.state.global.center);
        const Vec3 dV = J / body.ref.total_mass;
        const Vec3 dw = rigid_world_inertia(rigid_view(body), body.state.global).ldlt().solve((p - c).cross(J));
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3 dv = dV + dw.cross(Vec3(&body.state.x[3 * i]) - c);
            for (int k = 0; k < 3; ++k) v[3 * i + k] += dv[k];
        }
        return set_velocities(handle, v.data());
    }
    // The tet around the point where the nodes are now, or the nearest within one mean boundary
    // edge (a point on the surface, a little proud of it), as a skin's vertex is bound.
    SkinTets tets;
    tets.X = body.state.x;
    tets.tets = body.ref.tets;
    tets.nodes_per_tet = body.ref.nodes_per_tet;
    Skin at;
    try {
        at = bind_skin(tets, point, 1, nullptr, 0, body.ref.surface.edge_length);
    } catch (const Error& e) {
        if (e.status() != Status::invalid_argument) throw;
        char where[160];
        std::snprintf(where, sizeof where, "point (%.6g, %.6g, %.6g) m lies farther than %.3g m (one edge) from the body",
                      point[0], point[1], point[2], body.ref.surface.edge_length);
        throw Error(Status::invalid_argument, where);
    }
    for (uint32_t k = 0; k < at.nodes_per_vertex; ++k) {
        const uint32_t i = at.nodes[k];
        if (body.node_mode[i] != NodeMode::free) continue;  // a held node's share goes to its support
        const Vec3 dv = at.weights[k] / body.ref.mass[i] * J;
        for (int d = 0; d < 3; ++d) v[3 * std::size_t(i) + d] += dv[d];
    }
    set_velocities(handle, v.data());
}

}  // namespace lfem
