#include "world/body_registry.h"

#include <algorithm>
#include <atomic>
#include <string>

#include "common/error.h"

namespace lfem {
namespace {

// Generations come from one process-wide counter, so a handle of another world (foreign) can
// never match a slot's generation in this one: it is detected like a stale handle.
std::atomic<uint32_t> g_next_generation{1};

}  // namespace

uint32_t next_generation() {
    uint32_t g = g_next_generation.fetch_add(1, std::memory_order_relaxed);
    if (g == 0) g = g_next_generation.fetch_add(1, std::memory_order_relaxed);  // wrapped
    return g;
}

void keep_generations_above(uint32_t highest) {
    uint32_t next = g_next_generation.load(std::memory_order_relaxed);
    while (next <= highest &&
           !g_next_generation.compare_exchange_weak(next, highest + 1, std::memory_order_relaxed)) {
    }
}

BodyHandle BodyRegistry::create(const BodyDef& def) {
    uint32_t index;
    if (!free_slots_.empty()) {
        index = free_slots_.back();
    } else {
        slots_.emplace_back();  // may throw bad_alloc before anything changed
        index = uint32_t(slots_.size() - 1);
    }
    Body body;
    body.def = def;
    body.generation = next_generation();
    if (!free_slots_.empty() && free_slots_.back() == index) free_slots_.pop_back();
    slots_[index] = std::move(body);
    return BodyHandle{index, slots_[index].generation};
}

bool BodyRegistry::is_valid(BodyHandle h) const {
    return h.generation != 0 && h.index < slots_.size() && slots_[h.index].generation == h.generation;
}

Body& BodyRegistry::get(BodyHandle h) { return const_cast<Body&>(static_cast<const BodyRegistry&>(*this).get(h)); }

const Body& BodyRegistry::get(BodyHandle h) const {
    if (h.generation == 0 && h.index == 0) throw Error(Status::invalid_handle, "null body handle");
    if (!is_valid(h))
        throw Error(Status::invalid_handle, "body handle {" + std::to_string(h.index) + ", " +
                                             std::to_string(h.generation) +
                                             "} is stale or belongs to another world");
    return slots_[h.index];
}

void BodyRegistry::destroy(BodyHandle h) {
    Body& b = get(h);
    free_slots_.reserve(free_slots_.size() + 1);  // the only allocation: before any change
    b = Body{};                                   // generation 0: the slot is free
    free_slots_.push_back(h.index);
}

uint32_t BodyRegistry::live_count() const {
    uint32_t n = 0;
    for_each([&](const Body&, uint32_t) { ++n; });
    return n;
}

void BodyRegistry::restore(std::vector<Body>&& slots, std::vector<uint32_t>&& free_slots) {
    uint32_t highest = 0;
    for (const Body& b : slots) highest = std::max(highest, b.generation);
    slots_ = std::move(slots);
    free_slots_ = std::move(free_slots);
    keep_generations_above(highest);
}

}  // namespace lfem
