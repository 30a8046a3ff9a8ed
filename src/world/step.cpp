// One call of lfem_world_step: the caller's dt split into equal sub-steps (substep.cpp runs
// each), a snapshot taken first so that any failure rolls the world back bit for bit, and the
// blow-up test after every sub-step. Under the automatic step a call whose body outran its
// sub-step, or whose state blew up, is redone from the snapshot with more sub-steps.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/error.h"
#include "common/thread_pool.h"
#include "world/world.h"

namespace lfem {
namespace {

std::string seconds(double s) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g s", s);
    return buf;
}

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// What a run of the call's sub-steps found: the 1-based sub-step at which the state blew up or
// a body outran its sub-step (0 = none), and the smallest stable limit seen.
struct Attempt {
    uint32_t blew_up_at = 0, outran_at = 0;
    double limit_seen = 0;
    bool failed() const { return blew_up_at != 0 || outran_at != 0; }
};

// The message of a call that could not be redone (its world already rolled back).
[[noreturn]] void fail_unstable(const Attempt& a, uint32_t substeps, double h, int attempt, double wanted,
                                uint32_t max_substeps) {
    const std::string where = std::to_string(a.blew_up_at ? a.blew_up_at : a.outran_at) + " of " +
                              std::to_string(substeps) + " (step " + seconds(h) + ", stable limit " +
                              seconds(a.limit_seen) + ", after " + std::to_string(attempt) +
                              " retries with more sub-steps)";
    throw Error(Status::unstable, (a.blew_up_at ? "the state blew up at sub-step " + where
                                             : "a body stiffened (or a self-contact body sped) beyond the "
                                               "sub-step at sub-step " +
                                                   where + "; the next retry would need " + number(wanted) +
                                                   " sub-steps (max_substeps " + std::to_string(max_substeps) + ")") +
                                   "; the world was rolled back to its state before this call");
}

}  // namespace

// Everything a call may change: each body's state, the world's counters and contacts, the
// profile. Taking it may throw (out of memory) before anything has changed; restoring it by
// moving cannot.
struct World::Snapshot {
    std::vector<BodyState> bodies;
    WorldState state;
    Profile profile{};
};

// The sub-steps a call of dt needs: no larger than the fixed time_step, or step_safety times the
// stable limit. Refused up front (LFEM_INVALID_ARGUMENT) when the fixed step exceeds the limit,
// or when more than max_substeps would be needed.
uint32_t World::substeps_for(double dt, double limit) const {
    double h_allowed;
    if (def_.time_step > 0.0) {
        if (def_.time_step > limit && !def_.allow_unstable_step)
            throw Error(Status::invalid_argument,
                        "fixed time_step " + seconds(def_.time_step) + " exceeds the stable limit " + seconds(limit) +
                            " of central differences (2/omega_max); use a step below it, 0 "
                            "for automatic, or set allow_unstable_step");
        h_allowed = def_.time_step;
    } else {
        h_allowed = def_.step_safety * limit;
    }
    double count = std::isfinite(h_allowed) ? std::ceil(dt / h_allowed * (1.0 - 1e-12)) : 1.0;
    if (count < 1.0) count = 1.0;
    if (!(count <= double(def_.max_substeps)))  // also a NaN count; count may exceed 2^64
        throw Error(Status::invalid_argument, "dt " + seconds(dt) + " needs " + number(count) + " sub-steps of at most " +
                                               seconds(h_allowed) + ", more than max_substeps " +
                                               std::to_string(def_.max_substeps));
    return uint32_t(count);
}

// The energy of the moving bodies at the start (per body on the pool, added up in slot
// order) into start_energy; returns the floor below which energy changes are too small to call
// a blow-up: m c_d^2 * 1e-12, the energy of a uniform strain of 1e-6.
double World::blow_up_energy_scale(double& start_energy) {
    std::vector<double> body_energy(bodies_.slot_count(), 0.0);
    parallel_for(stages_.pool, bodies_.slot_count(), [&](uint32_t j) {  // (the last sub-step's choice)
        const Body& b = bodies_.slot(j);
        if (b.generation == 0 || !b.is_dynamic() || !b.has_mesh()) return;
        double e = 0.0;
        for (uint32_t i = 0; i < b.ref.node_count(); ++i)
            for (int k = 0; k < 3; ++k) e += 0.5 * b.ref.mass[i] * b.state.v_half[3 * i + k] * b.state.v_half[3 * i + k];
        body_energy[j] = e;
    });
    double scale = 0.0;
    start_energy = 0.0;
    for (uint32_t j = 0; j < bodies_.slot_count(); ++j) {
        const Body& b = bodies_.slot(j);
        if (b.generation == 0 || !b.is_dynamic() || !b.has_mesh()) continue;
        start_energy += b.state.strain_energy + body_energy[j];
        const double cd = dilatational_wave_speed(b.lame(), b.def.density);
        scale += 1e-12 * b.ref.total_mass * cd * cd;
    }
    return scale;
}

