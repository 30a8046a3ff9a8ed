// The explicit time integration of a body's nodes: central differences (eq. 3) on the
// semi-discrete equations of motion with lumped mass and mass-proportional damping (eq. 1),
//   M a^n + C v^n + f_int(x^n) = F^n,   C = alpha M,
// written with mid-step velocities v^{n+1/2} = (x^{n+1} - x^n)/h, which also handles a change
// of step size:
//   (m/h_mid + c/2) v^{n+1/2} = (m/h_mid - c/2) v^{n-1/2} + R^n,  h_mid = (h_prev + h)/2,
// R^n = gravity + node forces + elastic forces at x^n. With constant h this is exactly
// x* = (R + 2m/h^2 x^n - (m/h^2 - c/2h) x^{n-1}) / (m/h^2 + c/2h). After a reset (h_prev = 0,
// v^{n-1/2} holds the synchronized velocity) it is the velocity-Verlet start, exact for a
// constant force. The predictor gives x*; contact corrects it to x^{n+1}; the commit turns the
// correction into velocities and contact forces.
#pragma once

#include <cstdint>
#include <vector>

#include "common/math.h"
#include "common/span.h"
#include "common/thread_pool.h"

namespace lfem {

// How a node moves: by the equations of motion, held in place, or at a prescribed velocity.
enum class NodeMode : uint8_t { free = 0, fixed = 1, prescribed = 2 };

// The time between the mid-points of the last step and this one, h_mid = (h_prev + h)/2; h/2
// after a reset (no last step: the velocity-Verlet start). The interval over which the step's
// forces change the mid-step velocities (eq. 3), for deformable and rigid bodies alike; the
// world computes it once per body and sub-step (world/pipeline.h) for everything that needs it.
inline double mid_step(double h_last, double h) { return h_last > 0.0 ? 0.5 * (h_last + h) : 0.5 * h; }

// What the integration reads of one body's nodes (fixed during the step).
struct NodeLoads {
    Span<const double> mass;                 // per node: lumped mass (kg)
    Span<const NodeMode> mode;               // per node
    Span<const double> prescribed_velocity;  // 3 per node (m/s); empty when none is prescribed
    Span<const double> node_force;           // 3 per node (N); empty when none is set
    Span<const double> elastic;              // 3 per node: elastic force at x^n (N)
    double damping = 0;                      // alpha (1/s)
    const double* gravity = nullptr;         // m/s^2

    uint32_t node_count() const { return uint32_t(mass.size()); }
    // Gravity plus the node force on node i along axis k (N).
    double external_force(uint32_t i, int k) const {
        return mass[i] * gravity[k] + (node_force.empty() ? 0.0 : node_force[3 * std::size_t(i) + k]);
    }
};

// The step's start as the predictor leaves it, for the contact solve and the commit.
struct StepStart {
    std::vector<double> x;         // 3 per node: x^n
    std::vector<double> v;         // 3 per node: v^{n-1/2}
    std::vector<double> inv_mass;  // per node: 1/mhat = h / (m/h_mid + c/2), 0 for a node
                                   // that does not move freely (m per N: dx = lambda / mhat)
    double support_work = 0;       // J: the supports' work over the step (fixed, prescribed)
    Vec3 support_torque = Vec3::Zero();  // N m: their torque about torque_center ("paper")
};

// Predictor: x* = x^n + h v^{n+1/2} with v^{n+1/2} from eq. (3) over h_mid (mid_step), fixed
// nodes held, prescribed ones moved at their velocity; records the step's start in `start`. With torque_center (the "paper" model's centre of mass
// at x^n, nullable) the supports' torque about it as well. x, v_half: 3 per node.
void predict_positions(const NodeLoads& loads, double h_mid, double h, const double* torque_center,
                       Span<double> x, Span<double> v_half, StepStart& start, ThreadPool* pool);

// What the commit adds up over a body's nodes.
struct CommitSums {
    double kinetic = 0;       // J, of the new mid-step velocities
    double work = 0;          // J, of gravity, node forces and supports over the step
    double contact_work = 0;  // J, of the contact forces on the moving nodes
    double damping = 0;       // J, removed by damping over the step
    Vec3 torque = Vec3::Zero();  // N m, of external and contact forces about torque_center

    CommitSums& operator+=(const CommitSums& o) {
        kinetic += o.kinetic, work += o.work, contact_work += o.contact_work, damping += o.damping;
        torque += o.torque;
        return *this;
    }
};

// Commit: the solve moved each free node from x* to x^{n+1} by lambda / mhat; that move is its
// contact force (written to contact_force, 3 per node, when not empty: the body was touched)
// and its new velocity (x^{n+1} - x^n)/h. Adds up the energy bookkeeping and, with
// torque_center, the torque of the step that eq. (2) needs.
CommitSums commit_positions(const NodeLoads& loads, double h, const StepStart& start,
                            const double* torque_center, Span<const double> x, Span<double> v_half,
                            Span<double> contact_force, ThreadPool* pool);

}  // namespace lfem
