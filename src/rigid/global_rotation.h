// Global rotation of a body by Lagrangian rigid dynamics, eq. (2) of the paper:
// d/dt (I_n omega) = Q, with I_n the inertia tensor of the lumped masses about the centre of
// mass at step n and Q the torque of the external (and contact) forces. Used by the "paper"
// model as the floating frame of its elastic forces.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

#include "common/thread_pool.h"

namespace lfem {

// The sums over nodes below are taken per fixed block of nodes, then over the blocks in order:
// with a pool the blocks run in parallel, and the result is bitwise the same as without.

// Centre of mass of n lumped masses at positions x (3 per node).
Eigen::Vector3d center_of_mass(const double* mass, const double* x, uint32_t n,
                               ThreadPool* pool = nullptr);

// Inertia tensor about c: sum m_i (|r_i|^2 I - r_i r_i^T), r_i = x_i - c.
Eigen::Matrix3d inertia_tensor(const double* mass, const double* x, uint32_t n,
                               const Eigen::Vector3d& c, ThreadPool* pool = nullptr);

// Angular momentum about c of nodes moving with velocities v: sum m_i r_i x v_i.
Eigen::Vector3d angular_momentum(const double* mass, const double* x, const double* v,
                                 uint32_t n, const Eigen::Vector3d& c);

// One step of eq. (2): L <- L + h Q, omega = I_n^-1 L, q <- exp(h omega) q. Returns omega.
Eigen::Vector3d integrate_global_rotation(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& torque,
                                          double h, Eigen::Vector3d& L, Eigen::Quaterniond& q);

// Re-fit the rotation to the deformed nodes: the polar rotation of
// A = sum m_i (x_i - c)(X_i - C)^T, warm-started from q (which it overwrites).
void fit_global_rotation(const double* mass, const double* x, const double* X, uint32_t n,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& C,
                         Eigen::Quaterniond& q, ThreadPool* pool = nullptr);

}  // namespace lfem
