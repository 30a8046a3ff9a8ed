// Rigid bodies (BodyKind::rigid): the paper's global translation and global rotation alone (eq. 2 for the
// rotation, Newton for the centre), with no local deformation. The nodes follow rigidly:
// x_i = c + R (X_i - C).
#pragma once

#include "common/math.h"
#include "common/span.h"
#include "rigid/global_rotation.h"

namespace lfem {

// What the rigid dynamics reads of a body, fixed during a step.
struct RigidBodyView {
    double mass = 0;                // kg
    Vec3 com = Vec3::Zero();        // reference centre of mass (m)
    Mat3 inertia = Mat3::Zero();    // about the centre of mass, reference frame (kg m^2)
    Span<const double> X;           // 3 per node: reference positions (m)
    Span<const double> node_force;  // 3 per node (N); empty when none is set
};

// The inertia tensor in the world frame, R I R^T.
Mat3 rigid_world_inertia(const RigidBodyView& body, const GlobalMotion& motion);

// Predictor: gravity and node forces over the step (eq. 2 for L, Newton for the centre), then
// the nodes placed rigidly at x* (3 per node); the forces act over h_mid (mid_step).
void predict_rigid(const RigidBodyView& body, const double gravity[3], double h_mid, double h,
                   GlobalMotion& motion, Span<double> x);

// Commit: the solve's corrections of the centre (dc, m) and of the rotation (dtheta, a
// rotation vector) change the velocity and angular momentum by them over the step h; the nodes
// are placed at x^{n+1}. Returns the kinetic energy the corrections changed (J).
double commit_rigid(const RigidBodyView& body, double h, const Vec3& dc, const Vec3& dtheta,
                    GlobalMotion& motion, Span<double> x);

// Velocity of the centre and angular velocity at the current time (the last step's values
// advanced by half a step of gravity and node forces, as for nodes); returns the angular
// momentum about the centre at that time. x: the nodes (for the node forces' torque).
Vec3 rigid_synchronized_velocity(const RigidBodyView& body, const GlobalMotion& motion,
                                 Span<const double> x, const double gravity[3], double h_last, Vec3& V,
                                 Vec3& omega);

// Place every node rigidly at the frame: x_i = c + R (X_i - C).
void place_nodes(const RigidBodyView& body, const GlobalMotion& motion, Span<double> x);

// Move nodes (3 per node) and shape placements (7 per shape: centre, quaternion w, x, y, z)
// rigidly: x -> to + R (x - from), a shape's rotation turned by `turn` (R's quaternion).
void move_rigidly(const Mat3& R, const Quat& turn, const Vec3& from, const Vec3& to, Span<double> x,
                  Span<double> shape_poses);

// A kinematic body moves rigidly: its centre by v h, its nodes (3 per node) and the
// placements of its shapes (7 per shape: centre, quaternion w, x, y, z) turned by omega h
// about the centre, and its rotation since it was created (a quaternion, for what is attached
// to it) by the same turn.
void move_kinematic(const Vec3& linear, const Vec3& angular, double h, double center[3], double rotation[4],
                    Span<double> x,
                    Span<double> shape_poses);

// Kinetic energy 1/2 M V^2 + 1/2 L . omega (last step's values), and the angular velocity.
double rigid_kinetic_energy(const RigidBodyView& body, const GlobalMotion& motion, Vec3* omega = nullptr);

}  // namespace lfem
