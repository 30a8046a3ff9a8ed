// The rotational part R of a 3x3 matrix A (its polar decomposition A = R S): the rotation that
// maximises tr(R^T A). Found iteratively from a warm start (the previous step's rotation), in
// the spirit of Mueller, Bender, Chentanez & Macklin, "A robust method to extract the
// rotational part of deformations" (MIG 2016), but with a Newton step on the rotation vector,
// which converges quadratically: one or two iterations per time step in practice.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lfem {

// Improves q in place so that q.toRotationMatrix() is the rotation closest to A. Returns the
// number of iterations used (at most max_iterations).
int extract_rotation(const Eigen::Matrix3d& A, Eigen::Quaterniond& q, int max_iterations = 50);

}  // namespace lfem
