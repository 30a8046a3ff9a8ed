#include "contact/warm_start.h"

#include <algorithm>
#include <tuple>

namespace lfem {

const ContactRecord* previous_record(const std::vector<ContactRecord>& previous, uint32_t body_a,
                                     uint32_t node, uint32_t body_b) {
    const auto key = std::make_tuple(body_a, node, body_b);
    const auto it = std::lower_bound(previous.begin(), previous.end(), key,
                                     [](const ContactRecord& r, const decltype(key)& k) {
                                         return std::make_tuple(r.body_a, r.node, r.body_b) < k;
                                     });
    return it != previous.end() && it->body_a == body_a && it->node == node && it->body_b == body_b
               ? &*it
               : nullptr;
}

}  // namespace lfem
