#include "fem/polar_rotation.h"

#include <cmath>

namespace lfem {

int extract_rotation(const Eigen::Matrix3d& A, Eigen::Quaterniond& quat, int max_iterations) {
    double a[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[3 * i + j] = A(i, j);
    double w = quat.w(), x = quat.x(), y = quat.y(), z = quat.z();
    int it = 0;
    for (; it < max_iterations; ++it) {
        const double angle2 = polar_newton_step(a, w, x, y, z, true);
        if (!(angle2 > 0.0)) break;
        // Quadratic convergence: after a step of 1e-8 rad the error is ~1e-16, round-off.
        if (angle2 < 1e-16) {
            ++it;
            break;
        }
    }
    quat = Eigen::Quaterniond(w, x, y, z);
    return it;
}

void extract_rotation_fast(const double* A, float* q, double* R) {
    double w = q[0], x = q[1], y = q[2], z = q[3];
    const double norm = 1.0 / std::sqrt(w * w + x * x + y * y + z * z);  // float rounding
    w *= norm, x *= norm, y *= norm, z *= norm;
    for (int it = 0; it < 50; ++it) {
        const double angle2 = polar_newton_step(A, w, x, y, z, true);
        if (!(angle2 > 0.0) || angle2 < 1e-8) break;
    }
    rotation_matrix(w, x, y, z, R);
    q[0] = float(w), q[1] = float(x), q[2] = float(y), q[3] = float(z);
}

}  // namespace lfem
