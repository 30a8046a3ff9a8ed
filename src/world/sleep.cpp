// Sleeping (lfem_world_def.enable_sleep): bodies at rest, and whatever touches or is attached
// to them, stop being stepped as a whole (an island, as Box2D's), and wake when touched by an
// awake body or changed by the caller.
#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>

#include "rigid/rigid_body.h"
#include "world/world.h"

namespace lfem {
namespace {

uint32_t root_of(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// How a body moves, split in two: as a whole (the rigid motion that carries its momentum about
// its centre of mass: V = P / M, omega = I^-1 L), measured by the speed of its farthest node under
// that motion, |V| + |omega| r_max; and its vibration, the mass-weighted RMS speed of what is
// left. A soft body at rest on others keeps ringing faintly at its own frequencies (tens to
// hundreds of hertz: a vibration of 1 cm/s is an amplitude of 10 to 100 um, and it goes
// nowhere), while a rigid drift of 1 cm/s is a centimetre a second: each gets its own measure,
// both held to sleep_velocity.
struct Restlessness {
    double whole = 0, vibration = 0;  // m/s
};

Restlessness restlessness(const std::vector<double>& mass, const std::vector<double>& x, const std::vector<double>& v) {
    const std::size_t n = mass.size();
    double M = 0.0;
    Vec3 c = Vec3::Zero(), V = Vec3::Zero();
    for (std::size_t i = 0; i < n; ++i) {
        M += mass[i];
        c += mass[i] * Vec3(&x[3 * i]);
        V += mass[i] * Vec3(&v[3 * i]);
    }
    Restlessness out;
    if (!(M > 0.0)) return out;
    c /= M, V /= M;
    Vec3 L = Vec3::Zero();
    Mat3 I = Mat3::Zero();
    double r_max = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 r = Vec3(&x[3 * i]) - c;
        L += mass[i] * r.cross(Vec3(&v[3 * i]) - V);
        I += mass[i] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
        r_max = std::max(r_max, r.norm());
    }
    // A tet mesh's inertia is positive definite (its nodes are not all on a line).
    const Vec3 omega = I.ldlt().solve(L);
    double left = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 r = Vec3(&x[3 * i]) - c;
        left += mass[i] * (Vec3(&v[3 * i]) - V - omega.cross(r)).squaredNorm();
    }
    out.whole = V.norm() + omega.norm() * r_max;
    out.vibration = std::sqrt(left / M);
    return out;
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

// After a sub-step's solve: a sleeping body that an awake, moving body presses wakes, and with
// it its whole island (the sleeping bodies joined to it by contacts and attachments), as it fell
// asleep: a pile touched on top wakes at once, not one layer a sub-step. The woken take part from
// the next sub-step on; in this one they held like static bodies.
void World::wake_touched_sleepers() {
    if (!contact_.bodies().any_asleep()) return;  // no body fell asleep during a call: none to wake
    const auto asleep = [&](uint32_t i) { return bodies_.slot(i).state.asleep != 0; };
    const auto pressing = [&](uint32_t i) { return !asleep(i) && !bodies_.slot(i).is_static(); };
    std::vector<uint32_t> touched;
    for (const ContactRecord& r : state_.contacts) {
        if (!r.active()) continue;
        if (asleep(r.body_a) && pressing(r.body_b)) touched.push_back(r.body_a);
        if (asleep(r.body_b) && pressing(r.body_a)) touched.push_back(r.body_b);
    }
    if (touched.empty()) return;
    const uint32_t n = bodies_.slot_count();
    std::vector<uint32_t> parent(n);
    for (uint32_t i = 0; i < n; ++i) parent[i] = i;
    const auto join = [&](uint32_t a, uint32_t b) {
        if (asleep(a) && asleep(b)) parent[root_of(parent, a)] = root_of(parent, b);
    };
    for (const ContactRecord& r : state_.contacts)
        if (r.active()) join(r.body_a, r.body_b);
    for (const Attachment& a : state_.attachments.slots)
        if (a.generation != 0 && a.target != kFrameTarget) join(a.body, a.target);
    std::vector<uint8_t> woken(n, 0);
    for (uint32_t i : touched) woken[root_of(parent, i)] = 1;
    for (uint32_t i = 0; i < n; ++i)  // in slot order: the wake events too
        if (bodies_.live(i) && asleep(i) && woken[root_of(parent, i)]) wake(i);
}

// After a call: each awake body's timer runs while its fastest node is slower than
// sleep_velocity; an island (bodies linked by active contacts and attachments) whose every
// body has run sleep_time falls asleep together. Touching a moving kinematic body keeps a
// body awake.
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
    // A body held by the caller's frame sleeps as one held by a static body: moving the frame
    // (lfem_attachment_set_frame) wakes it.
    for (const Attachment& a : state_.attachments.slots)
        if (a.generation != 0 && a.target != kFrameTarget) join(a.body, a.target);
    std::vector<double> v;
    for (uint32_t i = 0; i < n; ++i) {
        if (!dynamic(i)) continue;
        Body& b = bodies_.slot(i);
        if (b.state.asleep) continue;
        v.resize(b.state.x.size());
        synchronized_velocities(b, v.data());
        const Restlessness r = restlessness(b.ref.mass, b.state.x, v);
        const bool prescribed = std::find(b.node_mode.begin(), b.node_mode.end(), NodeMode::prescribed) != b.node_mode.end();
        const bool still = r.whole < def_.sleep_velocity && r.vibration < def_.sleep_velocity && !prescribed &&
                           !keep_awake[i] && b.def.enable_sleep;
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
