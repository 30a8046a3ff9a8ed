// Global rotation of a body by Lagrangian rigid dynamics, eq. (2) of the paper:
// d/dt (I_n omega) = Q, with I_n the inertia tensor of the lumped masses about the centre of
// mass at step n and Q the torque of the external (and contact) forces. Used by the "paper"
// model as the floating frame of its elastic forces.
#pragma once

#include <cstdint>

#include "common/math.h"
#include "common/thread_pool.h"

namespace lfem {

// The paper's global motion of a body: the rotation of its floating frame ("paper" model) or
// of the rigid body, the angular momentum L of eq. (2) about the centre of mass, and the
// centre itself with its velocity over the last step (rigid bodies; kinematic bodies keep
// their pivot in `center`).
struct GlobalMotion {
    double rotation[4] = {1, 0, 0, 0};        // unit quaternion (w, x, y, z)
    double angular_momentum[3] = {0, 0, 0};   // kg m^2/s
    double center[3] = {0, 0, 0};             // m
    double velocity[3] = {0, 0, 0};           // m/s
};

// The sums over nodes below are taken per fixed block of nodes, then over the blocks in order:
// with a pool the blocks run in parallel, and the result is bitwise the same as without.

// Centre of mass of n lumped masses at positions x (3 per node).
Eigen::Vector3d center_of_mass(const double* mass, const double* x, uint32_t n,
                               ThreadPool* pool = nullptr);

// Inertia tensor about c: sum m_i (|r_i|^2 I - r_i r_i^T), r_i = x_i - c. Of the "paper"
// model's deformed nodes in eq. (2), and of a rigid body's reference nodes.
Eigen::Matrix3d inertia_tensor(const double* mass, const double* x, uint32_t n,
                               const Eigen::Vector3d& c, ThreadPool* pool = nullptr);

// Angular momentum about c of nodes moving with velocities v: sum m_i r_i x v_i.
Eigen::Vector3d angular_momentum(const double* mass, const double* x, const double* v,
                                 uint32_t n, const Eigen::Vector3d& c);

// One step of eq. (2): L <- L + h Q, omega = I_n^-1 L, q <- exp(h omega) q. Returns omega.
Eigen::Vector3d integrate_global_rotation(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& torque,
                                          double h, Eigen::Vector3d& L, Eigen::Quaterniond& q);

// One step of the "paper" model's floating frame: eq. (2) advances L and the rotation by the
// torque of the step (about c_start, the centre of mass at x^n, with the inertia of the nodes
// there), then the rotation is re-fitted to the nodes at x^{n+1}, which keeps it free of drift.
// Returns their difference (rad), an error indicator.
double update_global_rotation(const double* mass, const double* x_start, const double* x, const double* X,
                              uint32_t n, const Eigen::Vector3d& com, const Eigen::Vector3d& c_start,
                              const Eigen::Vector3d& torque, double h, GlobalMotion& motion,
                              ThreadPool* pool = nullptr);

// Re-fit the rotation to the deformed nodes: the polar rotation of
// A = sum m_i (x_i - c)(X_i - C)^T, warm-started from q (which it overwrites).
void fit_global_rotation(const double* mass, const double* x, const double* X, uint32_t n,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& C,
                         Eigen::Quaterniond& q, ThreadPool* pool = nullptr);

}  // namespace lfem
