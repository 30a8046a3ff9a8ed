// The world's own small jobs: gravity, destroying a body (its contacts go with it) and taking
// over a checkpoint. Bodies, meshes, loads, the step and the statistics have files of their
// own (world.h lists them).
#include "world/world.h"

#include <algorithm>

#include "world/checkpoint.h"

namespace lfem {

void World::set_gravity(const double g[3]) {
    events_.reserve(bodies_.slot_count());  // waking cannot fail below
    for (uint32_t i = 0; i < bodies_.slot_count(); ++i) wake(i);
    for (int k = 0; k < 3; ++k) def_.gravity[k] = g[k];
}

void World::destroy_body(BodyHandle h) {
    bodies_.get(h);  // the handle first
    // The only allocation before any change: room for its attachments' slots (end_contacts_of
    // makes room for its events before it changes anything).
    state_.attachments.free_slots.reserve(state_.attachments.free_slots.size() + state_.attachments.slots.size());
    // Its pairs end, reported with the next call's events with its handle as it was (an engine
    // that tracks touching pairs from the events would otherwise keep them); what it held up
    // wakes; its contacts go with it: a query must not read its freed nodes, and a later body in
    // the same slot must not be warm-started from them (found by fuzz_api).
    end_contacts_of(h.index);
    bodies_.destroy(h);
    drop_attachments_of(h.index);
    moved();
}

void World::restore(WorldImage&& image) {
    for (Body& b : image.bodies) derive_reference_data(b, b.ref);
    def_ = image.def;
    bodies_.restore(std::move(image.bodies), std::move(image.free_slots));
    state_ = std::move(image.state);
    uint32_t highest = 0;  // attachment handles of the file stay unique too
    for (const Attachment& a : state_.attachments.slots) highest = std::max(highest, a.generation);
    keep_generations_above(highest);
    moved();
}

}  // namespace lfem
