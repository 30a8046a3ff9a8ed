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

// The same Newton iteration for the element loop of the corotational model: A row-major, the
// warm start q (w, x, y, z) stored as float (16 bytes per tet), the rotation written to R
// (row-major). It stops once a step turns by less than 1e-4 rad: Newton converges
// quadratically, so the rotation left out is about (1e-4)^2 = 1e-8 rad, and a rotation error
// delta changes the symmetric strain only by delta times the strain (the skew part drops out),
// a relative stress error of 1e-8. One iteration per step in smooth motion.
void extract_rotation_fast(const double* A, float* q, double* R);

}  // namespace lfem
