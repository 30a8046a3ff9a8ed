// Attachments: creation and the links each sub-step gives the multiplier solve
// (contact/link_constraint.h), and what the solve gives back (forces, breaks).
#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "world/world.h"

namespace lfem {
namespace {

// A frame (centre, quaternion w x y z) as a centre and a rotation.
struct Pose {
    Vec3 center = Vec3::Zero();
    Quat rotation = Quat::Identity();
};

Pose pose_of(const double* frame) { return Pose{Vec3(frame), load_quaternion(frame + 3).normalized()}; }

// The caller's frame a fraction f of the way through a call: the centre moved on a straight
// line, the rotation by the normalised linear interpolation of the shorter way round.
Pose frame_at(const Attachment& a, double f) {
    const Pose p0 = pose_of(a.frame_start), p1 = pose_of(a.frame_end);
    Quat q1 = p1.rotation;
    if (p0.rotation.dot(q1) < 0.0) q1.coeffs() = -q1.coeffs();
    Pose p;
    p.center = (1.0 - f) * p0.center + f * p1.center;
    p.rotation = Quat((1.0 - f) * p0.rotation.coeffs() + f * q1.coeffs()).normalized();
    return p;
}

}  // namespace

// The pose of an attachment's target now (a rigid body's: as predicted for the end of the
// sub-step; a kinematic body's: where it has moved; the caller's frame: a fraction of the call).
static Pose target_pose(const BodyRegistry& bodies, const Attachment& a, double fraction) {
    if (a.target == kFrameTarget) return frame_at(a, fraction);
    const GlobalMotion& g = bodies.slot(a.target).state.global;
    return Pose{Vec3(g.center), load_quaternion(g.rotation).normalized()};
}

AttachmentHandle World::create_attachment(BodyHandle body, const std::vector<uint32_t>& nodes, BodyHandle target,
                                         const double frame[7], double break_force) {
    const Body& b = this->body(body);
    if (!b.is_deformable() || !b.has_mesh())
        throw Error(Status::invalid_argument, "def->body must be a deformable body with a mesh");
    Attachment a;
    a.body = body.index, a.body_generation = body.generation;
    if (target.index != 0 || target.generation != 0) {
        const Body& t = this->body(target);
        if (target.index == body.index) throw Error(Status::invalid_argument, "def->target is def->body itself");
        if (t.is_deformable()) throw Error(Status::invalid_argument, "def->target must be rigid, kinematic or static, not deformable");
        if (!t.has_geometry()) throw Error(Status::invalid_argument, "def->target has no mesh or shape yet");
        a.target = target.index, a.target_generation = target.generation;
    } else {
        std::copy(frame, frame + 7, a.frame_start);
        std::copy(frame, frame + 7, a.frame_end);
    }
    a.nodes = nodes;
    a.break_force = break_force;
    const Pose p = target_pose(bodies_, a, 0.0);
    const Mat3 Rt = p.rotation.toRotationMatrix().transpose();
    a.offsets.resize(3 * nodes.size());
    a.lambda.assign(3 * nodes.size(), 0.0);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const Vec3 r = Rt * (Vec3(&b.state.x[3 * std::size_t(nodes[k])]) - p.center);
        for (int d = 0; d < 3; ++d) a.offsets[3 * k + d] = r[d];
    }
    Attachments& all = state_.attachments;
    if (all.free_slots.empty()) all.slots.reserve(all.slots.size() + 1);  // may throw before any change
    a.generation = next_generation();
    uint32_t index;
    if (!all.free_slots.empty()) {
        index = all.free_slots.back();
        all.free_slots.pop_back();
        all.slots[index] = std::move(a);
    } else {
        index = uint32_t(all.slots.size());
        all.slots.push_back(std::move(a));
    }
    wake(body.index);
    return AttachmentHandle{index, all.slots[index].generation};
}

bool World::is_valid(AttachmentHandle h) const {
    const Attachments& all = state_.attachments;
    return h.generation != 0 && h.index < all.slots.size() && all.slots[h.index].generation == h.generation;
}

