// Contact events (begin and end per pair of bodies, with the pair's impulse and largest force
// over the call), gathered during a call and handed out after it with the sleep, wake and
// broken-attachment events (lfem_world_get_events).
#include <algorithm>

#include "fem/central_difference.h"
#include "world/world.h"

namespace lfem {
namespace {

uint64_t pair_key(uint32_t a, uint32_t b) { return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a; }

}  // namespace

void World::begin_call_events() {
    pair_tally_.clear();
    broken_.clear();
    sleep_events_.clear();
}

// After the sub-step's solve, in one pass over the list: its deepest kept offset is taken for
// the next sub-step's detection, the bodies that touch are marked (for the commit's contact
// forces and for waking sleepers), and the normal force of every active
// pair is summed per body pair; its impulse is the force times the mid-step interval it changed
// the velocities over (central_difference.h), the same for every body of the step.
void World::tally_contact_pairs(double h) {
    const double h_mid = mid_step(state_.counters.step_size, h);
    substep_serial_ += 1;
    // The records come ordered by node, so a pair's come in runs: the bodies marked and the
    // pair's tally looked up once per run, its force of this sub-step summed in its tally, its
    // impulse and peak taken after.
    substep_pairs_.clear();
    uint32_t last_a = UINT32_MAX, last_b = UINT32_MAX;
    uint64_t key = UINT64_MAX;
    PairTally* t = nullptr;
    double deepest = 0.0;
    for (const ContactRecord& r : state_.contacts) {
        deepest = std::max(deepest, r.kept_offset());  // for the next sub-step's detection
        if (!r.active()) continue;
        if (r.body_a != last_a || r.body_b != last_b) {
            last_a = r.body_a, last_b = r.body_b;
            scratch_[r.body_a].touched = scratch_[r.body_b].touched = true;
            const uint64_t k = pair_key(r.body_a, r.body_b);
            if (k != key) {
                key = k;
                t = &pair_tally_[key];  // references into the map stay valid as it grows
                if (t->last_substep != substep_serial_) {
                    t->last_substep = substep_serial_;
                    t->substep_force = 0.0;
                    substep_pairs_.push_back(t);
                }
            }
        }
        t->substep_force += r.lambda_n;
    }
    kept_offset_ = deepest, kept_offset_known_ = true;
    for (PairTally* p : substep_pairs_) {
        p->impulse += p->substep_force * h_mid;
        p->max_force = std::max(p->max_force, p->substep_force);
    }
}

// After a call that succeeded: begin for a pair that touched during it and not at the end of
// the last call, end for one that touched (before or during it) and does not at its end.
void World::finish_call_events() {
    std::vector<uint64_t> now, met;
    met.reserve(pair_tally_.size());
    for (const auto& [key, t] : pair_tally_) {
        met.push_back(key);
        if (t.last_substep == substep_serial_) now.push_back(key);
    }
    std::sort(met.begin(), met.end());
    std::sort(now.begin(), now.end());
    std::vector<uint64_t> keys;
    std::set_union(met.begin(), met.end(), state_.touching.begin(), state_.touching.end(), std::back_inserter(keys));
    std::vector<StepEvent> events;
    events.reserve(2 * keys.size() + pending_events_.size() + sleep_events_.size() + broken_.size());
    for (uint64_t key : keys) {
        const bool before = std::binary_search(state_.touching.begin(), state_.touching.end(), key);
        const bool during = std::binary_search(met.begin(), met.end(), key);
        const bool after = std::binary_search(now.begin(), now.end(), key);
        const auto found = pair_tally_.find(key);
        StepEvent e;
        e.a = bodies_.handle_of(uint32_t(key >> 32));
        e.b = bodies_.handle_of(uint32_t(key));
        if (found != pair_tally_.end()) e.normal_impulse = found->second.impulse, e.max_force = found->second.max_force;
        if (during && !before) {
            e.type = LFEM_EVENT_CONTACT_BEGIN;
            events.push_back(e);
        }
        if ((before || during) && !after) {
            e.type = LFEM_EVENT_CONTACT_END;
            events.push_back(e);
        }
    }
    events.insert(events.end(), pending_events_.begin(), pending_events_.end());
    events.insert(events.end(), sleep_events_.begin(), sleep_events_.end());
    events.insert(events.end(), broken_.begin(), broken_.end());
    // Nothing below allocates: the call's results are handed over all at once.
    state_.touching.swap(now);
    events_.swap(events);
    pending_events_.clear();
}

}  // namespace lfem
