// The contact stage of a sub-step: it owns what contact keeps from one sub-step to the next
// (the detection's candidates and tracks, the solve's arrays, the pairs held among sleeping
// bodies, the deepest kept offset) and runs detection and the multiplier solve over the bodies
// the world lends it. The world's contact list (warm start in, new list out) stays the world's:
// a roll-back and a checkpoint restore it with the bodies.
#pragma once

#include <cstdint>
#include <vector>

#include "common/profile.h"
#include "common/span.h"
#include "common/thread_pool.h"
#include "contact/contact_bodies.h"
#include "contact/contact_record.h"
#include "contact/detect_features.h"
#include "contact/detect_node_triangle.h"
#include "contact/link_constraint.h"
#include "contact/solve_contact_multipliers.h"

namespace lfem {

// The solve's settings (the world's definition).
struct ContactSettings {
    uint32_t max_iterations = 200;
    double relative_tolerance = 1e-3;
};

// What a sub-step's solve leaves for the events and the bodies: its convergence, the normal
// force between every two bodies it solved (each pair once), and the pairs held frozen among
// sleeping bodies (merged into the list; their active records carry force too).
struct ContactOutcome {
    ContactSolveResult solve;  // iterations, residual, penetration, converged (zeros: nothing solved)
    Span<const BodyPairForce> pair_forces;
    Span<const ContactRecord> frozen;
};

class ContactStage {
public:
    // A call's attempt starts: what the last sub-step left of the list (its deepest kept
    // offset) is found from the list itself, which a retry or the caller may have changed.
    void begin_attempt() { kept_offset_known_ = false; }

    // The bodies of this sub-step, added by the world (ContactBodies::add) after clear().
    ContactBodies& bodies() { return bodies_; }

    // Detection between x^n and x* (detect_node_triangle.h) against the last sub-step's list
    // (warm start): pairs among sleeping and static bodies are not detected again but kept
    // frozen as they were. Returns the nodes found fallen in.
    FallenIn detect(const std::vector<ContactRecord>& previous, bool scan_overlaps, Profile& profile,
                    ThreadPool* pool);

    // The multipliers of the detected pairs and of the links (which carry theirs in and out)
    // move x* to x^{n+1}; `list` becomes the new contact list (the detected pairs, every one
    // kept for the next warm start, with the frozen ones merged in order).
    ContactOutcome solve(std::vector<LinkRecord>& links, const ContactSettings& settings, double h,
                         std::vector<ContactRecord>& list, Profile& profile, ThreadPool* pool);

private:
    ContactBodies bodies_;
    std::vector<ContactRecord> detected_, frozen_;  // frozen_: pairs among sleeping bodies
    std::vector<RecordRun> detected_runs_;          // detected_'s runs of one pair of bodies
    std::vector<BodyPairForce> pair_forces_;        // the last solve's
    // The list's deepest kept offset after a solve, for the next sub-step's detection; known
    // only from there to the next sub-step of the same attempt (begin_attempt).
    double kept_offset_ = 0;
    bool kept_offset_known_ = false;
    DetectionScratch detection_;
    FeatureScratch features_;
    ContactSolveScratch solve_scratch_;
};

}  // namespace lfem
