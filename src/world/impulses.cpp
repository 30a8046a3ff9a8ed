// A one-shot impulse at a world point (lfem_body_apply_impulse): the velocity change a hit gives,
// as engines apply it. A deformable body takes it on the nodes of the tet around the point, where
// the nodes are now, node k its share w_k J by the tet's shape functions at the point (the
// skin's weights: they sum to 1 and reproduce the point, so the body gains J as momentum and
// p x J as angular momentum about the origin, exactly); a rigid body as a whole, J / M and
// I^-1 (p - c) x J. The velocities change as lfem_body_set_velocities changes them: the change
// of kinetic energy is the caller's work.
#include <cmath>
#include <cstdio>

#include "common/error.h"
#include "rigid/rigid_body.h"
#include "world/point_binding.h"
#include "world/world.h"

namespace lfem {
namespace {

// The velocities an impulse leaves must be finite and carry a finite momentum: an impulse far
// from a rigid body (the fuzzer's was 9e61 m away) spins it beyond a double.
void require_finite_motion(const Body& body, const std::vector<double>& v) {
    Vec3 momentum = Vec3::Zero();
    for (uint32_t i = 0; i < body.ref.node_count(); ++i)
        for (int k = 0; k < 3; ++k) momentum[k] += body.ref.mass[i] * v[3 * std::size_t(i) + k];
    if (!std::isfinite(momentum.norm()))
        throw Error(Status::invalid_argument, "the impulse would move the body faster than a double holds "
                                              "(too large, or too far from the body)");
}

}  // namespace

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
        require_finite_motion(body, v);
        return set_velocities(handle, v.data());
    }
    const Skin at = bind_points(body, point, 1, body.ref.surface.edge_length, "point");
    for (uint32_t k = 0; k < at.nodes_per_vertex; ++k) {
        const uint32_t i = at.nodes[k];
        if (body.node_mode[i] != NodeMode::free) continue;  // a held node's share goes to its support
        const Vec3 dv = at.weights[k] / body.ref.mass[i] * J;
        for (int d = 0; d < 3; ++d) v[3 * std::size_t(i) + d] += dv[d];
    }
    require_finite_motion(body, v);
    set_velocities(handle, v.data());
}

}  // namespace lfem

namespace lfem {

// A force at a point for the next call (lfem_body_apply_force), as engines apply one: spread
// over the nodes of the tet around the point by the same weights as an impulse, so the nodes
// carry the force and its moment; the step applies node forces as it applies the caller's
// lasting ones (eq. 1 for a deformable body; a rigid body's sum and torque, eq. 2), and the
// call's end drops them (finish_call). On a rigid body the point may lie anywhere: its nearest
// tet's weights, extrapolated, still give the force's exact moment (its nodes move rigidly).
void World::apply_force(BodyHandle handle, const double point[3], const double force[3]) {
    Body& body = bodies_.get(handle);
    if (!body.is_dynamic() || !body.has_mesh())
        throw Error(Status::invalid_argument, "a force moves a deformable or rigid body with a mesh");
    const Skin at = bind_points(body, point, 1, body.is_rigid() ? HUGE_VAL : body.ref.surface.edge_length, "point");
    const std::size_t size = 3 * std::size_t(body.ref.node_count());
    // The candidates first (all the allocation), then the swap.
    std::vector<double> call = body.call_force;
    if (call.empty()) call.assign(size, 0.0);
    std::vector<double> applied(size);
    wake(handle.index);
    for (uint32_t k = 0; k < at.nodes_per_vertex; ++k)
        for (int d = 0; d < 3; ++d) call[3 * std::size_t(at.nodes[k]) + d] += at.weights[k] * force[d];
    body.call_force.swap(call);
    body.applied_force.swap(applied);
    body.refresh_loads();
}

// At the end of a call that succeeded, the forces meant for it are gone.
void World::drop_call_forces() {
    for (uint32_t i = 0; i < bodies_.slot_count(); ++i) {
        Body& b = bodies_.slot(i);
        if (b.call_force.empty()) continue;
        std::vector<double>().swap(b.call_force);
        std::vector<double>().swap(b.applied_force);
    }
}

}  // namespace lfem
