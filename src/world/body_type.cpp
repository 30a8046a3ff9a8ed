// A body's type changed after creation (lfem_body_set_type), between rigid, kinematic and
// static, as Box2D's b2Body_SetType: the handle, its meshes, shapes, skins and attachments stay.
// The pose carries over (x = c + R (X - C) for all three); the motion as the new type keeps it:
// a rigid body turned kinematic moves on at its velocity and spin, a kinematic one turned rigid
// starts from its velocities (L = R I R^T omega), and a static body has none. A static body
// never moves, so its reference becomes where it is (its tree and face normals are made there
// once). The kinetic energy gained or lost is the caller's work. A deformable body keeps its
// type (its elastic state has no rigid counterpart).
#include "common/error.h"
#include "rigid/global_rotation.h"
#include "rigid/rigid_body.h"
#include "world/world.h"

namespace lfem {
namespace {

const char* type_name(BodyKind k) {
    switch (k) {
        case BodyKind::rigid: return "rigid";
        case BodyKind::kinematic: return "kinematic";
        case BodyKind::static_body: return "static";
        default: return "deformable";
    }
}

// The motion the new type starts with, into the candidate reference and state: a static body's
// reference becomes where it is (V and omega zeroed); a rigid one's inertia, velocity and
// angular momentum L = R I R^T omega, its nodes' velocities. Returns the kinetic energy it has.
double start_as(BodyKind type, BodyReference& ref, BodyState& state, Vec3& V, Vec3& omega) {
    const uint32_t n = ref.node_count();
    if (type == BodyKind::static_body) {
        ref.X = state.x;  // the pose is the identity about its centre
        V = omega = Vec3::Zero();
        if (n > 0 && ref.total_mass > 0.0) {
            const Vec3 C = center_of_mass(ref.mass.data(), ref.X.data(), n);
            for (int k = 0; k < 3; ++k) ref.com[k] = C[k], state.global.center[k] = C[k];
        }
        store_quaternion(Quat::Identity(), state.global.rotation);
    }
    std::fill(state.v_half.begin(), state.v_half.end(), 0.0);
    state.h_last = 0.0;
    std::vector<double>().swap(state.contact_force);
    for (int k = 0; k < 3; ++k) state.global.velocity[k] = state.global.angular_momentum[k] = 0.0;
    if (type != BodyKind::rigid) return 0.0;
    const Mat3 I = inertia_tensor(ref.mass.data(), ref.X.data(), n, Vec3(ref.com));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) ref.inertia[3 * r + c] = I(r, c);
    const Vec3 c(state.global.center);
    const Mat3 R = load_quaternion(state.global.rotation).normalized().toRotationMatrix();
    const Vec3 L = R * I * R.transpose() * omega;
    for (int k = 0; k < 3; ++k) state.global.velocity[k] = V[k], state.global.angular_momentum[k] = L[k];
    for (uint32_t i = 0; i < n; ++i) {
        const Vec3 vi = V + omega.cross(Vec3(&state.x[3 * std::size_t(i)]) - c);
        for (int k = 0; k < 3; ++k) state.v_half[3 * std::size_t(i) + k] = vi[k];
    }
    return 0.5 * ref.total_mass * V.squaredNorm() + 0.5 * omega.dot(L);
}

}  // namespace

// The offsets of the attachments held in this body's frame, from its frame (c_was, q_was) to the
// one it has now (a static body's is turned to the identity about its centre): the points they
// hold to stay where they are.
void World::reframe_attachments(uint32_t slot, const Vec3& c_was, const Quat& q_was) {
    const Body& body = bodies_.slot(slot);
    const Vec3 c(body.state.global.center);
    const Mat3 R_was = q_was.toRotationMatrix();
    const Mat3 Rt = load_quaternion(body.state.global.rotation).normalized().toRotationMatrix().transpose();
    for (Attachment& a : state_.attachments.slots) {
        if (a.generation == 0 || a.target != slot || a.target_nodes_per_point > 0) continue;
        for (std::size_t k = 0; k < a.offsets.size(); k += 3) {
            const Vec3 p = c_was + R_was * Vec3(&a.offsets[k]);
            const Vec3 local = Rt * (p - c);
            for (int d = 0; d < 3; ++d) a.offsets[k + d] = local[d];
        }
    }
}

void World::set_type(BodyHandle handle, BodyKind type) {
    Body& body = bodies_.get(handle);
    if (body.def.type == type) return;
    if (body.is_deformable() || type == BodyKind::deformable)
        throw Error(Status::invalid_argument, std::string("a deformable body keeps its type (asked to make a ") +
                                                  type_name(body.def.type) + " body " + type_name(type) +
                                                  "): rigid, kinematic and static bodies change between them");
    if (type == BodyKind::rigid && body.ref.tet_count() == 0)
        throw Error(Status::invalid_argument, "a rigid body needs tets (its mass): this body has none");
    if (type == BodyKind::rigid && !body.shapes.empty())
        throw Error(Status::invalid_argument, "a rigid body has no shapes: this body has some");
    // The motion now, as the old type has it.
    Vec3 V = Vec3::Zero(), omega = Vec3::Zero();
    double kinetic_before = 0.0;
    if (body.is_rigid()) {
        rigid_velocity(body, V, omega);
        kinetic_before = rigid_kinetic_energy(rigid_view(body), body.state.global);
    } else if (body.is_kinematic()) {
        V = Vec3(body.def.linear_velocity), omega = Vec3(body.def.angular_velocity);
    }
    // The candidates: all allocation before any change.
    Body candidate;
    candidate.def = body.def;
    candidate.def.type = type;
    BodyReference ref = body.ref;
    BodyState state = body.state;
    const Vec3 c_was(body.state.global.center);
    const Quat q_was = load_quaternion(body.state.global.rotation).normalized();
    const double kinetic_after = start_as(type, ref, state, V, omega);
    for (int k = 0; k < 3; ++k) candidate.def.linear_velocity[k] = V[k], candidate.def.angular_velocity[k] = omega[k];
    derive_reference_data(candidate, ref);  // a static body's tree and face normals, or none
    end_contacts_of(handle.index);          // its pairs end (a static body's are found anew)
    wake(handle.index);
    // Nothing fails from here.
    body.def = candidate.def;
    body.ref = std::move(ref);
    body.state = std::move(state);
    reframe_attachments(handle.index, c_was, q_was);
    state_.counters.external_work += kinetic_after - kinetic_before;
    state_.counters.scan_overlaps = true;
    body.geometry_revision += 1;  // the contact candidates and the queries' boxes are made anew
    moved();
}

}  // namespace lfem
