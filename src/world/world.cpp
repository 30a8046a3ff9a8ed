// The world's own small jobs: gravity, destroying a body (its contacts go with it) and taking
// over a checkpoint. Bodies, meshes, loads, the step and the statistics have files of their
// own (world.h lists them).
#include "world/world.h"

#include <algorithm>

#include "world/checkpoint.h"

namespace lfem {

void World::set_gravity(const double g[3]) {
    for (int k = 0; k < 3; ++k) def_.gravity[k] = g[k];
}

void World::destroy_body(lfem_body h) {
    bodies_.destroy(h);
    // The body's contacts go with it: a query must not read its freed nodes, and a later body
    // in the same slot must not be warm-started from them (found by fuzz_api).
    std::vector<ContactRecord>& contacts = state_.contacts;
    contacts.erase(std::remove_if(contacts.begin(), contacts.end(),
                                  [&](const ContactRecord& r) { return r.body_a == h.index || r.body_b == h.index; }),
                   contacts.end());
}

void World::restore(WorldImage&& image) {
    for (Body& b : image.bodies) derive_reference_data(b, b.ref);
    def_ = image.def;
    bodies_.restore(std::move(image.bodies), std::move(image.free_slots));
    state_ = std::move(image.state);
}

}  // namespace lfem
