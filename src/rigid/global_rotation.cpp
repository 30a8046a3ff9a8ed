#include "rigid/global_rotation.h"

#include <cmath>

#include "fem/polar_rotation.h"

namespace lfem {

Eigen::Vector3d center_of_mass(const double* mass, const double* x, uint32_t n) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double total = 0.0;
    for (uint32_t i = 0; i < n; ++i) {
        sum += mass[i] * Eigen::Vector3d(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
        total += mass[i];
    }
    return sum / total;
}

Eigen::Matrix3d inertia_tensor(const double* mass, const double* x, uint32_t n,
                               const Eigen::Vector3d& c) {
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    for (uint32_t i = 0; i < n; ++i) {
        const Eigen::Vector3d r(x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]);
        I += mass[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    return I;
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
                         Eigen::Quaterniond& q) {
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    for (uint32_t i = 0; i < n; ++i) {
        const Eigen::Vector3d r(x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]);
        const Eigen::Vector3d R0(X[3 * i] - C[0], X[3 * i + 1] - C[1], X[3 * i + 2] - C[2]);
        A += mass[i] * r * R0.transpose();
    }
    extract_rotation(A, q);
}

}  // namespace lfem
