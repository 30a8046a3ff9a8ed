// The step pipeline (DESIGN.md section 1): per sub-step, for every moving body,
//   predictor (central difference, eqs. 1 and 3), [contact: detect and solve multipliers],
//   global rotation (eq. 2, "paper" model), internal forces at the new positions (commit).
// A call is split into equal sub-steps; if the state blows up the world is restored from a
// snapshot taken at the start of the call.
#include <cmath>
#include <cstdio>
#include <string>

#include "common/error.h"
#include "fem/internal_forces.h"
#include "fem/material.h"
#include "fem/tet_element.h"
#include "rigid/global_rotation.h"
#include "world/world.h"

namespace lfem {
namespace {

std::string seconds(double s) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g s", s);
    return buf;
}

// What one body's sub-step adds to the world's energy bookkeeping.
struct SubstepTally {
    double kinetic = 0;   // J, of the new mid-step velocities
    double work = 0;      // J, of gravity, node forces and prescribed nodes over the step
    double dissipated = 0;// J, by damping over the step
    double drift = 0;     // rad, eq. (2) rotation against the re-fitted one
};

Eigen::Quaterniond load_q(const double* q) { return {q[0], q[1], q[2], q[3]}; }

// Central difference predictor (eqs. 1 and 3) written with the mid-step velocity
// v^{n+1/2} = (x^{n+1} - x^n)/h, which also handles a change of step size:
//   (m/h_mid + c/2) v^{n+1/2} = (m/h_mid - c/2) v^{n-1/2} + R^n,  h_mid = (h_prev + h)/2,
// R^n = gravity + node forces + elastic forces at x^n, c = alpha m. With constant h this is
// exactly x^{n+1} = (R + 2m/h^2 x^n - (m/h^2 - c/2h) x^{n-1}) / (m/h^2 + c/2h). After a reset
// (h_prev = 0, v^{n-1/2} holds the synchronized velocity) it is the velocity-Verlet start,
// exact for a constant force.
void advance_deformable(Body& body, const double gravity[3], double h, SubstepTally& tally) {
    BodyState& s = body.state;
    const BodyReference& ref = body.ref;
    const uint32_t n = ref.node_count();
    const double h_mid = s.h_last > 0.0 ? 0.5 * (s.h_last + h) : 0.5 * h;
    const double alpha = body.def.damping;
    const bool paper = body.def.model == LFEM_MODEL_PAPER;
    const bool has_forces = !body.node_force.empty();

    Vec3 c_old = Vec3::Zero();
    Eigen::Matrix3d inertia;
    if (paper) {
        c_old = center_of_mass(ref.mass.data(), s.x.data(), n);
        inertia = inertia_tensor(ref.mass.data(), s.x.data(), n, c_old);
    }
    Vec3 torque = Vec3::Zero();

    for (uint32_t i = 0; i < n; ++i) {
        const double m = ref.mass[i];
        const double lhs = m / h_mid + 0.5 * alpha * m, rhs = m / h_mid - 0.5 * alpha * m;
        double external[3], reaction[3], dx[3];
        double* x = &s.x[3 * i];
        double* v = &s.v_half[3 * i];
        for (int k = 0; k < 3; ++k) {
            external[k] = m * gravity[k] + (has_forces ? body.node_force[3 * i + k] : 0.0);
            const double R = external[k] + s.elastic[3 * i + k];
            double v_new;
            switch (body.node_mode[i]) {
                case NodeMode::free: v_new = (rhs * v[k] + R) / lhs; break;
                case NodeMode::fixed: v_new = 0.0; break;
                default: v_new = body.prescribed_velocity[3 * i + k]; break;
            }
            // The support force that makes a fixed or prescribed node follow its motion
            // (zero for free nodes): it does work and exerts torque like an external force.
            reaction[k] = lhs * v_new - rhs * v[k] - R;
            dx[k] = h * v_new;
            tally.kinetic += 0.5 * m * v_new * v_new;
            tally.work += (external[k] + reaction[k]) * dx[k];
            tally.dissipated += alpha * m * 0.5 * (v_new + v[k]) * v_new * h;
            v[k] = v_new;
            x[k] += dx[k];
        }
        if (paper) {
            const Vec3 r(x[0] - dx[0] - c_old[0], x[1] - dx[1] - c_old[1], x[2] - dx[2] - c_old[2]);
            torque += r.cross(Vec3(external[0] + reaction[0], external[1] + reaction[1],
                                   external[2] + reaction[2]));
        }
    }

    if (paper) {
        // Eq. (2) predicts the frame's rotation; re-fitting it to the nodes keeps it free of
        // drift. Their difference is reported as an error indicator.
        Vec3 L(s.angular_momentum);
        Eigen::Quaterniond q = load_q(s.rotation);
        integrate_global_rotation(inertia, torque, h, L, q);
        const Eigen::Quaterniond predicted = q;
        const Vec3 c_new = center_of_mass(ref.mass.data(), s.x.data(), n);
        fit_global_rotation(ref.mass.data(), s.x.data(), ref.X.data(), n, c_new, Vec3(ref.com), q);
        tally.drift = std::max(tally.drift, predicted.angularDistance(q));
        s.rotation[0] = q.w(), s.rotation[1] = q.x(), s.rotation[2] = q.y(), s.rotation[3] = q.z();
        for (int k = 0; k < 3; ++k) s.angular_momentum[k] = L[k];
    }
    s.h_last = h;
    compute_elastic_forces(body, s);
}

// Kinematic bodies move rigidly: centre by v h, nodes rotated by omega h about it.
void advance_kinematic(Body& body, double h) {
    BodyState& s = body.state;
    const Vec3 lin(body.def.linear_velocity), ang(body.def.angular_velocity);
    const Vec3 c_old(s.center);
    const Vec3 c_new = c_old + h * lin;
    const double angle = h * ang.norm();
    const Eigen::Matrix3d Rot =
        angle > 0.0 ? Eigen::AngleAxisd(angle, ang.normalized()).toRotationMatrix()
                    : Eigen::Matrix3d::Identity();
    for (uint32_t i = 0; i < body.ref.node_count(); ++i) {
        const Vec3 x = c_new + Rot * (Vec3(&s.x[3 * i]) - c_old);
        for (int k = 0; k < 3; ++k) s.x[3 * i + k] = x[k];
    }
    for (int k = 0; k < 3; ++k) s.center[k] = c_new[k];
}

}  // namespace

