// The memory of contact from one step to the next. A pair found again (the same node against
// the same body) starts from last step's multipliers, so a resting contact starts solved and
// a kept overlap or residual is known; the list of records is ordered by (body_a, node,
// body_b), so the last record of a pair is found by binary search.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_record.h"

namespace lfem {

// The last step's record of node `node` of body_a against body_b (slots), looked up for keys
// that come in ascending order (the nodes of a block of the narrow phase, and per node the
// other bodies): a cursor that only moves forward, O(1) amortised.
class PreviousRecords {
public:
    explicit PreviousRecords(const std::vector<ContactRecord>& previous) : list_(previous) {}
    // Starts at the first record of (body_a, node) or after (one binary search).
    void seek(uint32_t body_a, uint32_t node);
    // The record, or nullptr.
    const ContactRecord* find(uint32_t body_a, uint32_t node, uint32_t body_b);

private:
    const std::vector<ContactRecord>& list_;
    std::size_t next_ = 0;
};

// Gives `record` the multipliers of the pair's last record (newtons): the solve applies them
// first (solve_contact_multipliers.h).
inline void warm_start(const ContactRecord& last, ContactRecord& record) {
    record.lambda_n = last.lambda_n;
    for (int d = 0; d < 3; ++d) record.lambda_t[d] = last.lambda_t[d];
}

}  // namespace lfem
