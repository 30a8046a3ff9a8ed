// Sleeping (lfem_world_def.enable_sleep): bodies at rest, and whatever touches or is attached
// to them, stop being stepped as a whole (an island, as Box2D's), and wake when touched by an
// awake body or changed by the caller.
#include <algorithm>
#include <cmath>

#include "rigid/rigid_body.h"
#include "world/world.h"

namespace lfem {
namespace {

uint32_t root_of(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

void World::wake(uint32_t slot) {
    if (slot >= bodies_.slot_count() || !bodies_.live(slot)) return;
    BodyState& s = bodies_.slot(slot).state;
    s.sleep_timer = 0.0;
    if (!s.asleep) return;
    events_.add_wake(bodies_.handle_of(slot));  // first: it may throw
    s.asleep = 0;
}

// A kinematic body's change of velocity wakes what touches it; a change of gravity, everything.
void World::wake_touching(uint32_t slot) {
    for (const ContactRecord& r : state_.contacts) {
        if (r.body_a == slot) wake(r.body_b);
        if (r.body_b == slot) wake(r.body_a);
    }
}

// After a sub-step's solve: a sleeping body that an awake, moving body presses wakes (it takes
// part from the next sub-step on; in this one it held like a static body).
void World::wake_touched_sleepers() {
    if (!contact_.bodies().any_asleep()) return;  // no body fell asleep during a call: none to wake
    for (const ContactRecord& r : state_.contacts) {
        if (!r.active()) continue;
        const Body& a = bodies_.slot(r.body_a);
        const Body& b = bodies_.slot(r.body_b);
        if (a.state.asleep && !b.state.asleep && !b.is_static()) wake(r.body_a);
        if (b.state.asleep && !a.state.asleep && !a.is_static()) wake(r.body_b);
    }
}

// After a call: each awake body's timer runs while its fastest node is slower than
// sleep_velocity; an island (bodies linked by active contacts and attachments) whose every
// body has run sleep_time falls asleep together. Touching a moving kinematic body, or being
// held by the caller's frame, keeps a body awake.
void World::update_sleep(double dt) {
    if (!def_.enable_sleep) return;
    const uint32_t n = bodies_.slot_count();
    events_.reserve(n);  // before any body changes
    std::vector<uint32_t> parent(n);
    std::vector<uint8_t> keep_awake(n, 0);
    for (uint32_t i = 0; i < n; ++i) parent[i] = i;
    auto dynamic = [&](uint32_t i) {
        const Body& b = bodies_.slot(i);
        return bodies_.live(i) && b.is_dynamic() && b.has_mesh();
    };
    auto join = [&](uint32_t a, uint32_t b) {
        if (dynamic(a) && dynamic(b)) parent[root_of(parent, a)] = root_of(parent, b);
        else if (dynamic(a) && bodies_.slot(b).is_kinematic() && bodies_.slot(b).moves_kinematically()) keep_awake[a] = 1;
        else if (dynamic(b) && bodies_.slot(a).is_kinematic() && bodies_.slot(a).moves_kinematically()) keep_awake[b] = 1;
    };
    for (const ContactRecord& r : state_.contacts)
        if (r.active()) join(r.body_a, r.body_b);
    for (const Attachment& a : state_.attachments.slots) {
        if (a.generation == 0) continue;
        if (a.target == kFrameTarget) keep_awake[a.body] = 1;  // the caller may move it any frame
        else join(a.body, a.target);
    }
    for (uint32_t i = 0; i < n; ++i) {
        if (!dynamic(i)) continue;
        Body& b = bodies_.slot(i);
        if (b.state.asleep) continue;
        double fastest = 0.0;
        for (std::size_t k = 0; k < b.state.v_half.size(); k += 3)
            fastest = std::max(fastest, Vec3(&b.state.v_half[k]).norm());
        const bool prescribed = std::find(b.node_mode.begin(), b.node_mode.end(), NodeMode::prescribed) != b.node_mode.end();
        const bool still = fastest < def_.sleep_velocity && !prescribed && !keep_awake[i] && b.def.enable_sleep;
        b.state.sleep_timer = still ? b.state.sleep_timer + dt : 0.0;
    }
    // An island sleeps when none of its bodies is awake and restless (a sleeping member, woken
    // this call or not, counts as rested).
    std::vector<uint8_t> restless(n, 0);
    for (uint32_t i = 0; i < n; ++i)
        if (dynamic(i) && !bodies_.slot(i).state.asleep && bodies_.slot(i).state.sleep_timer < def_.sleep_time)
            restless[root_of(parent, i)] = 1;
    for (uint32_t i = 0; i < n; ++i) {
        if (!dynamic(i) || restless[root_of(parent, i)]) continue;
        Body& b = bodies_.slot(i);
        if (b.state.asleep) continue;
        // Its kinetic energy goes to the dissipated energy: the balance stays closed.
        double kinetic = 0.0;
        add_kinetic_energy(b, kinetic);
        state_.counters.dissipated_energy += kinetic;
        std::fill(b.state.v_half.begin(), b.state.v_half.end(), 0.0);
        b.state.h_last = 0.0;  // the velocities are the synchronized ones: zero
        if (b.is_rigid()) std::fill(std::begin(b.state.global.velocity), std::end(b.state.global.velocity), 0.0),
                          std::fill(std::begin(b.state.global.angular_momentum), std::end(b.state.global.angular_momentum), 0.0);
        b.state.asleep = 1;
        events_.add_sleep(bodies_.handle_of(i));
    }
}

}  // namespace lfem
