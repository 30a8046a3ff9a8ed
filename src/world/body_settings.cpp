// A body's settings changed after creation (lfem_body_set_friction, _set_damping, _set_filter,
// _set_user_data, lfem_body_remove_skin): the handle, its meshes, skins and attachments stay.
// Each wakes the body (a sleeping body would not feel a change of damping or friction), and a
// filter change what it touched as well (its support may no longer hold it).
#include "common/error.h"
#include "world/world.h"

namespace lfem {

void World::set_friction(BodyHandle handle, double friction) {
    Body& body = bodies_.get(handle);
    wake(handle.index);
    body.def.friction = friction;  // each solve takes the pairs' friction from their bodies
}

void World::set_damping(BodyHandle handle, double damping) {
    Body& body = bodies_.get(handle);
    wake(handle.index);
    body.def.damping = damping;
}

void World::set_user_data(BodyHandle handle, void* user_data) { bodies_.get(handle).def.user_data = user_data; }

// Pairs the new filter forbids are not detected again: they end with the next call's events as
// any pair that stops touching does. The contact candidates are searched anew and the queries'
// cache is refreshed (both sort bodies by their filters).
void World::set_filter(BodyHandle handle, uint32_t category_bits, uint32_t mask_bits) {
    Body& body = bodies_.get(handle);
    events_.reserve(bodies_.slot_count());  // the wakes below cannot fail
    wake(handle.index);
    wake_touching(handle.index);
    body.def.category_bits = category_bits, body.def.mask_bits = mask_bits;
    body.geometry_revision += 1;
    moved();
}

void World::remove_skin(BodyHandle handle, uint32_t skin) {
    Body& body = bodies_.get(handle);
    if (skin >= body.skins.size())
        throw Error(Status::invalid_argument, "skin " + std::to_string(skin) + " is out of range (the body has " +
                                                  std::to_string(body.skins.size()) + ")");
    body.skins.erase(body.skins.begin() + skin);  // moves only: nothing allocates or fails
}

}  // namespace lfem
