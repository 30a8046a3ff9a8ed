#include "rigid/global_rotation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/math.h"
#include "fem/polar_rotation.h"

namespace lfem {

namespace {

// Node i's terms of the centre of mass (m x, m y, m z, m) and of the inertia tensor about c
// (row-major), for the sums below.
inline void add_mass_moment(const double* mass, const double* x, uint32_t i, Sums<4>& out) {
    for (int k = 0; k < 3; ++k) out.v[k] += mass[i] * x[3 * i + k];
    out.v[3] += mass[i];
}
inline void add_inertia(const double* mass, const double* x, uint32_t i, const Eigen::Vector3d& c, Sums<9>& out) {
    const double r[3] = {x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]};
    const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) out.v[3 * a + b] += mass[i] * ((a == b) * r2 - r[a] * r[b]);
}
Eigen::Vector3d center_of(const Sums<4>& s) { return Eigen::Vector3d(s.v[0], s.v[1], s.v[2]) / s.v[3]; }

// Both sums of update_global_rotation in one pass over the nodes: the inertia about c_start at
// x_start and the centre of mass at x. Each is added up as on its own (the same blocks, the
// same order), so the bits are those of inertia_tensor and center_of_mass.
struct InertiaAndCenter {
    Sums<9> inertia;
    Sums<4> center;
    InertiaAndCenter& operator+=(const InertiaAndCenter& o) {
        inertia += o.inertia, center += o.center;
        return *this;
    }
};

}  // namespace

Eigen::Vector3d center_of_mass(const double* mass, const double* x, uint32_t n, ThreadPool* pool) {
    Sums<4> s;  // m x, m y, m z, m
    blocked_sum(n, pool, s, [&](uint32_t i, Sums<4>& out) { add_mass_moment(mass, x, i, out); });
    return center_of(s);
}

Eigen::Matrix3d inertia_tensor(const double* mass, const double* x, uint32_t n,
                               const Eigen::Vector3d& c, ThreadPool* pool) {
    Sums<9> s;  // row-major
    blocked_sum(n, pool, s, [&](uint32_t i, Sums<9>& out) { add_inertia(mass, x, i, c, out); });
    return load_row_major(s.v);
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
    Sums<9> s;  // row-major
    blocked_sum(n, pool, s, [&](uint32_t i, Sums<9>& out) {
        const double r[3] = {x[3 * i] - c[0], x[3 * i + 1] - c[1], x[3 * i + 2] - c[2]};
        const double R0[3] = {X[3 * i] - C[0], X[3 * i + 1] - C[1], X[3 * i + 2] - C[2]};
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) out.v[3 * a + b] += mass[i] * r[a] * R0[b];
    });
    const Eigen::Matrix3d A = load_row_major(s.v);
    extract_rotation(A, q);
}

double update_global_rotation(const double* mass, const double* x_start, const double* x, const double* X,
                              uint32_t n, const Eigen::Vector3d& com, const Eigen::Vector3d& c_start,
                              const Eigen::Vector3d& torque, double h, GlobalMotion& motion, ThreadPool* pool) {
    InertiaAndCenter sums;
    blocked_sum(n, pool, sums, [&](uint32_t i, InertiaAndCenter& out) {
        add_inertia(mass, x_start, i, c_start, out.inertia);
        add_mass_moment(mass, x, i, out.center);
    });
    const Eigen::Matrix3d inertia = load_row_major(sums.inertia.v);
    Eigen::Vector3d L(motion.angular_momentum);
    Quat q = load_quaternion(motion.rotation);
    integrate_global_rotation(inertia, torque, h, L, q);
    const Quat predicted = q;
    const Eigen::Vector3d c_new = center_of(sums.center);
    fit_global_rotation(mass, x, X, n, c_new, com, q, pool);
    store_quaternion(q, motion.rotation);
    for (int k = 0; k < 3; ++k) motion.angular_momentum[k] = L[k];
    return predicted.angularDistance(q);
}

}  // namespace lfem
