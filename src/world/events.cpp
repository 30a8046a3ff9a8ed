// Contact events (begin and end per pair of bodies, with the pair's impulse and largest force
// over the call), gathered during a call and handed out after it with the sleep, wake and
// broken-attachment events (lfem_world_get_events).
#include <algorithm>

#include "fem/central_difference.h"
#include "world/world.h"

namespace lfem {
void World::begin_call_events() {
    pair_tally_.clear();
    broken_.clear();
    sleep_events_.clear();
}

// After the sub-step's solve: the bodies that touch are marked (for the commit's contact forces
// and for waking sleepers), and the normal force between every two bodies that touch goes to
// their tally; its impulse is the force times the mid-step interval it changed the velocities
// over (central_difference.h), the same for every body of the step. The solve summed the
// forces of the pairs it solved, each group on its own thread (pair_forces_); the pairs kept
// frozen among sleeping bodies, merged into the list after it, are summed here (their bodies
// never meet a solved pair's), and their kept offsets join the solve's deepest one for the
// next sub-step's detection.
void World::tally_contact_pairs(double h) {
    const double h_mid = mid_step(state_.counters.step_size, h);
    substep_serial_ += 1;
    substep_pairs_.clear();
    const auto tally_of = [&](uint64_t key) {
        PairTally* t = &pair_tally_[key];  // references into the map stay valid as it grows
        if (t->last_substep != substep_serial_) {
            t->last_substep = substep_serial_;
            t->substep_force = 0.0;
            substep_pairs_.push_back(t);
        }
        return t;
    };
    for (const BodyPairForce& f : pair_forces_) {
        scratch_[f.slot_a].touched = scratch_[f.slot_b].touched = true;
        tally_of(body_pair_key(f.slot_a, f.slot_b))->substep_force += f.force;
    }
    // The frozen pairs come ordered by node, so a pair's come in runs: the bodies marked and the
    // pair's tally looked up once per run, its force summed in list order.
    uint32_t last_a = UINT32_MAX, last_b = UINT32_MAX;
    PairTally* t = nullptr;
    for (const ContactRecord& r : frozen_) {
        kept_offset_ = std::max(kept_offset_, r.kept_offset());
        if (!r.active()) continue;
        if (r.body_a != last_a || r.body_b != last_b) {
            last_a = r.body_a, last_b = r.body_b;
            scratch_[r.body_a].touched = scratch_[r.body_b].touched = true;
            t = tally_of(body_pair_key(r.body_a, r.body_b));
        }
        t->substep_force += r.lambda_n;
    }
    kept_offset_known_ = true;
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
            e.type = EventType::contact_begin;
            events.push_back(e);
        }
        if ((before || during) && !after) {
            e.type = EventType::contact_end;
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
