#include "world/event_log.h"

#include <algorithm>

namespace lfem {

void EventLog::begin_attempt() {
    pair_tally_.clear();
    broken_.clear();
    sleep_events_.clear();
}

void EventLog::reserve(std::size_t n) {
    sleep_events_.reserve(sleep_events_.size() + n);
    pending_events_.reserve(pending_events_.size() + n);
}

void EventLog::add_body_event(EventType type, BodyHandle body) {
    StepEvent e;
    e.type = type;
    e.a = body;
    (in_call_ ? sleep_events_ : pending_events_).push_back(e);
}

void EventLog::add_contact_end(BodyHandle a, BodyHandle b) {
    StepEvent e;
    e.type = EventType::contact_end;
    e.a = a, e.b = b;
    pending_events_.push_back(e);
}

// The pair's tally, met for the first time in this sub-step or again (references into the map
// stay valid as it grows).
EventLog::PairTally* EventLog::tally_of(uint64_t key, double interval) {
    PairTally* t = &pair_tally_[key];
    if (t->last_substep != substep_serial_) {
        t->last_substep = substep_serial_;
        t->substep_force = 0.0;
        t->interval = interval;
        substep_pairs_.push_back(t);
    }
    return t;
}

void EventLog::tally(Span<const BodyPairForce> solved, Span<const ContactRecord> frozen, Span<const double> h_mid,
                     double h) {
    substep_serial_ += 1;
    substep_pairs_.clear();
    const auto interval = [&](uint32_t a, uint32_t b) {
        const double longer = std::max(h_mid[a], h_mid[b]);
        return longer > 0.0 ? longer : h;
    };
    for (const BodyPairForce& f : solved) {
        PairTally* t = tally_of(body_pair_key(f.slot_a, f.slot_b), interval(f.slot_a, f.slot_b));
        t->substep_force += f.force;
        // The first sub-step of the call in which the pair touched: a BEGIN's impact. (Later
        // sub-steps' approach is no speed of the bodies: a pressed node's predicted motion
        // holds the elastic push of the body behind it, the stress wave the contact stops.)
        if (!t->impact_known) {
            t->impact_known = true;
            t->impact.approach_speed = f.approach_speed;
            std::copy(f.point, f.point + 3, t->impact.point);
            std::copy(f.normal, f.normal + 3, t->impact.normal);
        }
    }
    // The frozen pairs come ordered by node, so a pair's come in runs: its tally is looked up
    // once per run, its force summed in list order.
    uint32_t last_a = UINT32_MAX, last_b = UINT32_MAX;
    PairTally* t = nullptr;
    for (const ContactRecord& r : frozen) {
        if (!r.active()) continue;
        if (r.body_a != last_a || r.body_b != last_b) {
            last_a = r.body_a, last_b = r.body_b;
            t = tally_of(body_pair_key(r.body_a, r.body_b), interval(r.body_a, r.body_b));
        }
        t->substep_force += r.lambda_n;
    }
    for (PairTally* p : substep_pairs_) {
        p->impulse += p->substep_force * p->interval;
        p->max_force = std::max(p->max_force, p->substep_force);
    }
}

void EventLog::finish_call(std::vector<uint64_t>& touching, const BodyRegistry& bodies,
                           Span<const ContactRecord> contacts) {
    std::vector<uint64_t> now, met, active;
    for (const ContactRecord& r : contacts)
        if (r.active()) active.push_back(body_pair_key(r.body_a, r.body_b));
    std::sort(active.begin(), active.end());
    const auto reports = [&](uint32_t slot) { return bodies.live(slot) && bodies.slot(slot).def.report_contacts; };
    met.reserve(pair_tally_.size());
    for (const auto& [key, t] : pair_tally_) {
        met.push_back(key);
        if (t.last_substep == substep_serial_) now.push_back(key);
    }
    std::sort(met.begin(), met.end());
    std::sort(now.begin(), now.end());
    std::vector<uint64_t> keys;
    std::set_union(met.begin(), met.end(), touching.begin(), touching.end(), std::back_inserter(keys));
    std::vector<StepEvent> events;
    events.reserve(2 * keys.size() + pending_events_.size() + sleep_events_.size() + broken_.size());
    for (uint64_t key : keys) {
        const bool before = std::binary_search(touching.begin(), touching.end(), key);
        const bool during = std::binary_search(met.begin(), met.end(), key);
        const bool after = std::binary_search(now.begin(), now.end(), key);
        const auto found = pair_tally_.find(key);
        StepEvent e;
        e.a = bodies.handle_of(uint32_t(key >> 32));
        e.b = bodies.handle_of(uint32_t(key));
        if (found != pair_tally_.end())
            e.normal_impulse = found->second.impulse, e.max_force = found->second.max_force, e.impact = found->second.impact;
        const auto run = std::equal_range(active.begin(), active.end(), key);
        e.contact_count = after ? uint32_t(run.second - run.first) : 0;
        if (during && !before) {
            e.type = EventType::contact_begin;
            events.push_back(e);
        }
        if ((before || during) && !after) {
            e.type = EventType::contact_end;
            events.push_back(e);
        }
        if (before && after && (reports(uint32_t(key >> 32)) || reports(uint32_t(key)))) {
            e.type = EventType::contact_persist;
            events.push_back(e);
        }
    }
    events.insert(events.end(), pending_events_.begin(), pending_events_.end());
    events.insert(events.end(), sleep_events_.begin(), sleep_events_.end());
    events.insert(events.end(), broken_.begin(), broken_.end());
    // Nothing below allocates: the call's results are handed over all at once.
    touching.swap(now);
    events_.swap(events);
    pending_events_.clear();
}

}  // namespace lfem
