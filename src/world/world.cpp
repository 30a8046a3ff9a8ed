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
    const auto involves = [&](uint64_t key) { return uint32_t(key >> 32) == h.index || uint32_t(key) == h.index; };
    std::vector<uint64_t>& touching = state_.touching;
    // The only allocations, before any change: room for its attachments' slots, and for the
    // events its going makes (an end for each pair it touched, a wake for each body it held).
    state_.attachments.free_slots.reserve(state_.attachments.free_slots.size() + state_.attachments.slots.size());
    events_.reserve(bodies_.slot_count() + std::size_t(std::count_if(touching.begin(), touching.end(), involves)));
    // Its pairs end, reported with the next call's events (an engine that tracks touching pairs
    // from the events would otherwise keep them), with its handle as it was; what it held up wakes.
    for (uint64_t key : touching)
        if (involves(key))
            events_.add_contact_end(bodies_.handle_of(uint32_t(key >> 32)), bodies_.handle_of(uint32_t(key)));
    wake_touching(h.index);
    bodies_.destroy(h);
    drop_attachments_of(h.index);
    touching.erase(std::remove_if(touching.begin(), touching.end(), involves), touching.end());
    // The body's contacts go with it: a query must not read its freed nodes, and a later body
    // in the same slot must not be warm-started from them (found by fuzz_api).
    std::vector<ContactRecord>& contacts = state_.contacts;
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [&](const ContactRecord& r) { return r.body_a == h.index || r.body_b == h.index; }),
                   contacts.end());
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
