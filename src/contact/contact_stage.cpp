#include "contact/contact_stage.h"

#include <algorithm>
#include <iterator>

namespace lfem {

FallenIn ContactStage::detect(const std::vector<ContactRecord>& previous, bool scan_overlaps, Profile& profile,
                              ThreadPool* pool) {
    // Pairs among sleeping and static bodies are not detected again: they are kept as they
    // were (and merged back after the solve), so a sleeping pile keeps its contacts. A sleeping
    // body takes part as a static one: neither moves.
    frozen_.clear();
    if (bodies_.any_asleep()) {
        for (const ContactRecord& r : previous) {
            const ContactBody& a = bodies_.of_slot(r.body_a);
            const ContactBody& b = bodies_.of_slot(r.body_b);
            if (!a.moves && !b.moves && (a.asleep || b.asleep)) frozen_.push_back(r);
        }
    }
    if (!bodies_.may_touch()) {
        detected_.clear();
        detected_runs_.clear();
        return FallenIn{};
    }
    // The list's deepest kept offset: taken after the last sub-step's solve, else (an attempt's
    // first sub-step) from the list.
    const double max_offset = kept_offset_known_ ? kept_offset_ : deepest_kept_offset(previous);
    const FallenIn fallen = detect_node_triangle(bodies_.bodies(), previous, max_offset, scan_overlaps, detection_,
                                                 detected_, detected_runs_, profile, pool);
    detect_features(bodies_.bodies(), detection_.candidates, previous, features_, detected_, detected_runs_, profile,
                    pool);
    return fallen;
}

// Every detected pair is kept, also those at zero force: the next step warm-starts from all of
// them, so redundant pairs (a node of each body pressing the other's face) keep the same split
// of the load from step to step instead of trading it back and forth. Only pairs that carry
// force are contacts.
ContactOutcome ContactStage::solve(std::vector<LinkRecord>& links, const ContactSettings& settings, double h,
                                   std::vector<ContactRecord>& list, Profile& profile, ThreadPool* pool) {
    ContactOutcome out;
    pair_forces_.clear();
    kept_offset_ = 0.0;
    if (!detected_.empty() || !links.empty()) {
        out.solve = solve_contact_multipliers(bodies_.bodies(), bodies_.body_of_slot(), detected_, detected_runs_, links,
                                              settings.max_iterations, settings.relative_tolerance, h, solve_scratch_,
                                              profile, pair_forces_, pool);
        kept_offset_ = out.solve.deepest_kept_offset;
    }
    if (frozen_.empty()) {
        list.swap(detected_);
    } else {
        list.clear();
        std::merge(detected_.begin(), detected_.end(), frozen_.begin(), frozen_.end(), std::back_inserter(list),
                   list_order);
    }
    for (const ContactRecord& r : frozen_) kept_offset_ = std::max(kept_offset_, r.kept_offset());
    kept_offset_known_ = true;
    out.pair_forces = pair_forces_;
    out.frozen = frozen_;
    return out;
}

}  // namespace lfem
