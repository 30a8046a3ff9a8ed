// The bodies of a world in generation-checked slots: handles {index, generation} that stay
// answerable after their body is gone (stale) or when they come from another world (foreign),
// as in Box2D v3. Every loop over the bodies runs in slot order, so results are deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include "world/body.h"
#include "world/definitions.h"

namespace lfem {

// Handles' generations come from one process-wide counter (bodies and attachments alike), so a
// handle of another world can never match a slot here. keep_generations_above(g): after a
// checkpoint is loaded, no generation up to g is handed out again.
uint32_t next_generation();
void keep_generations_above(uint32_t highest);

class BodyRegistry {
public:
    // A new body (generation from the process-wide counter) in a free slot or a new one.
    BodyHandle create(const BodyDef& def);
    // Frees the body's slot (throws Error(Status::invalid_handle) for a bad handle).
    void destroy(BodyHandle handle);
    bool is_valid(BodyHandle handle) const;
    // The body of a handle; throws Error(Status::invalid_handle) for a stale, foreign or null one.
    Body& get(BodyHandle handle);
    const Body& get(BodyHandle handle) const;
    uint32_t live_count() const;

    // Slots by index, live or free (generation 0), in the order every loop uses.
    uint32_t slot_count() const { return uint32_t(slots_.size()); }
    Body& slot(uint32_t i) { return slots_[i]; }
    const Body& slot(uint32_t i) const { return slots_[i]; }
    bool live(uint32_t i) const { return slots_[i].generation != 0; }
    BodyHandle handle_of(uint32_t i) const { return BodyHandle{i, slots_[i].generation}; }
    // f(body, slot) for the live bodies in slot order.
    template <class F>
    void for_each(F&& f) const {
        for (uint32_t i = 0; i < slots_.size(); ++i)
            if (slots_[i].generation != 0) f(slots_[i], i);
    }

    // Checkpoints: the slots and the free list as they are, and taken over from a file (the
    // process-wide generation counter moves beyond the loaded generations, so that no handle of
    // a destroyed body can become valid again).
    const std::vector<Body>& slots() const { return slots_; }
    const std::vector<uint32_t>& free_slots() const { return free_slots_; }
    void restore(std::vector<Body>&& slots, std::vector<uint32_t>&& free_slots);

private:
    std::vector<Body> slots_;  // generation 0 = a free slot
    std::vector<uint32_t> free_slots_;
};

}  // namespace lfem
