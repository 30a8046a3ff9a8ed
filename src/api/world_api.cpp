// C shim of the world: validates, translates, and leaves the work to lfem::World.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

#include "api/definitions.h"
#include "api/handles.h"
#include "world/checkpoint.h"

using namespace lfem;
using namespace lfem::api;

namespace lfem::api {

void check_world_def(const lfem_world_def& d) {
    require(d.internal_value == world_def_cookie,
            "def was not initialised by lfem_world_def_default()");
    require_finite(d.gravity, 3, "def->gravity");
    require(std::isfinite(d.time_step) && d.time_step >= 0.0,
            "def->time_step must be finite and >= 0 (0 = automatic)");
    require(std::isfinite(d.step_safety) && d.step_safety > 0.0 && d.step_safety < 1.0,
            "def->step_safety must lie in (0, 1)");
    require(d.contact_iterations >= 1, "def->contact_iterations must be >= 1");
    require(d.thread_count >= 1 && d.thread_count <= 64,
            "def->thread_count must lie in 1..64 (got " + std::to_string(d.thread_count) + ")");
    require(std::isfinite(d.contact_tolerance) && d.contact_tolerance > 0.0,
            "def->contact_tolerance must be finite and > 0");
    require(d.max_substeps >= 1, "def->max_substeps must be >= 1");
    require(d.allow_unstable_step <= 1, "def->allow_unstable_step must be 0 or 1");
    require(std::isfinite(d.mass_scaling_step) && d.mass_scaling_step >= 0.0,
            "def->mass_scaling_step must be finite and >= 0 s (0 = no mass scaling)");
    require(d.enable_sleep <= 1, "def->enable_sleep must be 0 or 1");
    require(std::isfinite(d.sleep_velocity) && d.sleep_velocity >= 0.0, "def->sleep_velocity must be finite and >= 0 m/s");
    require(std::isfinite(d.sleep_time) && d.sleep_time >= 0.0, "def->sleep_time must be finite and >= 0 s");
}

}  // namespace lfem::api

namespace {

// The C record of the world's statistics.
lfem_world_stats stats_of(const World& w) {
    const WorldCounters& c = w.counters();
    lfem_world_stats st{};
    st.time = c.time;
    st.steps = c.steps;
    st.step_size = c.step_size;
    st.stable_step = w.stable_step();
    st.substeps_last_call = c.substeps_last_call;
    st.body_count = w.bodies().live_count();
    st.external_work = c.external_work;
    st.dissipated_energy = c.dissipated_energy;
    st.rotation_drift = c.rotation_drift;
    for (const ContactRecord& r : w.contacts()) st.contact_count += r.active();
    st.solver_iterations = c.solver_iterations;
    st.solver_residual = c.solver_residual;
    st.max_penetration = c.max_penetration;
    const WorldTotals t = w.totals();
    st.kinetic_energy = t.kinetic_energy;
    st.strain_energy = t.strain_energy;
    for (int k = 0; k < 3; ++k) st.linear_momentum[k] = t.linear_momentum[k], st.angular_momentum[k] = t.angular_momentum[k];
    st.energy_error = t.energy_error;
    st.added_mass = t.added_mass;
    st.inverted_tets = t.inverted_tets;
    st.min_jacobian = t.min_jacobian;
    return st;
}

}  // namespace

extern "C" {

LFEM_API lfem_world_def lfem_world_def_default(void) {
    lfem_world_def d{};
    d.gravity[2] = -9.81;
    d.time_step = 0.0;
    d.step_safety = 0.9;
    d.contact_iterations = 200;
    d.thread_count = 1;
    d.contact_tolerance = 1e-3;
    d.max_substeps = 1000000;
    d.allow_unstable_step = 0;
    d.enable_sleep = 0;
    d.sleep_velocity = 0.01;
    d.sleep_time = 0.5;
    d.internal_value = world_def_cookie;
    return d;
}

LFEM_API lfem_status lfem_world_create(const lfem_world_def* def, lfem_world** out) {
    return guard(__func__, [&] {
        require_pointer(def, "def");
        require_pointer(out, "out");
        check_world_def(*def);
        *out = new lfem_world(to_world_def(*def));
    });
}

LFEM_API void lfem_world_destroy(lfem_world* world) { delete world; }

LFEM_API lfem_status lfem_world_step(lfem_world* world, double dt) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        require(std::isfinite(dt) && dt > 0.0, "dt must be finite and > 0, got " + std::to_string(dt));
        w.step(dt);
    });
}

