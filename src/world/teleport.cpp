// Where a body is, and moving it there at once (lfem_body_get_transform, _get_center_of_mass,
// _set_transform, _set_positions): the pose an engine parents objects to, and the teleport it
// resets a scene with. A teleport is no motion: no work is done, velocities are kept, and the
// body's pairs end (the contacts it had are not where it is now).
#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "rigid/global_rotation.h"
#include "common/error.h"
#include "rigid/rigid_body.h"
#include "world/world.h"

namespace lfem {
namespace {

// The rotation closest to A (its polar factor), by SVD: any angle, no warm start needed.
Quat polar_rotation(const Mat3& A) {
    const Eigen::JacobiSVD<Mat3> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Mat3 U = svd.matrixU();
    const Mat3 V = svd.matrixV();
    if ((U * V.transpose()).determinant() < 0.0) U.col(2) = -U.col(2);  // a rotation, not a reflection
    return Quat(Mat3(U * V.transpose())).normalized();
}

// A deformable body's centre of mass and the rotation that best carries its mesh as added to its
// nodes now: the polar rotation of A = sum m_i (x_i - c)(X_i - C)^T, as the "paper" model's
// frame is fitted (eq. 2's re-fit, rigid/global_rotation.cpp).
void fit_pose(const Body& b, Vec3& c, Quat& q) {
    const BodyReference& ref = b.ref;
    const uint32_t n = ref.node_count();
    c = center_of_mass(ref.mass.data(), b.state.x.data(), n);
    const Vec3 C(ref.com);
    Mat3 A = Mat3::Zero();
    for (uint32_t i = 0; i < n; ++i) A += ref.mass[i] * (Vec3(&b.state.x[3 * i]) - c) * (Vec3(&ref.X[3 * i]) - C).transpose();
    q = polar_rotation(A);
}

// The body's centre and rotation: a deformable body's fit, the frame of the others (a rigid
// body's centre of mass, a kinematic body's pivot, a static body's centre as added).
void pose_of(const Body& b, Vec3& c, Quat& q) {
    if (b.is_deformable() && b.has_mesh()) return fit_pose(b, c, q);
    c = Vec3(b.state.global.center);
    q = b.is_static() ? Quat::Identity() : load_quaternion(b.state.global.rotation).normalized();
}

}  // namespace

Vec3 World::body_center_of_mass(const Body& b) const {
    Vec3 c;
    Quat q;
    pose_of(b, c, q);
    return c;
}

void World::body_transform(const Body& b, double out[7]) const {
    Vec3 c;
    Quat q;
    pose_of(b, c, q);
    const Vec3 t = c - q.toRotationMatrix() * Vec3(b.ref.com);  // x = R X + t carries C to c
    for (int k = 0; k < 3; ++k) out[k] = t[k];
    store_quaternion(q, out + 3);
}

// A teleport's effects beyond the body's own state: its pairs end (the next call's events say
// so), what it held up wakes, its contact records go (none may be warm-started or queried at a
// place it left), its cached contact candidates are searched again, the queries see it anew.
void World::end_contacts_of(uint32_t slot) {
    const auto involves = [&](uint64_t key) { return uint32_t(key >> 32) == slot || uint32_t(key) == slot; };
    std::vector<uint64_t>& touching = state_.touching;
    // The only allocation, before any change: room for the events (an end for each pair, a wake
    // for each body).
    events_.reserve(bodies_.slot_count() + std::size_t(std::count_if(touching.begin(), touching.end(), involves)));
    for (uint64_t key : touching)
        if (involves(key))
            events_.add_contact_end(bodies_.handle_of(uint32_t(key >> 32)), bodies_.handle_of(uint32_t(key)));
    wake_touching(slot);
    touching.erase(std::remove_if(touching.begin(), touching.end(), involves), touching.end());
    std::vector<ContactRecord>& contacts = state_.contacts;
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [&](const ContactRecord& r) { return r.body_a == slot || r.body_b == slot; }),
                   contacts.end());
}

