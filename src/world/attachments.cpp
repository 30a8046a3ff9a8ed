// Attachments: creation and the links each sub-step gives the multiplier solve
// (contact/link_constraint.h), and what the solve gives back (forces, breaks).
#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "world/point_binding.h"
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

namespace {

// Each held point's nodes and weights into a (nodes_per_point of each), and where each point is.
void hold_points(const Body& b, const AttachmentSpec& spec, Attachment& a, std::vector<double>& where) {
    if (!spec.nodes.empty()) {
        a.nodes_per_point = 1;
        a.nodes = spec.nodes;
        a.weights.assign(spec.nodes.size(), 1.0);
        where.resize(3 * spec.nodes.size());
        for (std::size_t k = 0; k < spec.nodes.size(); ++k)
            for (int d = 0; d < 3; ++d) where[3 * k + d] = b.state.x[3 * std::size_t(spec.nodes[k]) + d];
        return;
    }
    const uint32_t count = uint32_t(spec.points.size() / 3);
    Skin at = bind_points(b, spec.points.data(), count, b.ref.surface.edge_length, "def->points");
    a.nodes_per_point = at.nodes_per_vertex;
    a.nodes = std::move(at.nodes);
    a.weights = std::move(at.weights);
    where = spec.points;
}

}  // namespace

