// A big contact group shared by the threads. A pile of soft bodies is one group (every body
// touches the next), which one thread solved alone. Its movable bodies are split into parts
// along the x axis (by the x of each body's first node, then its slot: a rule of the group
// alone, never of the thread count), and its pairs into tasks: the pairs within each part, then
// those between two parts, the pairs between parts in colours such that no two pairs of a colour
// join the same part. A sweep runs the phases in order, the tasks of a phase side by side: the
// tasks of a phase touch disjoint sets of movable points, so the sweep is the same sequence of
// updates however many threads share it (a fixed Gauss-Seidel order), and the results are
// bitwise the same on 1, 2 or 3 threads.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_body.h"
#include "contact/contact_record.h"

namespace lfem {

// A group is split when it has at least this many pairs and kPartitionBodies movable bodies:
// below, one task's sweeps cost less than a round of the pool per phase.
constexpr uint32_t kPartitionPairs = 512;
constexpr uint32_t kPartitionBodies = 8;

struct GroupPartition {
    // Phase p holds tasks phase_begin[p] .. phase_begin[p+1]; task t the group's pairs
    // task_begin[t] .. task_begin[t+1] (positions in the group's reordered range).
    std::vector<uint32_t> phase_begin, task_begin;
    uint32_t phases() const { return phase_begin.empty() ? 0 : uint32_t(phase_begin.size() - 1); }

    // Scratch, kept for its capacity.
    struct Body {
        double x;
        uint32_t slot, index;  // the body's world slot, its index in the ContactBody list
    };
    std::vector<Body> sorted;
    std::vector<uint32_t> part_of_body;  // per ContactBody index (UINT32_MAX: not movable or not here)
    std::vector<uint32_t> task_of_pair, task_of_edge, moved, next, edges, colour_of_edge;
    std::vector<uint64_t> colours_of_part;
};

// Splits a group whose records are order[0 .. count) (list order): reorders `order` so that each
// task's records are contiguous (in list order within a task) and fills `out`. Returns false,
// leaving everything as it was, for a group too small to split (kPartitionPairs,
// kPartitionBodies).
bool partition_group(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     const std::vector<ContactRecord>& records, uint32_t* order, uint32_t count,
                     GroupPartition& out);

}  // namespace lfem
