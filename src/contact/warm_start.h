// The memory of contact from one step to the next. A pair found again (the same node against
// the same body) starts from last step's multipliers, so a resting contact starts solved and
// a kept overlap or residual is known; the list of records is ordered by (body_a, node,
// body_b), so the last record of a pair is found by binary search.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_record.h"

namespace lfem {

// The last step's record of node `node` of body_a against body_b (slots), or nullptr.
const ContactRecord* previous_record(const std::vector<ContactRecord>& previous, uint32_t body_a,
                                     uint32_t node, uint32_t body_b);

// Gives `record` the multipliers of the pair's last record (newtons): the solve applies them
// first (solve_contact_multipliers.h).
inline void warm_start(const ContactRecord& last, ContactRecord& record) {
    record.lambda_n = last.lambda_n;
    for (int d = 0; d < 3; ++d) record.lambda_t[d] = last.lambda_t[d];
}

}  // namespace lfem
