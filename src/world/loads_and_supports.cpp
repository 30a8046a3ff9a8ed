// What the caller changes on a body between steps: velocities, supports (fixed and prescribed
// nodes), node forces, a kinematic body's velocity. Each change is all or nothing: the only
// allocation comes before anything is written.
#include <algorithm>

#include "rigid/global_rotation.h"
#include "rigid/rigid_body.h"
#include "world/world.h"

namespace lfem {

// Each change wakes the body first (wake() changes nothing if it fails).
void World::set_velocities(BodyHandle handle, const double* v) {
    Body& body = bodies_.get(handle);
    wake(handle.index);
    const uint32_t n = body.ref.node_count();
    if (body.is_rigid()) {
        // The rigid motion nearest the field: the one with its momentum and its angular
        // momentum about the centre of mass (V = P / M, L; the nodes' lumped masses).
        const RigidBodyView view = rigid_view(body);
        const double before = rigid_kinetic_energy(view, body.state.global);
        const Vec3 c(body.state.global.center);
        Vec3 P = Vec3::Zero();
        for (uint32_t i = 0; i < n; ++i) P += body.ref.mass[i] * Vec3(&v[3 * i]);
        const Vec3 L = angular_momentum(body.ref.mass.data(), body.state.x.data(), v, n, c);
        for (int k = 0; k < 3; ++k)
            body.state.global.velocity[k] = P[k] / body.ref.total_mass, body.state.global.angular_momentum[k] = L[k];
        const Vec3 omega = rigid_world_inertia(view, body.state.global).ldlt().solve(L);
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3 vi = Vec3(body.state.global.velocity) + omega.cross(Vec3(&body.state.x[3 * i]) - c);
            for (int k = 0; k < 3; ++k) body.state.v_half[3 * i + k] = vi[k];
        }
        body.state.h_last = 0.0;  // the frame holds synchronized velocities
        std::vector<double>().swap(body.state.contact_force);
        state_.counters.external_work += rigid_kinetic_energy(view, body.state.global) - before;
        return;
    }
    double before = 0.0, after = 0.0;
    if (body.is_deformable()) {
        std::vector<double> old(3 * std::size_t(n));
        synchronized_velocities(body, old.data());
        for (uint32_t i = 0; i < n; ++i) {
            const double m = body.ref.mass[i];
            for (int k = 0; k < 3; ++k) {
                before += 0.5 * m * old[3 * i + k] * old[3 * i + k];
                after += 0.5 * m * v[3 * i + k] * v[3 * i + k];
            }
        }
    }
    std::copy(v, v + 3 * std::size_t(n), body.state.v_half.begin());
    body.state.h_last = 0.0;  // v_half now holds synchronized velocities
    if (body.is_paper()) {
        const Vec3 c = center_of_mass(body.ref.mass.data(), body.state.x.data(), n);
        const Vec3 L = angular_momentum(body.ref.mass.data(), body.state.x.data(), v, n, c);
        for (int k = 0; k < 3; ++k) body.state.global.angular_momentum[k] = L[k];
    }
    state_.counters.external_work += after - before;
}

void World::set_node_mode(BodyHandle handle, const uint32_t* nodes, uint32_t count, NodeMode mode,
                          const double velocity[3]) {
    Body& body = bodies_.get(handle);
    wake(handle.index);
    if (mode == NodeMode::prescribed && body.prescribed_velocity.empty())
        body.prescribed_velocity.assign(3 * std::size_t(body.ref.node_count()), 0.0);
    for (uint32_t i = 0; i < count; ++i) {
        body.node_mode[nodes[i]] = mode;
        if (mode == NodeMode::prescribed)
            for (int k = 0; k < 3; ++k) body.prescribed_velocity[3 * std::size_t(nodes[i]) + k] = velocity[k];
    }
}

void World::set_node_forces(BodyHandle handle, const uint32_t* nodes, uint32_t count, const double* forces) {
    Body& body = bodies_.get(handle);
    wake(handle.index);
    if (body.node_force.empty()) body.node_force.assign(3 * std::size_t(body.ref.node_count()), 0.0);
    for (uint32_t i = 0; i < count; ++i) {
        const std::size_t at = 3 * std::size_t(nodes[i]);
        std::copy_n(&forces[3 * std::size_t(i)], 3, &body.node_force[at]);
        if (!body.call_force.empty())  // the next call's force at a point stays on top
            for (int k = 0; k < 3; ++k) body.applied_force[at + k] = body.call_force[at + k] + body.node_force[at + k];
    }
}

void World::clear_node_forces(BodyHandle handle) {
    Body& body = bodies_.get(handle);
    wake(handle.index);
    std::vector<double>().swap(body.node_force);  // unused features hold no memory
    body.refresh_loads();
}

void World::set_kinematic_velocity(BodyHandle handle, const double linear[3], const double angular[3]) {
    Body& body = bodies_.get(handle);
    wake_touching(handle.index);
    for (int k = 0; k < 3; ++k) {
        body.def.linear_velocity[k] = linear[k];
        body.def.angular_velocity[k] = angular[k];
    }
}

}  // namespace lfem