void World::substep(double h, double& kinetic, double& strain, double& work) {
    SubstepTally tally;
    for (Slot& slot : slots_) {
        Body& b = slot.body;
        if (b.generation == 0 || !b.has_mesh()) continue;
        if (b.is_deformable()) {
            advance_deformable(b, def_.gravity, h, tally);
            strain += b.state.strain_energy;
        } else if (b.def.type == LFEM_BODY_KINEMATIC) {
            advance_kinematic(b, h);
        }
        // Static bodies: nothing to do.
    }
    kinetic = tally.kinetic;
    work += tally.work;
    counters_.external_work += tally.work;
    counters_.dissipated_energy += tally.dissipated;
    counters_.rotation_drift = tally.drift;
    counters_.time += h;
    counters_.steps += 1;
    counters_.step_size = h;
}

void World::step(double dt) {
    const double limit = stable_step();
    double h_allowed;
    if (def_.time_step > 0.0) {
        if (def_.time_step > limit && !def_.allow_unstable_step)
            throw Error(LFEM_INVALID_ARGUMENT,
                        "fixed time_step " + seconds(def_.time_step) +
                            " exceeds the stable limit " + seconds(limit) +
                            " of central differences (2/omega_max); use a step below it, 0 "
                            "for automatic, or set allow_unstable_step");
        h_allowed = def_.time_step;
    } else {
        h_allowed = def_.step_safety * limit;
    }
    double count = std::isfinite(h_allowed) ? std::ceil(dt / h_allowed * (1.0 - 1e-12)) : 1.0;
    if (count < 1.0) count = 1.0;
    if (count > double(def_.max_substeps))
        throw Error(LFEM_INVALID_ARGUMENT,
                    "dt " + seconds(dt) + " needs " + std::to_string(uint64_t(count)) +
                        " sub-steps of at most " + seconds(h_allowed) + ", more than max_substeps " +
                        std::to_string(def_.max_substeps));
    const uint32_t substeps = uint32_t(count);
    const double h = dt / substeps;

    // Snapshot for rollback: every body's state and the world's counters.
    std::vector<BodyState> saved;
    saved.reserve(slots_.size());
    for (const Slot& s : slots_) saved.push_back(s.body.state);
    const WorldCounters saved_counters = counters_;

    // Energy of the moving bodies at the start, for the blow-up test below.
    double start_energy = 0.0, scale = 0.0;
    for (const Slot& s : slots_) {
        const Body& b = s.body;
        if (b.generation == 0 || !b.is_deformable() || !b.has_mesh()) continue;
        start_energy += b.state.strain_energy;
        for (uint32_t i = 0; i < b.ref.node_count(); ++i)
            for (int k = 0; k < 3; ++k)
                start_energy += 0.5 * b.ref.mass[i] * b.state.v_half[3 * i + k] * b.state.v_half[3 * i + k];
        // m c_d^2 * 1e-12: the energy of a uniform strain of 1e-6, a floor below which energy
        // changes are too small to call a blow-up.
        const double cd = dilatational_wave_speed(b.lame, b.def.density);
        scale += 1e-12 * b.ref.total_mass * cd * cd;
    }

    double work = 0.0;
    for (uint32_t k = 0; k < substeps; ++k) {
        double kinetic = 0.0, strain = 0.0;
        substep(h, kinetic, strain, work);
        // A stable explicit step cannot create energy: kinetic + strain - work stays near the
        // starting energy (minus damping). An unstable one multiplies it every step (by about
        // 47 per step at 1.5x the limit), so doubling is a clear and early sign.
        const double balance = kinetic + strain - work;
        if (!std::isfinite(balance) || balance > 2.0 * start_energy + scale) {
            for (std::size_t i = 0; i < slots_.size(); ++i) slots_[i].body.state = std::move(saved[i]);
            counters_ = saved_counters;
            throw Error(LFEM_UNSTABLE,
                        "the state blew up at sub-step " + std::to_string(k + 1) + " of " +
                            std::to_string(substeps) + " (step " + seconds(h) +
                            ", stable limit " + seconds(limit) +
                            "); the world was rolled back to its state before this call");
        }
    }
    counters_.substeps_last_call = substeps;
}

}  // namespace lfem