// New node positions for a deformable body (3 per node, internal order), its synchronized
// velocities kept; the change of strain energy is the caller's work (the balance stays closed).
// turn: the rotation of a rigid teleport (its tets' rotations' warm starts turn with it).
void World::place_deformable(BodyHandle handle, const double* x, const Quat& turn) {
    Body& body = bodies_.get(handle);
    const uint32_t n = body.ref.node_count();
    BodyState state = body.state;  // the candidate: all allocation before any change
    synchronized_velocities(body, state.v_half.data());
    state.h_last = 0.0;  // v_half holds synchronized velocities
    std::copy(x, x + 3 * std::size_t(n), state.x.begin());
    std::vector<double>().swap(state.contact_force);  // it touches nothing where it is now
    if (!std::all_of(state.x.begin(), state.x.end(), [](double a) { return std::isfinite(a); }))
        throw Error(Status::invalid_argument, "the transform moves the body beyond what a double holds");
    for (std::size_t k = 0; k < state.tet_rotation.size(); k += 4) {
        const Quat q = (turn * Quat(state.tet_rotation[k], state.tet_rotation[k + 1], state.tet_rotation[k + 2],
                                    state.tet_rotation[k + 3]).cast<double>())
                           .normalized();
        state.tet_rotation[k] = float(q.w()), state.tet_rotation[k + 1] = float(q.x());
        state.tet_rotation[k + 2] = float(q.y()), state.tet_rotation[k + 3] = float(q.z());
    }
    if (body.is_paper()) {
        const Vec3 c = center_of_mass(body.ref.mass.data(), state.x.data(), n);
        Quat q = (turn * load_quaternion(state.global.rotation)).normalized();
        fit_global_rotation(body.ref.mass.data(), state.x.data(), body.ref.X.data(), n, c, Vec3(body.ref.com), q);
        store_quaternion(q, state.global.rotation);
        const Vec3 L = angular_momentum(body.ref.mass.data(), state.x.data(), state.v_half.data(), n, c);
        for (int k = 0; k < 3; ++k) state.global.center[k] = c[k], state.global.angular_momentum[k] = L[k];
    }
    update_elastic_forces(body, state, pool_.get());
    if (!std::isfinite(state.strain_energy))
        throw Error(Status::invalid_argument, "the positions strain the body beyond what a double holds "
                                              "(its elastic energy overflows)");
    const double work = state.strain_energy - body.state.strain_energy;
    end_contacts_of(handle.index);
    wake(handle.index);
    body.state = std::move(state);  // nothing fails from here
    if (body.is_dynamic()) state_.counters.external_work += work;
    body.geometry_revision += 1;  // the contact candidates are searched again
    moved();
}

void World::set_positions(BodyHandle handle, const double* x) {
    const Body& body = bodies_.get(handle);
    if (!body.is_deformable() || !body.has_mesh())
        throw Error(Status::invalid_argument, "setting node positions needs a deformable body with a mesh "
                                              "(move a rigid or kinematic body with its transform)");
    place_deformable(handle, x, Quat::Identity());
}

void World::set_transform(BodyHandle handle, const double transform[7]) {
    Body& body = bodies_.get(handle);
    if (body.is_static()) throw Error(Status::invalid_argument, "a static body does not move (make it kinematic)");
    if (!body.has_geometry()) throw Error(Status::invalid_argument, "the body has no mesh or shape to move");
    Vec3 c;
    Quat q;
    pose_of(body, c, q);
    // The rigid move D(x) = R_d x + t_d from the body's pose to the one asked: R_d = R_new R^T.
    const Quat q_new = load_quaternion(transform + 3).normalized();
    const Quat turn = (q_new * q.conjugate()).normalized();
    const Mat3 R_d = turn.toRotationMatrix();
    const Vec3 t_new(transform);
    const Vec3 t = c - q.toRotationMatrix() * Vec3(body.ref.com);
    const Vec3 t_d = t_new - R_d * t;
    const uint32_t n = body.ref.node_count();
    if (body.is_deformable()) {
        std::vector<double> x(3 * std::size_t(n));
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3 xi = R_d * Vec3(&body.state.x[3 * i]) + t_d;
            for (int k = 0; k < 3; ++k) x[3 * i + k] = xi[k];
        }
        return place_deformable(handle, x.data(), turn);  // refuses positions that are not finite
    }
    // Rigid and kinematic: the frame moves, the nodes and shapes with it. A rigid body keeps
    // its synchronized velocity and spin (its angular momentum turns with it).
    GlobalMotion motion = body.state.global;
    const Vec3 c_new = R_d * c + t_d;
    for (int k = 0; k < 3; ++k) motion.center[k] = c_new[k];
    store_quaternion(q_new, motion.rotation);
    std::vector<double> x = body.state.x, poses = body.state.shape_pose;  // all allocation first
    // A rigid body's nodes are placed at its frame below (exactly); the others' move with it.
    move_rigidly(R_d, turn, c, c_new, body.is_rigid() ? Span<double>() : Span<double>(x), poses);
    if (body.is_rigid()) {
        const RigidBodyView view = rigid_view(body);
        Vec3 V, omega;
        rigid_velocity(body, V, omega);
        const Vec3 L = rigid_world_inertia(view, motion) * omega;
        for (int k = 0; k < 3; ++k) motion.velocity[k] = V[k], motion.angular_momentum[k] = L[k];
        place_nodes(view, motion, x);  // exactly at the frame
    }
    const auto finite = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double a) { return std::isfinite(a); });
    };
    if (!finite(x) || !finite(poses) || !c_new.allFinite())
        throw Error(Status::invalid_argument, "the transform moves the body beyond what a double holds");
    end_contacts_of(handle.index);
    wake(handle.index);
    body.state.global = motion;  // nothing fails from here
    body.state.x.swap(x);
    body.state.shape_pose.swap(poses);
    if (body.is_rigid()) body.state.h_last = 0.0;  // the frame holds synchronized velocities
    std::vector<double>().swap(body.state.contact_force);
    body.geometry_revision += 1;
    moved();
}

}  // namespace lfem
