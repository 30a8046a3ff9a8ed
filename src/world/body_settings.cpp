// A body's settings changed after creation (lfem_body_set_friction, _set_damping, _set_filter,
// _set_user_data, lfem_body_remove_skin): the handle, its meshes, skins and attachments stay.
// Each wakes the body (a sleeping body would not feel a change of damping or friction), and a
// filter change what it touched as well (its support may no longer hold it).
#include "common/error.h"
#include "fem/stable_step.h"
#include "rigid/global_rotation.h"
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
// (the Lanczos estimate of the body's highest frequency, as when its mesh was added). Under mass
// scaling the added masses are fitted to the new material as they were to the old one (the
// velocities kept: the mass changes, and so its momentum and kinetic energy). The change of
// strain and kinetic energy at the same shape and velocities is the caller's work.
void World::set_material(BodyHandle handle, double young_modulus, double poisson_ratio) {
    Body& body = bodies_.get(handle);
    if (!body.is_deformable()) throw Error(Status::invalid_argument, "a material belongs to a deformable body");
    Body candidate;  // the new def and masses: all allocation before any change
    candidate.def = body.def;
    candidate.def.young_modulus = young_modulus, candidate.def.poisson_ratio = poisson_ratio;
    candidate.ref = body.ref;
    BodyState state = body.state;
    std::vector<double> v;
    double kinetic_before = 0.0, kinetic_after = 0.0;
    if (body.has_mesh()) {
        const uint32_t n = body.ref.node_count();
        v.resize(3 * std::size_t(n));
        synchronized_velocities(body, v.data());
        fit_step_and_masses(candidate, def_, candidate.ref, pool_.get());
        for (uint32_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) {
                const double vk = v[3 * std::size_t(i) + k];
                kinetic_before += 0.5 * body.ref.mass[i] * vk * vk;
                kinetic_after += 0.5 * candidate.ref.mass[i] * vk * vk;
            }
        update_elastic_forces(candidate, state, pool_.get());
        if (candidate.is_paper()) {  // eq. (2)'s angular momentum with the masses it now has
            const Vec3 c = center_of_mass(candidate.ref.mass.data(), state.x.data(), n);
            const Vec3 L = angular_momentum(candidate.ref.mass.data(), state.x.data(), v.data(), n, c);
            for (int k = 0; k < 3; ++k) state.global.angular_momentum[k] = L[k];
        }
    }
    wake(handle.index);
    // Nothing fails from here.
    state_.counters.external_work += state.strain_energy - body.state.strain_energy + kinetic_after - kinetic_before;
    body.def = candidate.def;
    body.state = std::move(state);
    body.ref.mass.swap(candidate.ref.mass);
    body.ref.stable_step = candidate.ref.stable_step, body.ref.added_mass = candidate.ref.added_mass;
    body.ref.total_mass = candidate.ref.total_mass;
    for (int k = 0; k < 3; ++k) body.ref.com[k] = candidate.ref.com[k];
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
