// The rotational part R of a 3x3 matrix A (its polar decomposition A = R S): the rotation that
// maximises tr(R^T A). Found iteratively from a warm start (the previous step's rotation), in
// the spirit of Mueller, Bender, Chentanez & Macklin, "A robust method to extract the
// rotational part of deformations" (MIG 2016), but with a Newton step on the rotation vector,
// which converges quadratically: one or two iterations per time step in practice.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lfem {

#if defined(__GNUC__)
#define LFEM_POLAR_INLINE __attribute__((always_inline)) inline
#else
#define LFEM_POLAR_INLINE inline
#endif

// The rotation matrix (row-major) of the unit quaternion (w, x, y, z).
LFEM_POLAR_INLINE void rotation_matrix(double w, double x, double y, double z, double* R) {
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

// One Newton step of the polar rotation of A (row-major) from the unit quaternion (w, x, y, z),
// the one step every extraction below takes. With M = R^T A, turning R by a small body-frame
// rotation vector d changes f = tr(R^T A) by g.d + d^T (sym(M) - tr(M) I) d / 2, g the axial
// vector of the skew part of M; the maximum is where M is symmetric (R^T A = S). Newton:
// d = H^-1 g, H = tr(M) I - sym(M), positive definite near the answer (A = R S, S positive).
// Where H is not (far from the answer, an inverted element): with gradient_fallback the
// gradient step g / |tr M| of Mueller et al., which always increases f; without it the
// quaternion is left as it is and -1 returned. The turn: q (1, d/2) renormalised, which agrees
// with exp(d/2) to O(|d|^3) (the next step absorbs it) and needs no trigonometry. Returns
// |d|^2, or 0 when there is nothing to turn (q unchanged).
LFEM_POLAR_INLINE double polar_newton_step(const double* A, double& w, double& x, double& y,
                                           double& z, bool gradient_fallback) {
    double R[9], M[9];
    rotation_matrix(w, x, y, z, R);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M[3 * i + j] = R[i] * A[j] + R[3 + i] * A[3 + j] + R[6 + i] * A[6 + j];
    const double g0 = M[7] - M[5], g1 = M[2] - M[6], g2 = M[3] - M[1];
    const double tr = M[0] + M[4] + M[8];
    const double h00 = tr - M[0], h11 = tr - M[4], h22 = tr - M[8];
    const double h01 = -0.5 * (M[1] + M[3]), h02 = -0.5 * (M[2] + M[6]), h12 = -0.5 * (M[5] + M[7]);
    // Cofactors of the symmetric H; Sylvester's criterion tells whether it is positive.
    const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22, c02 = h01 * h12 - h02 * h11;
    const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12, c22 = h00 * h11 - h01 * h01;
    const double det = h00 * c00 + h01 * c01 + h02 * c02;
    double d0, d1, d2;
    if (h00 > 0.0 && c22 > 0.0 && det > 0.0) {
        const double inv = 1.0 / det;
        d0 = (c00 * g0 + c01 * g1 + c02 * g2) * inv;
        d1 = (c01 * g0 + c11 * g1 + c12 * g2) * inv;
        d2 = (c02 * g0 + c12 * g1 + c22 * g2) * inv;
    } else if (gradient_fallback) {
        const double s = 1.0 / (std::fabs(tr) + 1e-300);
        d0 = g0 * s, d1 = g1 * s, d2 = g2 * s;
    } else {
        return -1.0;
    }
    const double angle2 = d0 * d0 + d1 * d1 + d2 * d2;
    if (!(angle2 > 0.0)) return 0.0;
    const double a = 0.5 * d0, b = 0.5 * d1, c = 0.5 * d2;
    const double nw = w - x * a - y * b - z * c;
    const double nx = x + w * a + y * c - z * b;
    const double ny = y + w * b + z * a - x * c;
    const double nz = z + w * c + x * b - y * a;
    const double norm = 1.0 / std::sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
    w = nw * norm, x = nx * norm, y = ny * norm, z = nz * norm;
    return angle2;
}

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
