#include "contact/warm_start.h"

#include <algorithm>
#include <tuple>

namespace lfem {

namespace {

std::tuple<uint32_t, uint32_t, uint32_t> key_of(const ContactRecord& r) { return {r.body_a, r.node, r.body_b}; }

std::size_t lower_bound_of(const std::vector<ContactRecord>& list, uint32_t body_a, uint32_t node, uint32_t body_b) {
    const auto key = std::make_tuple(body_a, node, body_b);
    return std::size_t(std::lower_bound(list.begin(), list.end(), key,
                                        [](const ContactRecord& r, const decltype(key)& k) { return key_of(r) < k; }) -
                       list.begin());
}

bool is_pair(const ContactRecord& r, uint32_t body_a, uint32_t node, uint32_t body_b) {
    return r.body_a == body_a && r.node == node && r.body_b == body_b;
}

}  // namespace

void PreviousRecords::seek(uint32_t body_a, uint32_t node) { next_ = lower_bound_of(list_, body_a, node, 0); }

const ContactRecord* PreviousRecords::find(uint32_t body_a, uint32_t node, uint32_t body_b) {
    const auto key = std::make_tuple(body_a, node, body_b);
    while (next_ < list_.size() && key_of(list_[next_]) < key) ++next_;
    return next_ < list_.size() && is_pair(list_[next_], body_a, node, body_b) ? &list_[next_] : nullptr;
}

}  // namespace lfem
