// The events of a call (lfem_world_get_events): contact begin and end per pair of bodies, with
// the pair's impulse and largest force over the call, sleep and wake, broken attachments. Fed
// during the call (the contact stage's results after each sub-step, the sleeping and the
// attachments' breaks), handed out all at once after a call that succeeded.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/span.h"
#include "contact/contact_record.h"
#include "contact/solve_contact_multipliers.h"
#include "world/body_registry.h"
#include "world/definitions.h"

namespace lfem {

// One event, with the world's handles.
// Where and how fast two bodies came together: the fastest approach of their touching points
// in the first sub-step of a call they touched in (BodyPairForce), the normal from the
// event's body a toward its body b.
struct ImpactPoint {
    double approach_speed = 0;  // m/s
    double point[3] = {0, 0, 0};
    double normal[3] = {0, 0, 0};
};

struct StepEvent {
    EventType type = EventType::contact_begin;
    BodyHandle a{}, b{};
    AttachmentHandle attachment{};
    double normal_impulse = 0;  // N s
    double max_force = 0;       // N
    ImpactPoint impact;         // contact events: the pair's approach in its first sub-step of the call
    uint32_t contact_count = 0; // contact events: the pair's active records at the end of the call
};

class EventLog {
public:
    // The events of the last call that succeeded, in their fixed order.
    const std::vector<StepEvent>& events() const { return events_; }

    // A call begins (its attempts may be redone) and ends (whether it succeeded or not): between
    // calls, a wake belongs to the next call's events.
    void begin_call() { in_call_ = true; }
    void end_call() { in_call_ = false; }
    // An attempt of the call starts from nothing: a redone one's tallies and events are dropped.
    void begin_attempt();

    // Room for n sleep or wake events, so that adding them cannot fail.
    void reserve(std::size_t n);
    void add_sleep(BodyHandle body) { add_body_event(EventType::sleep, body); }
    void add_wake(BodyHandle body) { add_body_event(EventType::wake, body); }
    void add_broken(const StepEvent& e) { broken_.push_back(e); }
    // A pair ended between calls (a body destroyed): reported with the next call's events.
    void add_contact_end(BodyHandle a, BodyHandle b);

    // The sub-step's normal forces between bodies: `solved`, the solve's sums per pair of bodies,
    // and `frozen`, the pairs held among sleeping bodies (each active record's force). A pair's
    // impulse adds its force times the interval it changed the velocities over: the h_mid of
    // its bodies stepped in this sub-step (per slot, 0 for one not stepped; the longer of two,
    // should one have been reset), or the sub-step h when neither was stepped.
    void tally(Span<const BodyPairForce> solved, Span<const ContactRecord> frozen, Span<const double> h_mid, double h);

    // After a call that succeeded: begin for a pair that touched during it and not at the end of
    // the last call (`touching`, which becomes the pairs touching now), end for one that touched
    // (before or during it) and does not at its end, persist for one that touched at both ends
    // when either body reports its contacts (BodyDef::report_contacts), each with the pair's
    // active records in `contacts`; then the wakes between calls, the sleeps and wakes of the
    // call, the broken attachments. Allocates before it changes anything.
    void finish_call(std::vector<uint64_t>& touching, const BodyRegistry& bodies, Span<const ContactRecord> contacts);

private:
    struct PairTally {
        double impulse = 0, max_force = 0;
        ImpactPoint impact;        // the approach of the first sub-step of the call it touched in
        bool impact_known = false;
        double substep_force = 0;  // N, summed over the sub-step being tallied
        double interval = 0;       // s, the sub-step's interval for this pair's impulse
        uint64_t last_substep = 0;
    };
    void add_body_event(EventType type, BodyHandle body);
    PairTally* tally_of(uint64_t key, double interval);

    std::vector<StepEvent> events_;          // of the last call
    std::vector<StepEvent> broken_, sleep_events_, pending_events_;  // pending: wakes between calls
    std::unordered_map<uint64_t, PairTally> pair_tally_;  // by body_pair_key
    std::vector<PairTally*> substep_pairs_;  // the pairs met in the sub-step being tallied
    uint64_t substep_serial_ = 0;
    bool in_call_ = false;
};

}  // namespace lfem