AttachmentHandle World::create_attachment(BodyHandle body, const AttachmentSpec& spec) {
    const Body& b = this->body(body);
    if (!b.is_deformable() || !b.has_mesh())
        throw Error(Status::invalid_argument, "def->body must be a deformable body with a mesh");
    Attachment a;
    a.body = body.index, a.body_generation = body.generation;
    const BodyHandle target = spec.target;
    const Body* deformable_target = nullptr;
    if (!target.is_null()) {
        const Body& t = this->body(target);
        if (target.index == body.index) throw Error(Status::invalid_argument, "def->target is def->body itself");
        if (!t.has_geometry()) throw Error(Status::invalid_argument, "def->target has no mesh or shape yet");
        if (t.is_deformable() && !t.has_mesh()) throw Error(Status::invalid_argument, "def->target has no tets");
        if (t.is_deformable()) deformable_target = &t;
        a.target = target.index, a.target_generation = target.generation;
    } else {
        std::copy(spec.frame, spec.frame + 7, a.frame_start);
        std::copy(spec.frame, spec.frame + 7, a.frame_end);
    }
    std::vector<double> where;
    hold_points(b, spec, a, where);
    const uint32_t count = uint32_t(where.size() / 3);
    a.break_force = spec.break_force, a.stiffness = spec.stiffness, a.damping = spec.damping;
    a.lambda.assign(3 * std::size_t(count), 0.0);
    a.target_end = where;  // the target point is where the held point is
    if (deformable_target) {
        // The same material point of the other body: its tet around each held point.
        Skin at = bind_points(*deformable_target, where.data(), count, deformable_target->ref.surface.edge_length,
                              "def->target (the held points in it)");
        a.target_nodes_per_point = at.nodes_per_vertex;
        a.target_nodes = std::move(at.nodes);
        a.target_weights = std::move(at.weights);
    } else {
        const Pose p = target_pose(bodies_, a, 0.0);
        const Mat3 Rt = p.rotation.toRotationMatrix().transpose();
        a.offsets.resize(3 * std::size_t(count));
        for (uint32_t k = 0; k < count; ++k) {
            const Vec3 r = Rt * (Vec3(&where[3 * std::size_t(k)]) - p.center);
            for (int d = 0; d < 3; ++d) a.offsets[3 * std::size_t(k) + d] = r[d];
        }
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
    if (deformable_target) wake(target.index);
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

namespace {

LinkNodes link_nodes(const std::vector<uint32_t>& nodes, const std::vector<double>& weights, uint32_t per, uint32_t k) {
    LinkNodes n;
    n.count = per;
    for (uint32_t j = 0; j < per; ++j) n.node[j] = nodes[per * std::size_t(k) + j], n.weight[j] = weights[per * std::size_t(k) + j];
    return n;
}

// sum weight_j x_j of a link side's nodes in x (3 per node).
Vec3 weighted(const LinkNodes& n, const double* x) {
    Vec3 p = n.weight[0] * Vec3(&x[3 * std::size_t(n.node[0])]);
    for (uint32_t j = 1; j < n.count; ++j) p += n.weight[j] * Vec3(&x[3 * std::size_t(n.node[j])]);
    return p;
}

}  // namespace

// One link per held point. A compliant one carries its compliance 1 / (k + c/h), the damper's
// share of it and the offset at the start of the sub-step: the held point at x^n against the
// target point where the last sub-step left it.
void World::build_links(double fraction, double h) {
    std::vector<LinkRecord>& links = pipeline_.links;
    links.clear();
    for (const Attachment& a : state_.attachments.slots) {
        if (a.generation == 0) continue;
        const Pose p = target_pose(bodies_, a, fraction);
        const Mat3 R = p.rotation.toRotationMatrix();
        const bool body_target = a.target != kFrameTarget;
        const bool rigid = body_target && bodies_.slot(a.target).is_rigid();
        const double kappa = a.stiffness > 0.0 ? a.stiffness + a.damping / h : 0.0;
        // The held body's x^n: its predictor's record when it is stepped; a sleeping body (or
        // one not stepped since a checkpoint was loaded) stands where it is.
        const Body& body = bodies_.slot(a.body);
        const std::vector<double>& recorded = pipeline_.bodies[a.body].start.x;
        const double* held_start =
            !body.state.asleep && recorded.size() == body.state.x.size() ? recorded.data() : body.state.x.data();
        for (uint32_t k = 0; k < a.point_count(); ++k) {
            LinkRecord l;
            l.body_a = a.body;
            l.held = link_nodes(a.nodes, a.weights, a.nodes_per_point, k);
            if (a.target_nodes_per_point > 0) {
                l.body_b = a.target;
                l.target_nodes = link_nodes(a.target_nodes, a.target_weights, a.target_nodes_per_point, k);
            } else {
                l.body_b = rigid ? a.target : UINT32_MAX;
                const Vec3 target = p.center + R * Vec3(&a.offsets[3 * std::size_t(k)]);
                for (int d = 0; d < 3; ++d) l.target[d] = target[d];
            }
            for (int d = 0; d < 3; ++d) l.lambda[d] = a.lambda[3 * std::size_t(k) + d];
            if (kappa > 0.0) {
                l.compliance = 1.0 / kappa;
                l.start_share = a.damping / h / kappa;
                const Vec3 r0 = weighted(l.held, held_start) - Vec3(&a.target_end[3 * std::size_t(k)]);
                for (int d = 0; d < 3; ++d) l.r0[d] = r0[d];
            }
            links.push_back(l);
        }
    }
}

// The target point where the solve left it: a fixed one where it was put, a rigid body's moved
// by the body's corrections (to first order in the rotation), a deformable body's at its nodes.
Vec3 World::link_target_end(const LinkRecord& l) const {
    const Vec3 t(l.target);
    if (l.target_nodes.count > 0) return weighted(l.target_nodes, bodies_.slot(l.body_b).state.x.data());
    if (l.body_b == UINT32_MAX || bodies_.slot(l.body_b).state.asleep) return t;  // (a sleeping body: no correction)
    const RigidResponse& r = pipeline_.bodies[l.body_b].rigid;
    return t + r.dc + r.dtheta.cross(t - r.center);
}

void World::take_link_forces(double h) {
    std::size_t next = 0;
    Attachments& all = state_.attachments;
    for (uint32_t i = 0; i < all.slots.size(); ++i) {
        Attachment& a = all.slots[i];
        if (a.generation == 0) continue;
        Vec3 total = Vec3::Zero();
        for (uint32_t k = 0; k < a.point_count(); ++k, ++next) {
            const LinkRecord& l = pipeline_.links[next];
            for (int d = 0; d < 3; ++d) a.lambda[3 * std::size_t(k) + d] = l.lambda[d];
            if (l.start_share > 0.0) {  // only a damper reads where its target was left
                const Vec3 end = link_target_end(l);
                for (int d = 0; d < 3; ++d) a.target_end[3 * std::size_t(k) + d] = end[d];
            }
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
