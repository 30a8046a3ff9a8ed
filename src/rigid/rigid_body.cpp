#include "rigid/rigid_body.h"

#include <cmath>

namespace lfem {
namespace {

Eigen::Quaterniond load_q(const double* q) { return {q[0], q[1], q[2], q[3]}; }
void store_q(const Eigen::Quaterniond& q, double* out) {
    out[0] = q.w(), out[1] = q.x(), out[2] = q.y(), out[3] = q.z();
}
Eigen::Quaterniond rotation_of(const Vec3& theta) {
    const double a = theta.norm();
    return a > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(a, theta / a)) : Eigen::Quaterniond::Identity();
}
Eigen::Matrix3d world_inertia(const Body& b) {
    const Eigen::Matrix3d R = load_q(b.state.rotation).toRotationMatrix();
    const Eigen::Matrix3d I = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(b.ref.inertia);
    return R * I * R.transpose();
}
// Place every node rigidly: x_i = c + R (X_i - C).
void place_nodes(Body& b) {
    const Eigen::Matrix3d R = load_q(b.state.rotation).toRotationMatrix();
    const Vec3 c(b.state.center), C(b.ref.com);
    for (uint32_t i = 0; i < b.ref.node_count(); ++i) {
        const Vec3 x = c + R * (Vec3(&b.ref.X[3 * i]) - C);
        for (int k = 0; k < 3; ++k) b.state.x[3 * i + k] = x[k];
    }
}

}  // namespace

void rigid_reference_inertia(const BodyReference& ref, double out[9]) {
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    const Vec3 C(ref.com);
    for (uint32_t i = 0; i < ref.node_count(); ++i) {
        const Vec3 r = Vec3(&ref.X[3 * i]) - C;
        I += ref.mass[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    }
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[3 * r + c] = I(r, c);
}

double rigid_kinetic_energy(const Body& b, Vec3* omega_out) {
    const Vec3 V(b.state.velocity), L(b.state.angular_momentum);
    const Vec3 omega = world_inertia(b).ldlt().solve(L);
    if (omega_out) *omega_out = omega;
    return 0.5 * b.ref.total_mass * V.squaredNorm() + 0.5 * L.dot(omega);
}

Vec3 rigid_synchronized_velocity(const Body& b, const double g[3], Vec3& V, Vec3& omega) {
    const BodyState& s = b.state;
    const double M = b.ref.total_mass, half = 0.5 * s.h_last;
    Vec3 force = M * Vec3(g), torque = Vec3::Zero();
    if (!b.node_force.empty())
        for (uint32_t i = 0; i < b.ref.node_count(); ++i) {
            force += Vec3(&b.node_force[3 * i]);
            torque += (Vec3(&s.x[3 * i]) - Vec3(s.center)).cross(Vec3(&b.node_force[3 * i]));
        }
    V = Vec3(s.velocity) + half / M * force;
    const Vec3 L = Vec3(s.angular_momentum) + half * torque;
    omega = world_inertia(b).ldlt().solve(L);
    return L;
}

void predict_rigid(Body& b, const double g[3], double h, RigidResponse& out) {
    BodyState& s = b.state;
    const double h_mid = s.h_last > 0.0 ? 0.5 * (s.h_last + h) : 0.5 * h;
    const double M = b.ref.total_mass;
    Vec3 force = M * Vec3(g), torque = Vec3::Zero();
    const Vec3 c(s.center);
    if (!b.node_force.empty())
        for (uint32_t i = 0; i < b.ref.node_count(); ++i) {
            const Vec3 f(&b.node_force[3 * i]);
            force += f;
            torque += (Vec3(&s.x[3 * i]) - c).cross(f);
        }
    // Newton for the centre, eq. (2) for the rotation: L <- L + h Q, omega = I_n^-1 L.
    Vec3 V = Vec3(s.velocity) + h_mid / M * force;
    Vec3 L = Vec3(s.angular_momentum) + h_mid * torque;
    const Vec3 omega = world_inertia(b).ldlt().solve(L);
    const Eigen::Quaterniond q = (rotation_of(h * omega) * load_q(s.rotation)).normalized();
    const Vec3 c_new = c + h * V;
    for (int k = 0; k < 3; ++k) s.velocity[k] = V[k], s.angular_momentum[k] = L[k], s.center[k] = c_new[k];
    store_q(q, s.rotation);
    place_nodes(b);
    out = RigidResponse{};
    out.center = c_new;
    out.inv_mass = h * h_mid / M;
    out.inv_inertia = h * h_mid * world_inertia(b).inverse();
}

double commit_rigid(Body& b, double h, const RigidResponse& r) {
    BodyState& s = b.state;
    if (r.dc.squaredNorm() == 0.0 && r.dtheta.squaredNorm() == 0.0) {
        s.h_last = h;
        return 0.0;
    }
    const double before = rigid_kinetic_energy(b);
    // A correction dx = lambda/mhat is a velocity change dx/h: the impulse lambda h_mid.
    const Eigen::Matrix3d I = world_inertia(b);
    const Vec3 V = Vec3(s.velocity) + r.dc / h;
    const Vec3 L = Vec3(s.angular_momentum) + I * r.dtheta / h;
    const Vec3 c = Vec3(s.center) + r.dc;
    const Eigen::Quaterniond q = (rotation_of(r.dtheta) * load_q(s.rotation)).normalized();
    for (int k = 0; k < 3; ++k) s.velocity[k] = V[k], s.angular_momentum[k] = L[k], s.center[k] = c[k];
    store_q(q, s.rotation);
    place_nodes(b);
    s.h_last = h;
    return rigid_kinetic_energy(b) - before;
}

}  // namespace lfem
