#include "fem/polar_rotation.h"

#include <cmath>

namespace lfem {

int extract_rotation(const Eigen::Matrix3d& A, Eigen::Quaterniond& quat, int max_iterations) {
    // With M = R^T A, turning R by a small body-frame rotation vector d changes
    // f = tr(R^T A) by g.d + d^T (sym(M) - tr(M) I) d / 2, with g the axial vector of the skew
    // part of M. The maximum is where M is symmetric (R^T A = S). Newton: d = H^-1 g with
    // H = tr(M) I - sym(M), positive definite near the answer (A = R S with S positive).
    // Written out by hand: this runs once or twice per tet per step in the corotational model.
    double w = quat.w(), x = quat.x(), y = quat.y(), z = quat.z();
    for (int it = 0; it < max_iterations; ++it) {
        const double R[3][3] = {
            {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
        double M[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                M[i][j] = R[0][i] * A(0, j) + R[1][i] * A(1, j) + R[2][i] * A(2, j);
        const double g[3] = {M[2][1] - M[1][2], M[0][2] - M[2][0], M[1][0] - M[0][1]};
        const double tr = M[0][0] + M[1][1] + M[2][2];
        const double h00 = tr - M[0][0], h11 = tr - M[1][1], h22 = tr - M[2][2];
        const double h01 = -0.5 * (M[0][1] + M[1][0]), h02 = -0.5 * (M[0][2] + M[2][0]),
                     h12 = -0.5 * (M[1][2] + M[2][1]);
        // Cofactors of the symmetric H; Sylvester's criterion tells whether it is positive.
        const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22,
                     c02 = h01 * h12 - h02 * h11;
        const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12,
                     c22 = h00 * h11 - h01 * h01;
        const double det = h00 * c00 + h01 * c01 + h02 * c02;
        double d[3];
        if (h00 > 0.0 && c22 > 0.0 && det > 0.0) {
            const double inv = 1.0 / det;
            d[0] = (c00 * g[0] + c01 * g[1] + c02 * g[2]) * inv;
            d[1] = (c01 * g[0] + c11 * g[1] + c12 * g[2]) * inv;
            d[2] = (c02 * g[0] + c12 * g[1] + c22 * g[2]) * inv;
        } else {
            // Far from the answer (e.g. an inverted element): a gradient step scaled as in
            // Mueller et al., which always increases f.
            const double s = 1.0 / (std::fabs(tr) + 1e-300);
            d[0] = g[0] * s, d[1] = g[1] * s, d[2] = g[2] * s;
        }
        const double angle2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (!(angle2 > 0.0)) {
            quat = Eigen::Quaterniond(w, x, y, z);
            return it;
        }
        // Turn by d: q (1, d/2) renormalised agrees with exp(d/2) to O(|d|^3), which the next
        // Newton step absorbs; it needs no trigonometry.
        const double a = 0.5 * d[0], b = 0.5 * d[1], c = 0.5 * d[2];
        const double nw = w - x * a - y * b - z * c;
        const double nx = x + w * a + y * c - z * b;
        const double ny = y + w * b + z * a - x * c;
        const double nz = z + w * c + x * b - y * a;
        const double norm = 1.0 / std::sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
        w = nw * norm, x = nx * norm, y = ny * norm, z = nz * norm;
        // Quadratic convergence: after a step of 1e-8 rad the error is ~1e-16, round-off.
        if (angle2 < 1e-16) {
            quat = Eigen::Quaterniond(w, x, y, z);
            return it + 1;
        }
    }
    quat = Eigen::Quaterniond(w, x, y, z);
    return max_iterations;
}

namespace {
inline void rotation_matrix(double w, double x, double y, double z, double* R) {
    R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}
}  // namespace

void extract_rotation_fast(const double* A, float* q, double* R) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double norm = 1.0 / std::sqrt(w * w + x * x + y * y + z * z);  // float rounding
    w *= norm, x *= norm, y *= norm, z *= norm;
    rotation_matrix(w, x, y, z, R);
    for (int it = 0; it < 50; ++it) {
        // Same Newton step as extract_rotation above, with M = R^T A.
        double M[9];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                M[3 * i + j] = R[i] * A[j] + R[3 + i] * A[3 + j] + R[6 + i] * A[6 + j];
        const double g0 = M[7] - M[5], g1 = M[2] - M[6], g2 = M[3] - M[1];
        const double tr = M[0] + M[4] + M[8];
        const double h00 = tr - M[0], h11 = tr - M[4], h22 = tr - M[8];
        const double h01 = -0.5 * (M[1] + M[3]), h02 = -0.5 * (M[2] + M[6]),
                     h12 = -0.5 * (M[5] + M[7]);
        const double c00 = h11 * h22 - h12 * h12, c01 = h02 * h12 - h01 * h22,
                     c02 = h01 * h12 - h02 * h11;
        const double c11 = h00 * h22 - h02 * h02, c12 = h01 * h02 - h00 * h12,
                     c22 = h00 * h11 - h01 * h01;
        const double det = h00 * c00 + h01 * c01 + h02 * c02;
        double d0, d1, d2;
        if (h00 > 0.0 && c22 > 0.0 && det > 0.0) {
            const double inv = 1.0 / det;
            d0 = (c00 * g0 + c01 * g1 + c02 * g2) * inv;
            d1 = (c01 * g0 + c11 * g1 + c12 * g2) * inv;
            d2 = (c02 * g0 + c12 * g1 + c22 * g2) * inv;
        } else {
            const double s = 1.0 / (std::fabs(tr) + 1e-300);
            d0 = g0 * s, d1 = g1 * s, d2 = g2 * s;
        }
        const double angle2 = d0 * d0 + d1 * d1 + d2 * d2;
        if (!(angle2 > 0.0)) break;
        const double a = 0.5 * d0, b = 0.5 * d1, c = 0.5 * d2;
        const double nw = w - x * a - y * b - z * c;
        const double nx = x + w * a + y * c - z * b;
        const double ny = y + w * b + z * a - x * c;
        const double nz = z + w * c + x * b - y * a;
        norm = 1.0 / std::sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
        w = nw * norm, x = nx * norm, y = ny * norm, z = nz * norm;
        rotation_matrix(w, x, y, z, R);
        if (angle2 < 1e-8) break;
    }
    q[0] = float(w), q[1] = float(x), q[2] = float(y), q[3] = float(z);
}

}  // namespace lfem
