// C shim of a body's settings changed after creation (friction, damping, material, filter,
// user data and user id, type): each value checked here before lfem::World sees it
// (world/body_settings.cpp changes them).
#include <cmath>
#include <string>

#include "api/conversions.h"
#include "api/guard.h"
#include "api/handles.h"

using namespace lfem;
using namespace lfem::api;

LFEM_API lfem_status lfem_body_set_friction(lfem_world* world, lfem_body body, double friction) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        require(std::isfinite(friction) && friction >= 0.0, "friction must be finite and >= 0");
        w.set_friction(from_c(body), friction);
    });
}

LFEM_API lfem_status lfem_body_set_damping(lfem_world* world, lfem_body body, double damping) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        require(std::isfinite(damping) && damping >= 0.0, "damping must be finite and >= 0 1/s");
        w.set_damping(from_c(body), damping);
    });
}

LFEM_API lfem_status lfem_body_set_material(lfem_world* world, lfem_body body, double young_modulus,
                                            double poisson_ratio) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        require(std::isfinite(young_modulus) && young_modulus > 0.0, "young_modulus must be finite and > 0 Pa");
        require(std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio < 0.5,
                "poisson_ratio must lie in (-1, 0.5)");
        w.set_material(from_c(body), young_modulus, poisson_ratio);
    });
}

LFEM_API lfem_status lfem_body_set_filter(lfem_world* world, lfem_body body, uint32_t category_bits,
                                          uint32_t mask_bits) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        w.set_filter(from_c(body), category_bits, mask_bits);
    });
}

LFEM_API lfem_status lfem_body_set_user_data(lfem_world* world, lfem_body body, void* user_data) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        w.set_user_data(from_c(body), user_data);
    });
}

LFEM_API lfem_status lfem_body_set_user_id(lfem_world* world, lfem_body body, uint64_t user_id) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        w.set_user_id(from_c(body), user_id);
    });
}

LFEM_API lfem_status lfem_body_set_type(lfem_world* world, lfem_body body, lfem_body_type type) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        require(type == LFEM_BODY_DEFORMABLE || type == LFEM_BODY_STATIC || type == LFEM_BODY_KINEMATIC ||
                    type == LFEM_BODY_RIGID,
                "type " + std::to_string(int(type)) + " is not a body type");
        w.set_type(from_c(body), from_c(type));
    });
}

LFEM_API lfem_status lfem_body_get_type(const lfem_world* world, lfem_body body, lfem_body_type* out) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(out, "out");
        *out = to_c(b.def.type);
    });
}
