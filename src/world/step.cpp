// One call of lfem_world_step: the caller's dt split into equal sub-steps (substep.cpp runs
// each), the blow-up test after every sub-step, and the call's guard, which rolls the world back
// bit for bit unless the call succeeds. Under the automatic step a call whose body outran its
// sub-step, or whose state blew up, is redone from the guard's copy with more sub-steps.
#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "common/format.h"
#include "common/thread_pool.h"
#include "world/world.h"

namespace lfem {

// What a run of the call's sub-steps found: the 1-based sub-step at which the state blew up or
// a body outran its sub-step (0 = none), and the smallest stable limit seen.
struct CallAttempt {
    uint32_t blew_up_at = 0, outran_at = 0;
    double limit_seen = 0;
    bool failed() const { return blew_up_at != 0 || outran_at != 0; }
};

namespace {

// The message of a call that cannot be redone (the guard rolls its world back).
[[noreturn]] void fail_unstable(const CallAttempt& a, uint32_t substeps, double h, int attempt, double wanted,
                                uint32_t max_substeps) {
    const std::string where = std::to_string(a.blew_up_at ? a.blew_up_at : a.outran_at) + " of " +
                              std::to_string(substeps) + " (step " + format_seconds(h) + ", stable limit " +
                              format_seconds(a.limit_seen) + ", after " + std::to_string(attempt) +
                              " retries with more sub-steps)";
    throw Error(Status::unstable, (a.blew_up_at ? "the state blew up at sub-step " + where
                                                : "a body stiffened (or a self-contact body sped) beyond the "
                                                  "sub-step at sub-step " +
                                                      where + "; the next retry would need " + format_number(wanted) +
                                                      " sub-steps (max_substeps " + std::to_string(max_substeps) + ")") +
                                      "; the world was rolled back to its state before this call");
}

}  // namespace

// A call's transaction: everything a call may change (each body's state, the world's counters
// and contacts, the profile) is copied when it begins, and put back when the guard goes out of
// scope uncommitted, whatever the way out (an exception, a refusal). Taking the copy may throw
// (out of memory) before anything has changed; putting it back by moving cannot.
class World::CallGuard {
public:
    explicit CallGuard(World& w) : w_(w) {
        // Body by body on the pool (a copy of every node and tet array: with one sub-step a
        // call, as much memory traffic as a fifth of the step), the world's state (its contact
        // list) as one more task of the same round (the last sub-step's choice of pool).
        const uint32_t slots = w.bodies_.slot_count();
        bodies_.resize(slots);
        parallel_for(w.pipeline_.stages.pool, slots + 1, [&](uint32_t i) {
            if (i < slots) bodies_[i] = w.bodies_.slot(i).state;
            else state_ = w.state_;
        });
        profile_ = w.profile_;
        w.events_.begin_call();
    }
    CallGuard(const CallGuard&) = delete;
    CallGuard& operator=(const CallGuard&) = delete;
    // Back to the copy for a retry, keeping it for a later failure (the copies may allocate:
    // if one throws, the guard still puts everything back). The profile keeps counting.
    void restart() {
        for (uint32_t i = 0; i < w_.bodies_.slot_count(); ++i) w_.bodies_.slot(i).state = bodies_[i];
        w_.state_ = state_;
    }
    void commit() { committed_ = true; }
    ~CallGuard() {
        if (!committed_) {
            for (uint32_t i = 0; i < w_.bodies_.slot_count(); ++i) w_.bodies_.slot(i).state = std::move(bodies_[i]);
            w_.state_ = std::move(state_);
            w_.profile_ = profile_;
        }
        w_.events_.end_call();
    }

private:
    World& w_;
    std::vector<BodyState> bodies_;
    WorldState state_;
    Profile profile_{};
    bool committed_ = false;
};

// The sub-steps a call of dt needs: no larger than the fixed time_step, or step_safety times the
// stable limit. Refused up front (Status::invalid_argument) when the fixed step exceeds the limit,
// or when more than max_substeps would be needed.
uint32_t World::substeps_for(double dt, double limit) const {
    double h_allowed;
    if (def_.time_step > 0.0) {
        if (def_.time_step > limit && !def_.allow_unstable_step)
            throw Error(Status::invalid_argument,
                        "fixed time_step " + format_seconds(def_.time_step) + " exceeds the stable limit " + format_seconds(limit) +
                            " of central differences (2/omega_max); use a step below it, 0 "
                            "for automatic, or set allow_unstable_step");
        h_allowed = def_.time_step;
    } else {
        h_allowed = def_.step_safety * limit;
    }
    double count = std::isfinite(h_allowed) ? std::ceil(dt / h_allowed * (1.0 - 1e-12)) : 1.0;
    if (count < 1.0) count = 1.0;
    if (!(count <= double(def_.max_substeps)))  // also a NaN count; count may exceed 2^64
        throw Error(Status::invalid_argument, "dt " + format_seconds(dt) + " needs " + format_number(count) + " sub-steps of at most " +
                                               format_seconds(h_allowed) + ", more than max_substeps " +
                                               std::to_string(def_.max_substeps));
    return uint32_t(count);
}

// The energy of the moving bodies at the start (per body on the pool, added up in slot
// order) into start_energy; returns the floor below which energy changes are too small to call
// a blow-up: m c_d^2 * 1e-12, the energy of a uniform strain of 1e-6.
double World::blow_up_energy_scale(double& start_energy) {
    std::vector<double> body_energy(bodies_.slot_count(), 0.0);
    parallel_for(pipeline_.stages.pool, bodies_.slot_count(), [&](uint32_t j) {  // (the last sub-step's choice)
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

double World::step_limit() const {
    // The automatic step also keeps self-contact bodies' parts from closing too fast per
    // sub-step; a fixed time_step is checked against the stable limit alone.
    return def_.time_step == 0.0 ? std::min(stable_step(), self_contact_step()) : stable_step();
}

// A stable explicit step cannot create energy: kinetic + strain - work stays near the starting
// energy (minus damping). Measured with mid-step velocities it still wobbles, by up to a few
// times the energy that entered the fastest modes (a sudden load near the stable limit), so the
// test allows ten times the energy present or moved. An unstable step multiplies the energy
// every step (by about 47 at 1.5x the limit, 6 at 1.1x), so it passes that bound within a few
// steps of becoming visible. Under the automatic step the limit is re-checked after every
// sub-step (the neo-Hookean limit follows the current shape).
CallAttempt World::run_substeps(uint32_t substeps, double h, double limit, double start_energy, double scale) {
    const bool automatic = def_.time_step == 0.0;
    contact_.begin_attempt();
    events_.begin_attempt();
    CallAttempt a;
    a.limit_seen = limit;
    double work = 0.0, work_flow = 0.0;
    for (uint32_t k = 0; k < substeps && !a.failed(); ++k) {
        double kinetic = 0.0, strain = 0.0, step_work = 0.0, limit_now = a.limit_seen;
        pipeline_.frame_fraction = double(k + 1) / substeps;  // the caller's frames end the call in place
        pipeline_.first_substep = k == 0;
        substep(h, kinetic, strain, step_work);
        if (automatic) limit_now = step_limit();
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
}

// Whatever fails inside (out of memory in detection, say), the caller gets the world as it was
// before the call (the guard) and the failure's own status. A failed attempt is redone from the
// copy up to kMaxRetries times, each with at least twice the sub-steps; a fixed time_step is
// the caller's choice: no retry, and a blow-up fails the call at once.
void World::step(double dt) {
    constexpr int kMaxRetries = 4;
    const bool automatic = def_.time_step == 0.0;
    const double limit = step_limit();
    uint32_t substeps = substeps_for(dt, limit);
    CallGuard call(*this);
    double start_energy = 0.0;
    const double scale = blow_up_energy_scale(start_energy);
    for (int attempt = 0;; ++attempt) {
        const double h = dt / substeps;
        const CallAttempt a = run_substeps(substeps, h, limit, start_energy, scale);
        if (!a.failed()) break;
        const double wanted = std::max(2.0 * substeps, std::ceil(dt / (def_.step_safety * a.limit_seen)));
        if (!automatic || attempt == kMaxRetries || !(wanted <= double(def_.max_substeps)))
            fail_unstable(a, substeps, h, attempt, wanted, def_.max_substeps);
        call.restart();
        substeps = uint32_t(wanted);
    }
    state_.counters.substeps_last_call = substeps;
    finish_call(dt);  // allocates before it changes anything it cannot roll back
    call.commit();
}

// After a call's sub-steps: the caller's frames reach where they were set, the forces applied for
// this call are dropped, bodies at rest fall
// asleep, the call's events are handed out, and the queries' cache follows the bodies.
void World::finish_call(double dt) {
    finish_attachment_frames();
    drop_call_forces();
    update_sleep(dt);
    events_.finish_call(state_.touching, bodies_, state_.contacts);
    moved(pool_.get());  // the queries' boxes of the new positions (once queries are in use)
}

}  // namespace lfem
