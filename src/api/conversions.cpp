#include "api/conversions.h"

#include <algorithm>

namespace lfem::api {

lfem_status to_c(Status s) {
    switch (s) {
        case Status::ok: return LFEM_OK;
        case Status::invalid_argument: return LFEM_INVALID_ARGUMENT;
        case Status::invalid_mesh: return LFEM_INVALID_MESH;
        case Status::invalid_handle: return LFEM_INVALID_HANDLE;
        case Status::buffer_too_small: return LFEM_BUFFER_TOO_SMALL;
        case Status::unstable: return LFEM_UNSTABLE;
        case Status::io_error: return LFEM_IO_ERROR;
        case Status::out_of_memory: return LFEM_OUT_OF_MEMORY;
        case Status::internal_error: return LFEM_INTERNAL_ERROR;
        case Status::unsupported: return LFEM_UNSUPPORTED;
    }
    return LFEM_INTERNAL_ERROR;
}

lfem_body to_c(BodyHandle h) { return lfem_body{h.index, h.generation}; }
lfem_attachment to_c(AttachmentHandle h) { return lfem_attachment{h.index, h.generation}; }

lfem_event_type to_c(EventType t) {
    switch (t) {
        case EventType::contact_begin: return LFEM_EVENT_CONTACT_BEGIN;
        case EventType::contact_end: return LFEM_EVENT_CONTACT_END;
        case EventType::sleep: return LFEM_EVENT_SLEEP;
        case EventType::wake: return LFEM_EVENT_WAKE;
        case EventType::attachment_broken: return LFEM_EVENT_ATTACHMENT_BROKEN;
        case EventType::contact_persist: return LFEM_EVENT_CONTACT_PERSIST;
    }
    return LFEM_EVENT_CONTACT_BEGIN;
}

BodyKind from_c(lfem_body_type t) {
    switch (t) {
        case LFEM_BODY_STATIC: return BodyKind::static_body;
        case LFEM_BODY_KINEMATIC: return BodyKind::kinematic;
        case LFEM_BODY_RIGID: return BodyKind::rigid;
        default: return BodyKind::deformable;
    }
}

namespace {

lfem_phase_time to_c(const PhaseTime& t) { return lfem_phase_time{t.seconds, t.calls}; }

Model from_c(lfem_model m) {
    switch (m) {
        case LFEM_MODEL_COROTATIONAL: return Model::corotational;
        case LFEM_MODEL_NEO_HOOKEAN: return Model::neo_hookean;
        case LFEM_MODEL_LINEAR: return Model::linear;
        default: return Model::paper;
    }
}

}  // namespace

lfem_body_type to_c(BodyKind k) {
    switch (k) {
        case BodyKind::deformable: return LFEM_BODY_DEFORMABLE;
        case BodyKind::static_body: return LFEM_BODY_STATIC;
        case BodyKind::kinematic: return LFEM_BODY_KINEMATIC;
        case BodyKind::rigid: return LFEM_BODY_RIGID;
    }
    return LFEM_BODY_TYPE_FORCE32;  // not a body type: refused by check_body_def
}

lfem_model to_c(Model m) {
    switch (m) {
        case Model::paper: return LFEM_MODEL_PAPER;
        case Model::corotational: return LFEM_MODEL_COROTATIONAL;
        case Model::neo_hookean: return LFEM_MODEL_NEO_HOOKEAN;
        case Model::linear: return LFEM_MODEL_LINEAR;
    }
    return LFEM_MODEL_FORCE32;  // not a model: refused by check_body_def
}

lfem_profile to_c(const Profile& p) {
    lfem_profile c{};
    c.substeps = p.substeps;
    c.internal_forces = to_c(p.internal_forces);
    c.predictor = to_c(p.predictor);
    c.kinematic_motion = to_c(p.kinematic_motion);
    c.broad_phase = to_c(p.broad_phase);
    c.narrow_phase = to_c(p.narrow_phase);
    c.shape_queries = to_c(p.shape_queries);
    c.shape_tests = p.shape_tests;
    c.ccd_queries = p.ccd_queries;
    c.normal_solve = to_c(p.normal_solve);
    c.friction = to_c(p.friction);
    c.global_rotation = to_c(p.global_rotation);
    c.commit = to_c(p.commit);
    c.candidate_searches = p.candidate_searches;
    c.contact_sweeps = p.contact_sweeps;
    c.constraint_updates = p.constraint_updates;
    return c;
}

WorldDef to_world_def(const lfem_world_def& d) {
    WorldDef w;
    std::copy(d.gravity, d.gravity + 3, w.gravity);
    w.time_step = d.time_step;
    w.step_safety = d.step_safety;
    w.contact_iterations = d.contact_iterations;
    w.thread_count = d.thread_count;
    w.contact_tolerance = d.contact_tolerance;
    w.max_substeps = d.max_substeps;
    w.allow_unstable_step = d.allow_unstable_step != 0;
    w.enable_sleep = d.enable_sleep != 0;
    w.mass_scaling_step = d.mass_scaling_step;
    w.sleep_velocity = d.sleep_velocity;
    w.sleep_time = d.sleep_time;
    return w;
}

lfem_world_def to_c(const WorldDef& w, uint32_t cookie) {
    lfem_world_def d{};
    std::copy(w.gravity, w.gravity + 3, d.gravity);
    d.time_step = w.time_step;
    d.step_safety = w.step_safety;
    d.contact_iterations = w.contact_iterations;
    d.thread_count = w.thread_count;
    d.contact_tolerance = w.contact_tolerance;
    d.max_substeps = w.max_substeps;
    d.allow_unstable_step = w.allow_unstable_step;
    d.enable_sleep = w.enable_sleep;
    d.internal_value = cookie;
    d.mass_scaling_step = w.mass_scaling_step;
    d.sleep_velocity = w.sleep_velocity;
    d.sleep_time = w.sleep_time;
    return d;
}

BodyDef to_body_def(const lfem_body_def& d) {
    BodyDef b;
    b.type = from_c(d.type);
    b.model = from_c(d.model);
    b.young_modulus = d.young_modulus;
    b.poisson_ratio = d.poisson_ratio;
    b.density = d.density;
    b.damping = d.damping;
    b.friction = d.friction;
    std::copy(d.linear_velocity, d.linear_velocity + 3, b.linear_velocity);
    std::copy(d.angular_velocity, d.angular_velocity + 3, b.angular_velocity);
    b.category_bits = d.category_bits;
    b.mask_bits = d.mask_bits;
    b.user_data = d.user_data;
    b.enable_sleep = d.enable_sleep != 0;
    b.self_contact = d.self_contact != 0;
    b.composite_tets = d.composite_tets != 0;
    b.report_contacts = d.report_contacts != 0;
    b.edge_contacts = d.edge_contacts != 0;
    return b;
}

lfem_body_def to_c(const BodyDef& b, uint32_t cookie) {
    lfem_body_def d{};
    d.type = to_c(b.type);
    d.model = to_c(b.model);
    d.young_modulus = b.young_modulus;
    d.poisson_ratio = b.poisson_ratio;
    d.density = b.density;
    d.damping = b.damping;
    d.friction = b.friction;
    std::copy(b.linear_velocity, b.linear_velocity + 3, d.linear_velocity);
    std::copy(b.angular_velocity, b.angular_velocity + 3, d.angular_velocity);
    d.category_bits = b.category_bits;
    d.mask_bits = b.mask_bits;
    d.user_data = b.user_data;
    d.internal_value = cookie;
    d.enable_sleep = b.enable_sleep;
    d.self_contact = b.self_contact;
    d.composite_tets = b.composite_tets;
    d.report_contacts = b.report_contacts;
    d.edge_contacts = b.edge_contacts;
    return d;
}

bool shape_type_from_c(lfem_shape_type t, ShapeType& out) {
    switch (t) {
        case LFEM_SHAPE_PLANE: out = ShapeType::plane; return true;
        case LFEM_SHAPE_BOX: out = ShapeType::box; return true;
        case LFEM_SHAPE_SPHERE: out = ShapeType::sphere; return true;
        case LFEM_SHAPE_CAPSULE: out = ShapeType::capsule; return true;
        case LFEM_SHAPE_CONVEX_HULL: out = ShapeType::convex_hull; return true;
        default: return false;
    }
}

}  // namespace lfem::api
