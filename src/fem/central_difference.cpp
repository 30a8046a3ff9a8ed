#include "fem/central_difference.h"

namespace lfem {
namespace {

struct SupportSums {
    double work = 0;
    Vec3 torque = Vec3::Zero();
    SupportSums& operator+=(const SupportSums& o) {
        work += o.work, torque += o.torque;
        return *this;
    }
};

}  // namespace

void predict_positions(const NodeLoads& loads, double h_mid, double h, const double* torque_center,
                       Span<double> x, Span<double> v_half, StepStart& start, ThreadPool* pool) {
    const uint32_t n = loads.node_count();
    const double alpha = loads.damping;
    start.x.resize(x.size());
    start.v.resize(v_half.size());
    start.inv_mass.resize(n);
    const Vec3 c = torque_center ? Vec3(torque_center) : Vec3::Zero();
    // Divisions hoisted (one per node, not five): this loop and the commit's run over every node
    // of every sub-step.
    const double inv_h_mid = 1.0 / h_mid;
    SupportSums sums;
    blocked_sum(n, pool, sums, [&](uint32_t i, SupportSums& out) {
        for (int k = 0; k < 3; ++k) {
            start.x[3 * i + k] = x[3 * i + k];
            start.v[3 * i + k] = v_half[3 * i + k];
        }
        const double m = loads.mass[i];
        const double lhs = m * inv_h_mid + 0.5 * alpha * m, rhs = m * inv_h_mid - 0.5 * alpha * m;
        const double inv_lhs = 1.0 / lhs;
        const NodeMode mode = loads.mode[i];
        start.inv_mass[i] = mode == NodeMode::free ? h * inv_lhs : 0.0;  // dx = (h/lhs) lambda
        Vec3 reaction;
        for (int k = 0; k < 3; ++k) {
            const double R = loads.external_force(i, k) + loads.elastic[3 * i + k];
            double v_new;
            switch (mode) {
                case NodeMode::free: v_new = (rhs * v_half[3 * i + k] + R) * inv_lhs; break;
                case NodeMode::fixed: v_new = 0.0; break;
                default: v_new = loads.prescribed_velocity[3 * i + k]; break;
            }
            // The support force that makes a fixed or prescribed node follow its motion (zero
            // for free nodes): it does work and exerts torque like an external force.
            reaction[k] = lhs * v_new - rhs * v_half[3 * i + k] - R;
            v_half[3 * i + k] = v_new;
            x[3 * i + k] += h * v_new;
        }
        if (mode != NodeMode::free) {
            const Vec3 dx = Vec3(&x[3 * i]) - Vec3(&start.x[3 * i]);
            out.work += reaction.dot(dx);
            if (torque_center) out.torque += (Vec3(&start.x[3 * i]) - c).cross(reaction);
        }
    });
    start.support_work = sums.work;
    start.support_torque = sums.torque;
}

CommitSums commit_positions(const NodeLoads& loads, double h, const StepStart& start,
                            const double* torque_center, Span<const double> x, Span<double> v_half,
                            Span<double> contact_force, ThreadPool* pool) {
    const uint32_t n = loads.node_count();
    const double alpha = loads.damping;
    const bool touched = !contact_force.empty();
    const Vec3 c_old = torque_center ? Vec3(torque_center) : Vec3::Zero();
    const double inv_h = 1.0 / h;
    // Every entry of contact_force is written in the node loop below (zero where no contact
    // acts), so it is not cleared first: no serial pass over all nodes.
    CommitSums sums;
    sums.work = start.support_work;
    sums.torque = start.support_torque;
    blocked_sum(n, pool, sums, [&](uint32_t i, CommitSums& out) {
        const double m = loads.mass[i];
        const bool moved = touched && start.inv_mass[i] > 0.0;
        const double mhat = moved ? 1.0 / start.inv_mass[i] : 0.0;
        Vec3 f_ext, f_contact = Vec3::Zero(), dx;
        for (int k = 0; k < 3; ++k) {
            dx[k] = x[3 * i + k] - start.x[3 * i + k];
            f_ext[k] = loads.external_force(i, k);
            if (moved) {
                // The solve moved the node by (x - x*) = lambda / mhat: its contact force.
                const double correction = dx[k] - h * v_half[3 * i + k];
                f_contact[k] = correction * mhat;
                v_half[3 * i + k] = dx[k] * inv_h;
            }
            if (touched) contact_force[3 * i + k] = f_contact[k];
            const double v = v_half[3 * i + k];
            out.kinetic += 0.5 * m * v * v;
            out.damping += alpha * m * 0.5 * (v + start.v[3 * i + k]) * v * h;
        }
        out.work += f_ext.dot(dx);
        out.contact_work += f_contact.dot(dx);
        if (torque_center) out.torque += (Vec3(&start.x[3 * i]) - c_old).cross(f_ext + f_contact);
    });
    return sums;
}

}  // namespace lfem
