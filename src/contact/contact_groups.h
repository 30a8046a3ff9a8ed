// Groups of the multiplier solve: pairs that share no movable point cannot affect each other, so
// each group of pairs linked through movable bodies is solved on its own, to its own
// convergence, and the groups side by side on the pool. Static and kinematic bodies do not link
// (their points never move): sixteen cubes on one static floor are sixteen groups. A group's
// result does not depend on the others or on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_body.h"
#include "contact/contact_record.h"
#include "contact/link_constraint.h"

namespace lfem {

struct ContactGroups {
    // The records of group g are order[begin[g] .. begin[g+1]) (indices into the list, in list
    // order), its links link_order[link_begin[g] .. link_begin[g+1]).
    std::vector<uint32_t> begin, order, link_begin, link_order;
    uint32_t count() const { return begin.empty() ? 0 : uint32_t(begin.size() - 1); }

    // Scratch, kept for its capacity.
    struct Run {
        uint32_t first, a, b, group;  // a run of one pair of bodies; a, b: indices of ContactBodies
    };
    std::vector<Run> runs;
    std::vector<uint32_t> parent, group_of_root, next, group_of_link;
    std::vector<uint8_t> movable;
};

// Groups the `record_count` records of a contact list from their runs of one pair of bodies
// (the detection gives them; the records themselves are not read) and the links. Groups are
// numbered in the order of their first body: the pool gives each thread a contiguous range of
// groups as it gives it one of bodies, so a body's group is solved on the thread that predicted
// the body and computed its forces, from that core's cache.
void find_groups(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                 uint32_t record_count, const std::vector<RecordRun>& record_runs,
                 const std::vector<LinkRecord>& links, ContactGroups& out);

}  // namespace lfem
