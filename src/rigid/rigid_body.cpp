#include "rigid/rigid_body.h"

#include <cmath>


namespace lfem {
namespace {

Quat rotation_of(const Vec3& theta) {
    const double a = theta.norm();
    return a > 0.0 ? Quat(Eigen::AngleAxisd(a, theta / a)) : Quat::Identity();
}

// Gravity plus the node forces, and the node forces' torque about the centre.
void applied_load(const RigidBodyView& b, const GlobalMotion& m, Span<const double> x,
                  const double g[3], Vec3& force, Vec3& torque) {
    force = b.mass * Vec3(g), torque = Vec3::Zero();
    const Vec3 c(m.center);
    if (!b.node_force.empty())
        for (uint32_t i = 0; i < x.size() / 3; ++i) {
            const Vec3 f(&b.node_force[3 * i]);
            force += f;
            torque += (Vec3(&x[3 * i]) - c).cross(f);
        }
}

}  // namespace

void place_nodes(const RigidBodyView& b, const GlobalMotion& m, Span<double> x) {
    const Mat3 R = load_quaternion(m.rotation).toRotationMatrix();
    const Vec3 c(m.center);
    for (uint32_t i = 0; i < x.size() / 3; ++i) {
        const Vec3 xi = c + R * (Vec3(&b.X[3 * i]) - b.com);
        for (int k = 0; k < 3; ++k) x[3 * i + k] = xi[k];
    }
}

Mat3 rigid_world_inertia(const RigidBodyView& b, const GlobalMotion& m) {
    const Mat3 R = load_quaternion(m.rotation).toRotationMatrix();
    return R * b.inertia * R.transpose();
}

double rigid_kinetic_energy(const RigidBodyView& b, const GlobalMotion& m, Vec3* omega_out) {
    const Vec3 V(m.velocity), L(m.angular_momentum);
    const Vec3 omega = rigid_world_inertia(b, m).ldlt().solve(L);
    if (omega_out) *omega_out = omega;
    return 0.5 * b.mass * V.squaredNorm() + 0.5 * L.dot(omega);
}

Vec3 rigid_synchronized_velocity(const RigidBodyView& b, const GlobalMotion& m, Span<const double> x,
                                 const double g[3], double h_last, Vec3& V, Vec3& omega) {
    const double half = 0.5 * h_last;
    Vec3 force, torque;
    applied_load(b, m, x, g, force, torque);
    V = Vec3(m.velocity) + half / b.mass * force;
    const Vec3 L = Vec3(m.angular_momentum) + half * torque;
    omega = rigid_world_inertia(b, m).ldlt().solve(L);
    return L;
}

void predict_rigid(const RigidBodyView& b, const double g[3], double h_mid, double h, GlobalMotion& m,
                   Span<double> x) {
    Vec3 force, torque;
    applied_load(b, m, x, g, force, torque);
    // Newton for the centre, eq. (2) for the rotation: L <- L + h Q, omega = I_n^-1 L.
    const Vec3 c(m.center);
    const Vec3 V = Vec3(m.velocity) + h_mid / b.mass * force;
    const Vec3 L = Vec3(m.angular_momentum) + h_mid * torque;
    const Vec3 omega = rigid_world_inertia(b, m).ldlt().solve(L);
    const Quat q = (rotation_of(h * omega) * load_quaternion(m.rotation)).normalized();
    const Vec3 c_new = c + h * V;
    for (int k = 0; k < 3; ++k) m.velocity[k] = V[k], m.angular_momentum[k] = L[k], m.center[k] = c_new[k];
    store_quaternion(q, m.rotation);
    place_nodes(b, m, x);
}

double commit_rigid(const RigidBodyView& b, double h, const Vec3& dc, const Vec3& dtheta, GlobalMotion& m,
                    Span<double> x) {
    if (dc.squaredNorm() == 0.0 && dtheta.squaredNorm() == 0.0) return 0.0;
    const double before = rigid_kinetic_energy(b, m);
    // A correction dx = lambda/mhat is a velocity change dx/h: the impulse lambda h_mid.
    const Mat3 I = rigid_world_inertia(b, m);
    const Vec3 V = Vec3(m.velocity) + dc / h;
    const Vec3 L = Vec3(m.angular_momentum) + I * dtheta / h;
    const Vec3 c = Vec3(m.center) + dc;
    const Quat q = (rotation_of(dtheta) * load_quaternion(m.rotation)).normalized();
    for (int k = 0; k < 3; ++k) m.velocity[k] = V[k], m.angular_momentum[k] = L[k], m.center[k] = c[k];
    store_quaternion(q, m.rotation);
    place_nodes(b, m, x);
    return rigid_kinetic_energy(b, m) - before;
}

void move_rigidly(const Mat3& R, const Quat& turn, const Vec3& from, const Vec3& to, Span<double> x,
                  Span<double> shape_poses) {
    for (uint32_t i = 0; i < x.size() / 3; ++i) {
        const Vec3 xi = to + R * (Vec3(&x[3 * i]) - from);
        for (int k = 0; k < 3; ++k) x[3 * i + k] = xi[k];
    }
    for (std::size_t j = 0; j < shape_poses.size(); j += 7) {
        const Vec3 c = to + R * (Vec3(&shape_poses[j]) - from);
        const Quat q = (turn * load_quaternion(&shape_poses[j + 3])).normalized();
        for (int k = 0; k < 3; ++k) shape_poses[j + k] = c[k];
        store_quaternion(q, &shape_poses[j + 3]);
    }
}

void move_kinematic(const Vec3& lin, const Vec3& ang, double h, double center[3], double rotation[4], Span<double> x,
                    Span<double> shape_poses) {
    const Vec3 c_old(center);
    const Vec3 c_new = c_old + h * lin;
    const double angle = h * ang.norm();
    const Mat3 Rot = angle > 0.0 ? Mat3(Eigen::AngleAxisd(angle, ang.normalized()).toRotationMatrix()) : Mat3::Identity();
    const Quat turn(Rot);
    move_rigidly(Rot, turn, c_old, c_new, x, shape_poses);
    for (int k = 0; k < 3; ++k) center[k] = c_new[k];
    store_quaternion((turn * load_quaternion(rotation)).normalized(), rotation);
}

}  // namespace lfem
