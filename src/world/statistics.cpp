// What a world reports between steps: the stable limit, the bodies' synchronized velocities,
// momenta and energies (the run-time error indicators of the energy balance).
#include <algorithm>
#include <cmath>
#include <limits>

#include "world/world.h"

namespace lfem {
// A rigid body's synchronized velocity, extrapolated over half its last step (h_last; none
// after a reset). A body pressed by a contact or held by an attachment reports its last step's
// velocity, as a deformable body's pressed node does: the half-step extrapolation knows gravity
// but not the support, and a body at rest on a floor would report -g h/2. Returns its angular
// momentum about its centre.
Vec3 World::rigid_velocity(const Body& b, Vec3& V, Vec3& omega) const {
    const BodyState& s = b.state;
    const double h = s.contact_force.empty() ? s.h_last : 0.0;
    RigidBodyView view = rigid_view(b);
    view.node_force = b.node_force;  // the lasting ones: a force for the next call acts from its start
    return rigid_synchronized_velocity(view, s.global, s.x, def_.gravity, h, V, omega);
}

double World::stable_step() const {
    double h = std::numeric_limits<double>::infinity();
    bodies_.for_each([&](const Body& b, uint32_t) {
        if (!b.is_deformable() || !b.has_mesh() || b.state.asleep) return;
        // Neo-Hookean stiffness grows with deformation, and every model's below J = 0.2 (the
        // volume barrier): the limit at the current nodes. The reference limit already carries
        // the 2 % margin on omega^2 of its Lanczos estimate; only stiffening beyond it shortens
        // the step. The estimate comes with the elastic forces at x (internal_forces.cpp).
        const double stiffening = b.state.stiffening / 1.02;
        h = std::min(h, b.ref.stable_step / std::sqrt(std::max(stiffening, 1.0)));
    });
    return h;
}

double World::self_contact_step() const {
    double h = std::numeric_limits<double>::infinity();
    bodies_.for_each([&](const Body& b, uint32_t) {
        if (!b.def.self_contact || !b.is_deformable() || !b.has_mesh() || b.state.asleep) return;
        const std::vector<uint32_t>& nodes = b.ref.surface.nodes;
        const double* v = b.state.v_half.data();
        Vec3 mean = Vec3::Zero();
        for (uint32_t i : nodes) mean += Vec3(v + 3 * std::size_t(i));
        mean /= double(std::max<std::size_t>(nodes.size(), 1));
        double fastest = 0.0;
        for (uint32_t i : nodes) fastest = std::max(fastest, (Vec3(v + 3 * std::size_t(i)) - mean).norm());
        // Two parts of the body close at up to twice the fastest's speed about the mean.
        if (fastest > 0.0) h = std::min(h, kSelfContactMotion * b.ref.surface.edge_length / (2.0 * fastest));
    });
    return h;
}

void World::synchronized_velocities(const Body& body, double* out) const {
    const BodyState& s = body.state;
    const uint32_t n = body.ref.node_count();
    if (body.is_rigid()) {
        Vec3 V, omega;
        rigid_velocity(body, V, omega);
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3 v = V + omega.cross(Vec3(&s.x[3 * i]) - Vec3(s.global.center));
            for (int k = 0; k < 3; ++k) out[3 * i + k] = v[k];
        }
        return;
    }
    if (!body.is_deformable()) {
        // Static: at rest. Kinematic: rigid motion about the moving centre.
        const Vec3 lin(body.def.linear_velocity), ang(body.def.angular_velocity);
        for (uint32_t i = 0; i < n; ++i) {
            Vec3 v = Vec3::Zero();
            if (body.is_kinematic()) v = lin + ang.cross(Vec3(&s.x[3 * i]) - Vec3(s.global.center));
            for (int k = 0; k < 3; ++k) out[3 * i + k] = v[k];
        }
        return;
    }
    const double h = s.h_last;
    const double* g = def_.gravity;
    const auto in_contact = [&](uint32_t i) {
        return !s.contact_force.empty() && (s.contact_force[3 * i] != 0.0 || s.contact_force[3 * i + 1] != 0.0 ||
                                            s.contact_force[3 * i + 2] != 0.0);
    };
    for (uint32_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            double v = s.v_half[3 * i + k];
            switch (body.node_mode[i]) {
                case NodeMode::fixed: v = 0.0; break;
                case NodeMode::prescribed: v = body.prescribed_velocity[3 * i + k]; break;
                case NodeMode::free:
                    // A node pressed by a contact reports its last step's velocity: the
                    // half-step extrapolation would divide the step-to-step variation of the
                    // contact force (solver tolerance) by h and show jitter that is not there.
                    if (h > 0.0 && !(in_contact(i))) {
                        // v^n = v^{n-1/2} + h/2 a^n with m a^n = R^n - c v^n (central difference)
                        const double m = body.ref.mass[i];
                        double R = m * g[k] + s.elastic[3 * i + k];
                        // the lasting node forces: one applied for the next call acts from its start
                        if (!body.node_force.empty()) R += body.node_force[3 * i + k];
                        v = (2.0 * m / h * v + R) / (2.0 * m / h + body.def.damping * m);
                    }
                    break;
            }
            out[3 * i + k] = v;
        }
    }
}

void World::body_momentum(const Body& b, Vec3& P, Vec3& L) const {
    P = Vec3::Zero(), L = Vec3::Zero();
    if (b.is_rigid() && b.has_mesh()) {
        Vec3 V, omega;
        const Vec3 L_centre = rigid_velocity(b, V, omega);
        P = b.ref.total_mass * V;
        L = Vec3(b.state.global.center).cross(P) + L_centre;
    } else if (b.is_deformable() && b.has_mesh()) {
        std::vector<double> v(b.state.v_half.size());
        synchronized_velocities(b, v.data());
        for (uint32_t i = 0; i < b.ref.node_count(); ++i) {
            const Vec3 vi(&v[3 * i]);
            P += b.ref.mass[i] * vi;
            L += b.ref.mass[i] * Vec3(&b.state.x[3 * i]).cross(vi);
        }
    }
}

void World::add_kinetic_energy(const Body& b, double& sum) const {
    if (!b.is_dynamic() || !b.has_mesh()) return;
    if (b.is_rigid()) {
        sum += rigid_kinetic_energy(rigid_view(b), b.state.global);
        return;
    }
    std::vector<double> v(b.state.v_half.size());
    synchronized_velocities(b, v.data());
    for (uint32_t i = 0; i < b.ref.node_count(); ++i) sum += 0.5 * b.ref.mass[i] * Vec3(&v[3 * i]).squaredNorm();
}

WorldTotals World::totals() const {
    WorldTotals t;
    bodies_.for_each([&](const Body& b, uint32_t) {
        t.added_mass += b.ref.added_mass;
        if (!b.is_dynamic() || !b.has_mesh()) return;
        Vec3 P, L;
        add_kinetic_energy(b, t.kinetic_energy);  // node by node into the total
        body_momentum(b, P, L);
        t.linear_momentum += P, t.angular_momentum += L;
        if (b.is_rigid()) return;
        t.strain_energy += b.state.strain_energy;
        t.inverted_tets += b.state.inverted_tets;
        t.min_jacobian = std::min(t.min_jacobian, b.state.min_jacobian);
    });
    const WorldCounters& c = state_.counters;
    t.energy_error = t.kinetic_energy + t.strain_energy + c.dissipated_energy - c.external_work - c.initial_energy;
    return t;
}

}  // namespace lfem
