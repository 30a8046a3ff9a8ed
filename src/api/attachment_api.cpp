// C shim of attachments, sleeping and events: validates, translates node numbers and handles,
// and leaves the work to lfem::World.
#include <algorithm>
#include <cmath>
#include <string>

#include "api/handles.h"
#include "api/node_lists.h"

using namespace lfem;
using namespace lfem::api;

namespace {


lfem_event event_as_c(const StepEvent& e) {
    lfem_event out{};
    out.type = to_c(e.type);
    out.body_a = to_c(e.a);
    out.body_b = to_c(e.b);
    out.attachment = to_c(e.attachment);
    out.normal_impulse = e.normal_impulse;
    out.max_force = e.max_force;
    out.approach_speed = e.impact.approach_speed;
    out.contact_count = e.contact_count;
    for (int k = 0; k < 3; ++k) out.point[k] = e.impact.point[k], out.normal[k] = e.impact.normal[k];
    return out;
}

}  // namespace

extern "C" {

LFEM_API lfem_attachment_def lfem_attachment_def_default(void) {
    lfem_attachment_def d{};
    d.frame[3] = 1.0;
    d.internal_value = attachment_def_cookie;
    return d;
}

LFEM_API lfem_status lfem_attachment_create(lfem_world* world, const lfem_attachment_def* def, lfem_attachment* out) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        require_pointer(def, "def");
        require_pointer(out, "out");
        require(def->internal_value == attachment_def_cookie, "def was not initialised by lfem_attachment_def_default()");
        const Body& b = w.body(from_c(def->body));
        const BodyHandle target = from_c(def->target);
        require((def->node_count >= 1) != (def->point_count >= 1),
                "give nodes (def->node_count >= 1) or points (def->point_count >= 1), one of the two");
        require(target.is_null() || w.is_valid(target),
                "def->target {" + std::to_string(def->target.index) + ", " + std::to_string(def->target.generation) +
                    "} is stale or of another world (the null handle means the caller's frame)");
        if (target.is_null()) require_pose(def->frame, "def->frame");
        require(std::isfinite(def->break_force) && def->break_force >= 0.0,
                "def->break_force must be finite and >= 0 N (0 = never breaks)");
        require(std::isfinite(def->stiffness) && def->stiffness >= 0.0,
                "def->stiffness must be finite and >= 0 N/m (0 = rigid)");
        require(std::isfinite(def->damping) && def->damping >= 0.0, "def->damping must be finite and >= 0 N s/m");
        require(def->damping == 0.0 || def->stiffness > 0.0, "def->damping needs a def->stiffness > 0 (a rigid hold has no damper)");
        AttachmentSpec spec;
        if (def->node_count >= 1) {
            spec.nodes = internal_nodes(b, def->nodes, def->node_count);
        } else {
            require_pointer(def->points, "def->points");
            require(def->point_count <= (1u << 24), "def->point_count above 2^24");
            require_finite(def->points, 3 * std::size_t(def->point_count), "def->points");
            require(b.tet_count() > 0, "points are held in tets: def->body has none yet");
            spec.points.assign(def->points, def->points + 3 * std::size_t(def->point_count));
        }
        spec.target = target;
        for (int k = 0; k < 7; ++k) spec.frame[k] = def->frame[k];
        spec.break_force = def->break_force, spec.stiffness = def->stiffness, spec.damping = def->damping;
        *out = to_c(w.create_attachment(from_c(def->body), spec));
    });
}

LFEM_API lfem_status lfem_attachment_destroy(lfem_world* world, lfem_attachment attachment) {
    return guard(__func__, [&] { world_of(world).destroy_attachment(from_c(attachment)); });
}

LFEM_API int lfem_attachment_is_valid(const lfem_world* world, lfem_attachment attachment) {
    return world != nullptr && world->world.is_valid(from_c(attachment)) ? 1 : 0;
}

LFEM_API lfem_status lfem_attachment_set_frame(lfem_world* world, lfem_attachment attachment, const double frame[7]) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.attachment(from_c(attachment));  // the handle first
        require_pose(frame, "frame");
        w.set_attachment_frame(from_c(attachment), frame);
    });
}

LFEM_API lfem_status lfem_attachment_get_force(const lfem_world* world, lfem_attachment attachment, double force[3]) {
    return guard(__func__, [&] {
        const Attachment& a = world_of(world).attachment(from_c(attachment));
        require_pointer(force, "force");
        for (int k = 0; k < 3; ++k) force[k] = a.force[k];
    });
}

LFEM_API lfem_status lfem_attachment_get_frame(const lfem_world* world, lfem_attachment attachment, double frame[7]) {
    return guard(__func__, [&] {
        const Attachment& a = world_of(world).attachment(from_c(attachment));
        require(a.target == kFrameTarget, "the attachment holds its nodes to a body, not to a frame");
        require_pointer(frame, "frame");
        std::copy(a.frame_end, a.frame_end + 7, frame);
    });
}

LFEM_API lfem_status lfem_body_set_sleep_allowed(lfem_world* world, lfem_body body, int allowed) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        require(allowed == 0 || allowed == 1, "allowed must be 0 or 1, got " + std::to_string(allowed));
        w.set_sleep_allowed(from_c(body), allowed == 1);
    });
}

LFEM_API lfem_status lfem_body_wake(lfem_world* world, lfem_body body) {
    return guard(__func__, [&] { world_of(world).wake_body(from_c(body)); });
}

LFEM_API int lfem_body_is_awake(const lfem_world* world, lfem_body body) {
    if (world == nullptr || !world->world.is_valid(from_c(body))) return -1;
    return world->world.is_awake(world->world.body(from_c(body))) ? 1 : 0;
}

LFEM_API lfem_status lfem_world_get_events(const lfem_world* world, lfem_event* out, uint32_t capacity,
                                           uint32_t* count) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(count, "count");
        const std::vector<StepEvent>& events = w.events();
        require(capacity == 0 || out != nullptr, "out is NULL with capacity " + std::to_string(capacity));
        const uint32_t n = uint32_t(events.size());
        if (n > capacity) {
            *count = n;
            throw Error(Status::buffer_too_small, "capacity " + std::to_string(capacity) + " is below the " +
                                                   std::to_string(n) + " events of the last step");
        }
        for (uint32_t i = 0; i < n; ++i) out[i] = event_as_c(events[i]);
        *count = n;
    });
}

}  // extern "C"
