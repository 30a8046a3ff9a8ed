// A body's settings changed after creation (lfem_body_set_friction, _set_damping, _set_filter,
// _set_user_data, lfem_body_remove_skin): the handle, its meshes, skins and attachments stay.
// Each wakes the body (a sleeping body would not feel a change of damping or friction), and a
// filter change what it touched as well (its support may no longer hold it).
#include "common/error.h"
#include "fem/stable_step.h"
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

// A new material: the elastic forces at the nodes as they are, and the stable step that follows
// (the Lanczos estimate of the body's highest frequency, as when its mesh was added). The
// change of strain energy at the same shape is the caller's work.
void World::set_material(BodyHandle handle, double young_modulus, double poisson_ratio) {
    Body& body = bodies_.get(handle);
    if (!body.is_deformable()) throw Error(Status::invalid_argument, "a material belongs to a deformable body");
    if (def_.mass_scaling_step > 0.0 && body.has_mesh())
        throw Error(Status::invalid_argument, "under mass scaling a body keeps its material (its added masses were "
                                              "fitted to it)");
    const BodyDef was = body.def;
    BodyState state = body.state;  // the candidate: all allocation before any change
    double stable_step = body.ref.stable_step;
    body.def.young_modulus = young_modulus, body.def.poisson_ratio = poisson_ratio;  // read by the kernels below
    try {
        if (body.has_mesh()) {
            stable_step = 2.0 / estimate_stable_step(element_mesh(body.ref), body.lame(), pool_.get()).omega_max;
            update_elastic_forces(body, state, pool_.get());
        }
        wake(handle.index);
    } catch (...) {
        body.def = was;
        throw;
    }
    // Nothing fails from here.
    state_.counters.external_work += state.strain_energy - body.state.strain_energy;
    body.state = std::move(state);
    body.ref.stable_step = stable_step;
}

void World::set_sleep_allowed(BodyHandle handle, bool allowed) {
    Body& body = bodies_.get(handle);
    if (!allowed) wake(handle.index);
    body.def.enable_sleep = allowed;
    if (!allowed) body.state.sleep_timer = 0.0;
}

void World::set_user_data(BodyHandle handle, void* user_data) { bodies_.get(handle).def.user_data = user_data; }

void World::set_user_id(BodyHandle handle, uint64_t user_id) { bodies_.get(handle).def.user_id = user_id; }

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