const Attachment& World::attachment(AttachmentHandle h) const {
    if (!is_valid(h))
        throw Error(Status::invalid_handle, "attachment handle {" + std::to_string(h.index) + ", " +
                                             std::to_string(h.generation) + "} is stale, null or of another world");
    return state_.attachments.slots[h.index];
}

void World::destroy_attachment(AttachmentHandle h) {
    const Attachment& a = attachment(h);
    Attachments& all = state_.attachments;
    all.free_slots.reserve(all.free_slots.size() + 1);  // the only allocation: before any change
    wake(a.body);
    all.slots[h.index] = Attachment{};
    all.free_slots.push_back(h.index);
}

void World::set_attachment_frame(AttachmentHandle h, const double frame[7]) {
    if (attachment(h).target != kFrameTarget)
        throw Error(Status::invalid_argument, "the attachment holds its nodes to a body, not to a frame");
    Attachment& a = state_.attachments.slots[h.index];
    std::copy(frame, frame + 7, a.frame_end);
    wake(a.body);
}

// Attachments that name a destroyed body go with it (before the slot is reused).
void World::drop_attachments_of(uint32_t slot) {
    Attachments& all = state_.attachments;
    for (uint32_t i = 0; i < all.slots.size(); ++i) {
        const Attachment& a = all.slots[i];
        if (a.generation == 0 || (a.body != slot && a.target != slot)) continue;
        all.slots[i] = Attachment{};
        all.free_slots.push_back(i);
    }
}

void World::build_links(double fraction) {
    std::vector<LinkRecord>& links = pipeline_.links;
    links.clear();
    for (const Attachment& a : state_.attachments.slots) {
        if (a.generation == 0) continue;
        const Pose p = target_pose(bodies_, a, fraction);
        const Mat3 R = p.rotation.toRotationMatrix();
        const bool rigid = a.target != kFrameTarget && bodies_.slot(a.target).is_rigid();
        for (std::size_t k = 0; k < a.nodes.size(); ++k) {
            LinkRecord l;
            l.body_a = a.body, l.node = a.nodes[k];
            l.body_b = rigid ? a.target : UINT32_MAX;
            const Vec3 target = p.center + R * Vec3(&a.offsets[3 * k]);
            for (int d = 0; d < 3; ++d) l.target[d] = target[d], l.lambda[d] = a.lambda[3 * k + d];
            links.push_back(l);
        }
    }
}

void World::take_link_forces(double h) {
    std::size_t next = 0;
    Attachments& all = state_.attachments;
    for (uint32_t i = 0; i < all.slots.size(); ++i) {
        Attachment& a = all.slots[i];
        if (a.generation == 0) continue;
        Vec3 total = Vec3::Zero();
        for (std::size_t k = 0; k < a.nodes.size(); ++k, ++next) {
            const LinkRecord& l = pipeline_.links[next];
            for (int d = 0; d < 3; ++d) a.lambda[3 * k + d] = l.lambda[d];
            total += Vec3(l.lambda);
        }
        for (int d = 0; d < 3; ++d) a.force[d] = total[d];
        if (a.break_force > 0.0 && total.norm() > a.break_force) {
            StepEvent e;
            e.type = EventType::attachment_broken;
            e.a = bodies_.handle_of(a.body);
            if (a.target != kFrameTarget) e.b = bodies_.handle_of(a.target);
            e.attachment = AttachmentHandle{i, a.generation};
            e.normal_impulse = total.norm() * h;
            e.max_force = total.norm();
            events_.add_broken(e);
            all.free_slots.push_back(i);
            a = Attachment{};
        }
    }
}

void World::finish_attachment_frames() {
    for (Attachment& a : state_.attachments.slots)
        if (a.generation != 0 && a.target == kFrameTarget) std::copy(a.frame_end, a.frame_end + 7, a.frame_start);
}

}  // namespace lfem
