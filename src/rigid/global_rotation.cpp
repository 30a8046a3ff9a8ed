#include "rigid/global_rotation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "fem/polar_rotation.h"

namespace lfem {

Eigen::Vector3d center_of_mass(const double* mass, const double* x, uint32_t n, ThreadPool* pool) {
    double s[4] = {0, 0, 0, 0};
    blocked_sum<4>(n, pool, s, [&](uint32_t i, double* out) {
        for (int k = 0; k < 3; ++k) out[k] += mass[i] * x[3 * i + k];
        out[3] += mass[i];
    });
    return Eigen::Vector3d(s[0], s[1], s[2]) / s[3];
}

Eigen::Matrix3d inertia_tensor(const double* mass, const double* x, uint32_t n,
                               const Eigen::Vector3d& c, ThreadPool* pool) {
    double s[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    blocked_sum<9>(n, pool, s, [&](uint32_t i, double* out) {
        const double r[3] = {x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]};
        const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) out[3 * a + b] += mass[i] * ((a == b) * r2 - r[a] * r[b]);
    });
    return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(s);
}

Eigen::Vector3d angular_momentum(const double* mass, const double* x, const double* v,
                                 uint32_t n, const Eigen::Vector3d& c) {
    Eigen::Vector3d L = Eigen::Vector3d::Zero();
    for (uint32_t i = 0; i < n; ++i) {
        const Eigen::Vector3d r(x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]);
        L += mass[i] * r.cross(Eigen::Vector3d(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
    }
    return L;
}

Eigen::Vector3d integrate_global_rotation(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& torque,
                                          double h, Eigen::Vector3d& L, Eigen::Quaterniond& q) {
    L += h * torque;                                    // eq. (2): d(I omega)/dt = Q
    const Eigen::Vector3d omega = inertia.ldlt().solve(L);
    const double angle = h * omega.norm();
    if (angle > 0.0) q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega.normalized())) * q;
    q.normalize();
    return omega;
}

void fit_global_rotation(const double* mass, const double* x, const double* X, uint32_t n,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& C,
                         Eigen::Quaterniond& q, ThreadPool* pool) {
    double s[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    blocked_sum<9>(n, pool, s, [&](uint32_t i, double* out) {
        const double r[3] = {x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]};
        const double R0[3] = {X[3 * i] - C[0], X[3 * i + 1] - C[1], X[3 * i + 2] - C[2]};
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) out[3 * a + b] += mass[i] * r[a] * R0[b];
    });
    const Eigen::Matrix3d A = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(s);
    extract_rotation(A, q);
}

}  // namespace lfem
