// LFEM_BODY_RIGID: the paper's global translation and global rotation alone (eq. 2 for the
// rotation, Newton for the centre), with no local deformation. The nodes follow rigidly:
// x_i = c + R (X_i - C).
#pragma once

#include "fem/tet_element.h"
#include "world/body.h"

namespace lfem {

// What the contact solve needs of a rigid body in this step: its predicted centre, and how a
// force lambda (N) at a point moves it, as for a node: dx = lambda / mhat with
// 1/mhat = h h_mid (1/M + r x I^-1 (r x .)).
struct RigidResponse {
    Vec3 center = Vec3::Zero();     // c* (predicted)
    double inv_mass = 0;            // h h_mid / M
    Eigen::Matrix3d inv_inertia = Eigen::Matrix3d::Zero();  // h h_mid I_world^-1 at x*
    Vec3 dc = Vec3::Zero();         // correction of the centre accumulated by the solve
    Vec3 dtheta = Vec3::Zero();     // correction of the rotation (rotation vector)
};

// Inertia of the lumped masses about the centre of mass, reference frame (row-major 3x3).
void rigid_reference_inertia(const BodyReference& ref, double out[9]);

// Predictor: gravity and node forces over the step (eq. 2 for L, Newton for the centre),
// then the nodes placed rigidly at x*. Fills the contact response.
void predict_rigid(Body& body, const double gravity[3], double h, RigidResponse& response);

// Commit: apply the solve's corrections (velocity and angular momentum change with them),
// place the nodes at x^{n+1}. Returns the kinetic energy the contact corrections changed.
double commit_rigid(Body& body, double h, const RigidResponse& response);

// Velocity of the centre and angular velocity at the current time (the last step's values
// advanced by half a step of gravity and node forces, as for nodes); returns the angular
// momentum about the centre at that time.
Vec3 rigid_synchronized_velocity(const Body& body, const double gravity[3], Vec3& V, Vec3& omega);

// Kinetic energy 1/2 M V^2 + 1/2 L . omega (last step's values), and the angular velocity.
double rigid_kinetic_energy(const Body& body, Vec3* omega = nullptr);

}  // namespace lfem