void World::step(double dt) {
    // The automatic step also keeps self-contact bodies' parts from closing too fast per
    // sub-step; a fixed time_step is checked against the stable limit alone.
    const bool automatic = def_.time_step == 0.0;
    const auto step_limit = [&] { return automatic ? std::min(stable_step(), self_contact_step()) : stable_step(); };
    const double limit = step_limit();
    uint32_t substeps = substeps_for(dt, limit);

    // The snapshot: body by body on the pool (a copy of every node and tet array: with one
    // sub-step a call, as much memory traffic as a fifth of the step), the world's state (its
    // contact list) as one more task of the same round.
    Snapshot saved;
    const uint32_t slots = bodies_.slot_count();
    saved.bodies.resize(slots);
    parallel_for(stages_.pool, slots + 1, [&](uint32_t i) {
        if (i < slots) saved.bodies[i] = bodies_.slot(i).state;
        else saved.state = state_;
    });
    saved.profile = profile_;
    auto roll_back = [&] {
        for (uint32_t i = 0; i < bodies_.slot_count(); ++i) bodies_.slot(i).state = std::move(saved.bodies[i]);
        state_ = std::move(saved.state);
        profile_ = saved.profile;
    };
    double start_energy = 0.0;
    const double scale = blow_up_energy_scale(start_energy);

    // A stable explicit step cannot create energy: kinetic + strain - work stays near the
    // starting energy (minus damping). Measured with mid-step velocities it still wobbles, by up
    // to a few times the energy that entered the fastest modes (a sudden load near the stable
    // limit), so the test allows ten times the energy present or moved. An unstable step
    // multiplies the energy every step (by about 47 at 1.5x the limit, 6 at 1.1x), so it passes
    // that bound within a few steps of becoming visible. Under the automatic step the limit is
    // re-checked after every sub-step (the neo-Hookean limit follows the current shape).
    const auto run = [&](double h) {
        kept_offset_known_ = false;  // from the list as the attempt finds it
        Attempt a;
        a.limit_seen = limit;
        double work = 0.0, work_flow = 0.0;
        begin_call_events();
        for (uint32_t k = 0; k < substeps && !a.failed(); ++k) {
            double kinetic = 0.0, strain = 0.0, step_work = 0.0, limit_now = a.limit_seen;
            frame_fraction_ = double(k + 1) / substeps;  // the caller's frames end the call in place
            try {
                substep(h, kinetic, strain, step_work);
                if (automatic) limit_now = step_limit();
            } catch (...) {
                // Whatever failed inside (out of memory in detection, say), the caller gets the
                // world as it was before the call, and the failure's own status.
                roll_back();
                in_call_ = false;
                throw;
            }
            work += step_work;
            work_flow += std::fabs(step_work);
            const double balance = kinetic + strain - work;
            if (!std::isfinite(balance) || balance > 10.0 * (start_energy + work_flow) + scale) a.blew_up_at = k + 1;
            if (automatic) {
                a.limit_seen = std::min(a.limit_seen, limit_now);
                if (h > a.limit_seen) a.outran_at = k + 1;
            }
        }
        return a;
    };

    // Retried from the snapshot up to kMaxRetries times, each with at least twice the
    // sub-steps. A fixed time_step is the caller's choice: no retry, and a blow-up fails the
    // call at once.
    constexpr int kMaxRetries = 4;
    in_call_ = true;
    for (int attempt = 0;; ++attempt) {
        const double h = dt / substeps;
        const Attempt a = run(h);
        if (!a.failed()) break;
        const double wanted = std::max(2.0 * substeps, std::ceil(dt / (def_.step_safety * a.limit_seen)));
        if (!automatic || attempt == kMaxRetries || !(wanted <= double(def_.max_substeps))) {
            roll_back();
            in_call_ = false;
            fail_unstable(a, substeps, h, attempt, wanted, def_.max_substeps);
        }
        try {  // back to the snapshot, keeping it for a later failure (copies may allocate)
            for (uint32_t i = 0; i < bodies_.slot_count(); ++i) bodies_.slot(i).state = saved.bodies[i];
            state_ = saved.state;
        } catch (...) {
            roll_back();
            in_call_ = false;
            throw;
        }
        substeps = uint32_t(wanted);
    }
    state_.counters.substeps_last_call = substeps;
    try {  // what follows a call allocates before it changes anything it cannot roll back
        finish_call(dt);
    } catch (...) {
        roll_back();
        in_call_ = false;
        throw;
    }
    in_call_ = false;
}

// After a call's sub-steps: the caller's frames reach where they were set, bodies at rest fall
// asleep, the call's events are handed out, and the queries' cache follows the bodies.
void World::finish_call(double dt) {
    finish_attachment_frames();
    update_sleep(dt);
    finish_call_events();
    moved(pool_.get());  // the queries' boxes of the new positions (once queries are in use)
}

}  // namespace lfem