LFEM_API lfem_status lfem_world_save(const lfem_world* world, const char* path) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(path, "path");
#if LFEM_WITH_IO
        save_checkpoint(w, path);
#else
        (void)w;
        unsupported("checkpoint files", "LFEM_WITH_IO");
#endif
    });
}

LFEM_API lfem_status lfem_world_load(const char* path, lfem_world** out) {
    return guard(__func__, [&] {
        require_pointer(path, "path");
        require_pointer(out, "out");
#if LFEM_WITH_IO
        WorldImage image = read_checkpoint(path);
#if !LFEM_WITH_CCD
        for (const Body& b : image.bodies)
            for (const RigidShape& s : b.shapes)
                if (s.type == ShapeType::convex_hull)
                    unsupported(std::string("checkpoint ") + path + " holds a convex-hull shape: hulls (libccd)",
                                "LFEM_WITH_CCD");
#endif
        // The definitions must pass the checks a caller's would: a file is not trusted more.
        try {
            check_world_def(to_c(image.def, world_def_cookie));
            for (const Body& b : image.bodies)
                if (b.generation != 0) check_body_def(to_c(b.def, body_def_cookie));
        } catch (const Error& e) {
            throw Error(Status::io_error, std::string("checkpoint ") + path + ": " + e.what());
        }
        std::unique_ptr<lfem_world> world(new lfem_world(image.def));
        world->world.restore(std::move(image));
        *out = world.release();
#else
        unsupported("checkpoint files", "LFEM_WITH_IO");
#endif
    });
}

LFEM_API lfem_status lfem_world_set_gravity(lfem_world* world, const double gravity[3]) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        require_pointer(gravity, "gravity");
        require_finite(gravity, 3, "gravity");
        w.set_gravity(gravity);
    });
}

LFEM_API lfem_status lfem_world_set_time_step(lfem_world* world, double time_step) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        require(std::isfinite(time_step) && time_step >= 0.0,
                "time_step must be finite and >= 0 (0 = automatic)");
        w.set_time_step(time_step);
    });
}

LFEM_API lfem_status lfem_world_get_stable_step(const lfem_world* world, double* out) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(out, "out");
        *out = w.stable_step();
    });
}

LFEM_API lfem_status lfem_world_get_stats(const lfem_world* world, lfem_world_stats* out) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(out, "out");
        *out = stats_of(w);
    });
}

LFEM_API lfem_status lfem_world_get_profile(const lfem_world* world, lfem_profile* out) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(out, "out");
        lfem_profile p = to_c(w.profile());
        const QueryCounts& q = w.query_counts();
        p.queries = q.queries, p.query_bodies = q.bodies, p.query_primitives = q.primitives;
        p.query_refits = q.refits;
        *out = p;
    });
}

LFEM_API lfem_status lfem_world_reset_profile(lfem_world* world) {
    return guard(__func__, [&] { world_of(world).reset_profile(); });
}

LFEM_API lfem_status lfem_world_get_warning(const lfem_world* world, lfem_warning_kind kind, lfem_warning* out) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        require_pointer(out, "out");
        const Warnings& all = w.counters().warnings;
        const Warning* by_kind[] = {&all.inverted_tets, &all.stays_inverted, &all.fallen_in, &all.unconverged};
        static_assert(sizeof(by_kind) / sizeof(by_kind[0]) == LFEM_WARNING_KIND_COUNT, "a warning without its kind");
        // A C caller may pass any int: read its bits, not an lfem_warning_kind that has no such
        // value (undefined behaviour, which UBSan reports).
        int k = 0;
        static_assert(sizeof(kind) == sizeof(k), "lfem_warning_kind is an int");
        std::memcpy(&k, &kind, sizeof k);
        require(k >= 0 && k < LFEM_WARNING_KIND_COUNT,
                "kind must be an lfem_warning_kind below LFEM_WARNING_KIND_COUNT, got " + std::to_string(k));
        const Warning& x = *by_kind[k];
        *out = lfem_warning{x.count, x.last_time, lfem_body{x.last_slot, x.last_generation}};
    });
}

LFEM_API lfem_status lfem_world_clear_warnings(lfem_world* world) {
    return guard(__func__, [&] { world_of(world).clear_warnings(); });
}

}  // extern "C"
