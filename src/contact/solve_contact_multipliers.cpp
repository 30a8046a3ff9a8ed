#include "contact/solve_contact_multipliers.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/profile.h"
#include "common/thread_pool.h"
#include "contact/constraint_pair.h"
#include "contact/contact_groups.h"
#include "contact/link_constraint.h"

namespace lfem {
namespace {

// Velocity of point i of body b over the last step, along axis k.
double last_velocity(const ContactBody& b, uint32_t i, int k, double h) {
    return b.v_last ? b.v_last[3 * i + k] : (b.x[3 * i + k] - b.x_start[3 * i + k]) / h;
}

// The largest relative motion of record r's pair over a step of h: the relative velocity at
// the start of the step (last step's mid-step velocities) times h; not the predicted motion,
// which under a resting load is mostly the sag that contact undoes.
double pair_motion(const ContactBody& a, const ContactBody& b, const ContactRecord& r, double h) {
    const double w[3] = {1.0 - r.t1 - r.t2, r.t2, r.t1};
    double motion = 0.0;
    for (int d = 0; d < 3; ++d) {
        double rel = a.moves ? last_velocity(a, r.node, d, h) : 0.0;  // a static body's: 0
        if (r.shape != UINT32_MAX)
            rel -= (r.point_end[d] - r.point_start[d]) / h;  // the shape's surface moves rigidly
        else if (b.moves)
            for (int v = 0; v < 3; ++v) rel -= w[v] * last_velocity(b, r.triangle[v], d, h);
        motion = std::max(motion, std::fabs(rel) * h);
    }
    return motion;
}

// The stopping tolerance of one group, in physical units: relative_tolerance of the motion the
// solve has to deal with in this sub-step, the larger of two. The largest relative motion of
// its pairs (`motion`, the records' largest pair_motion, here joined by the links' in
// links[order[0 .. count)]): what an impact or a slide moves. And `load`, how far gravity and
// the node forces move a free node of its bodies in the sub-step (ContactBody::load_motion):
// what a resting contact undoes every sub-step. Left by a sweep, 1e-3 of that is a velocity of
// 1e-3 g h, 1e-5 m/s at a millisecond's sub-step, below what anything in the scene shows or
// feels; asked for less (the rule was once 1e-9 of an edge at rest), a pile of soft cubes ran
// the solve to its cap every sub-step chasing rounding. At least 1e-9 of its finest boundary
// edge (`length`) when nothing moves and nothing loads it. Each group's own: a body falling
// fast elsewhere neither loosens nor tightens the solve of a resting pile.
double stopping_tolerance(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                          const std::vector<LinkRecord>& links, const uint32_t* order, uint32_t count, double motion,
                          double load, double length, double relative_tolerance, double h) {
    for (uint32_t k = 0; k < count; ++k) {  // a held node: its own motion against its target's
        const LinkRecord& l = links[order[k]];
        const ContactBody& a = bodies[body_of_slot[l.body_a]];
        for (int d = 0; d < 3; ++d) motion = std::max(motion, std::fabs(last_velocity(a, l.node, d, h)) * h);
        length = std::min(length, a.edge_length);
        load = std::max(load, a.load_motion);
    }
    return std::max(relative_tolerance * std::max(motion, load), 1e-9 * length);
}

// What one group's solve reports; CPU time in ticks(), so that the solve's wall time can be split
// between its normal and friction parts however the groups ran.
struct GroupResult {
    ContactSolveResult solve;
    uint64_t ticks = 0, friction_ticks = 0;
    bool friction = false;  // some pair of the group has friction
    double tolerance = 0;   // its stopping tolerance (stopping_tolerance)
    double deepest_kept_offset = 0;  // of its records
    uint32_t pair_forces = 0;  // how many BodyPairForces it left in its range of the scratch
    uint64_t updates = 0;      // constraint updates: its pairs and links times its sweeps
};

// A group's links: links[order[0 .. count)] with their pairs.
struct GroupLinks {
    std::vector<LinkRecord>& links;
    std::vector<LinkPair>& pairs;
    const uint32_t* order;
    uint32_t count;
};

// The warm start: the multipliers the pairs carry in (the records' last step's, for the same
// node and body) are applied first, so a resting contact starts converged. Returns whether some
// pair of the group has friction.
bool warm_start_group(ConstraintPair* pairs, uint32_t count, const GroupLinks& held) {
    for (uint32_t k = 0; k < held.count; ++k) warm_start_link(held.links[held.order[k]], held.pairs[held.order[k]]);
    bool any_friction = false;
    for (uint32_t k = 0; k < count; ++k) {
        ConstraintPair& q = pairs[k];
        if (!(q.H > 0.0)) {
            q.lambda_n = 0.0, q.lambda_t.setZero();
            continue;
        }
        q.lambda_t -= q.n * q.n.dot(q.lambda_t);  // the normal may have turned since: the tangential part
        if (q.mu == 0.0) q.lambda_t.setZero();
        apply(q, q.lambda_n * q.n + q.lambda_t);
        any_friction = any_friction || q.mu > 0.0;
    }
    return any_friction;
}

// One sweep's normal updates: lambda_n <- max(0, lambda_n - (g - g_target)/H), the clamp the
// paper's tension release. Returns the sweep's measure of change (solve_group).
double normal_pass(ConstraintPair* pairs, uint32_t count, bool first) {
    double largest = 0.0;
    for (uint32_t k = 0; k < count; ++k) {
        ConstraintPair& q = pairs[k];
        if (!(q.H > 0.0)) continue;  // both sides immovable: nothing to solve
        const double g = q.n.dot(relative_position(q)) + q.offset;
        const double lambda_n = std::max(0.0, q.lambda_n - g / q.H);
        const double moved = apply(q, (lambda_n - q.lambda_n) * q.n);
        largest = std::max(largest, first ? moved : lambda_n > 0.0 || g < 0.0 ? std::fabs(g - q.seen_gap) : 0.0);
        q.seen_gap = g;
        q.lambda_n = lambda_n;
    }
    return largest;
}

// One sweep's friction updates: the tangential slip of the node relative to the triangle over
// the step, cancelled by the stick trial, then returned onto the Coulomb cone (eq. 7).
double friction_pass(ConstraintPair* pairs, uint32_t count, bool first) {
    double largest = 0.0;
    for (uint32_t k = 0; k < count; ++k) {
        ConstraintPair& q = pairs[k];
        if (!(q.H > 0.0) || q.mu == 0.0) continue;  // frictionless: no tangential work
        Vec3 slip = relative_motion(q);
        slip -= q.n * q.n.dot(slip);
        const Vec3 lt_old = q.lambda_t;
        Vec3 lt = lt_old - slip / q.H;
        // Squared: the square root only for a pair beyond the cone (its latency held up the sweep).
        const double cap = q.mu * q.lambda_n, norm2 = lt.squaredNorm();
        q.sliding = norm2 > cap * cap;
        if (q.sliding) lt *= cap / std::sqrt(norm2);  // norm2 > 0: above cap^2 >= 0
        const double moved = apply(q, lt - lt_old);
        largest = std::max(largest, first ? moved : q.lambda_n > 0.0 ? (slip - q.seen_slip).cwiseAbs().maxCoeff() : 0.0);
        q.seen_slip = slip;
        q.lambda_t = lt;
    }
    return largest;
}

// Projected Gauss-Seidel over one group's records (records[order[k]], k < count, in list
// order; pairs[k] is the pair of records[order[k]]): the warm start, then sweeps until the
// positions have settled: until no pair's gap (an active or penetrating pair's) and no tangential
// slip (of a pair that carries force) changed by more than `tolerance` from one sweep to the
// next, each measured where the sweep comes to the pair, before its update (the first sweep:
// until no update moves a point by more than it). The net change, not each update's move: where
// two nearly parallel constraints share a spot (a node of each body pressing the other's face,
// both with friction) each sweep's updates push the spot back and forth by the same amount while
// it stays where it is, and a rule on the moves never stopped.
void solve_group(std::vector<ContactRecord>& records, ConstraintPair* pairs, const uint32_t* order, uint32_t count,
                 const GroupLinks& held, uint32_t max_iterations, double tolerance, GroupResult& out) {
    const uint64_t group_start = ticks();
    ContactSolveResult& result = out.solve;
    const bool any_friction = warm_start_group(pairs, count, held);
    // Each sweep: the normal updates of every pair, the links, then the friction updates of the
    // pairs that have friction (in the same sweep, as the paper's forward increment asks; in two
    // passes so that each part's time can be measured on its own).
    out.friction = any_friction && max_iterations > 0;  // a friction pass will run
    for (uint32_t sweep = 0; sweep < max_iterations; ++sweep) {
        double largest = normal_pass(pairs, count, sweep == 0);
        for (uint32_t k = 0; k < held.count; ++k)
            largest = std::max(largest, update_link(held.links[held.order[k]], held.pairs[held.order[k]]));
        if (any_friction) {
            const uint64_t start = ticks();
            largest = std::max(largest, friction_pass(pairs, count, sweep == 0));
            out.friction_ticks += ticks() - start;
        }
        result.iterations = sweep + 1;
        result.residual = largest;
        out.updates += count + held.count;
        if (largest <= tolerance) break;
    }
    // The multipliers back into the records, with what the next step's detection reads.
    for (uint32_t k = 0; k < count; ++k) {
        ContactRecord& r = records[order[k]];
        const ConstraintPair& q = pairs[k];
        r.lambda_n = q.lambda_n;
        for (int d = 0; d < 3; ++d) r.lambda_t[d] = q.lambda_t[d];
        r.sliding = q.sliding;
        r.gap_after = q.n.dot(relative_position(q));
        r.plane_gap = plane_gap(q, r.gap_after);
        // The true depth, kept overlaps included (they are let out over several steps).
        result.max_penetration = std::max(result.max_penetration, -r.gap_after);
    }
    out.ticks = ticks() - group_start;
}

// One active record of a group, for its tally: its pair of bodies and its place in the group.
struct ForceEntry {
    uint64_t key;  // body_pair_key
    uint32_t k;    // in the group's list order
    double force;
};

// What a group leaves for the events' tally (records[order[k]], k < count, in list order):
// the sum of the active pairs' normal multipliers per pair of bodies, each added in list order
// (a sort by pair, then by place), written as BodyPairForces over the front of `entries`
// (`count` of scratch); and the deepest kept offset of its records.
void tally_group(const std::vector<ContactRecord>& records, const uint32_t* order, uint32_t count,
                 ForceEntry* entries, GroupResult& out) {
    uint32_t n = 0;
    double deepest = 0.0;
    for (uint32_t k = 0; k < count; ++k) {
        const ContactRecord& r = records[order[k]];
        deepest = std::max(deepest, r.kept_offset());
        if (!r.active()) continue;
        entries[n++] = ForceEntry{body_pair_key(r.body_a, r.body_b), k, r.lambda_n};
    }
    std::sort(entries, entries + n,
              [](const ForceEntry& x, const ForceEntry& y) { return x.key != y.key ? x.key < y.key : x.k < y.k; });
    uint32_t pairs = 0;
    for (uint32_t j = 0; j < n;) {
        const uint64_t key = entries[j].key;
        double force = 0.0;
        for (; j < n && entries[j].key == key; ++j) force += entries[j].force;
        entries[pairs++] = ForceEntry{key, 0, force};  // pairs <= j: never over an entry still to read
    }
    out.deepest_kept_offset = deepest;
    out.pair_forces = pairs;
}

}  // namespace

// The solve's arrays, kept from sub-step to sub-step for their capacity.
struct ContactSolveScratch::Arrays {
    std::vector<ConstraintPair> pairs;
    std::vector<double> fixed_points;  // 6 per pair: an immovable triangle's point (make_constraint_pair)
    std::vector<LinkPair> link_pairs;
    ContactGroups groups;
    std::vector<ForceEntry> forces;  // per record: the groups' tallies (tally_group)
    std::vector<GroupResult> results;
};

ContactSolveScratch::ContactSolveScratch() : arrays_(new Arrays) {}
ContactSolveScratch::~ContactSolveScratch() = default;

ContactSolveResult solve_contact_multipliers(const std::vector<ContactBody>& bodies,
                                             const std::vector<uint32_t>& body_of_slot,
                                             std::vector<ContactRecord>& records, const std::vector<RecordRun>& runs,
                                             std::vector<LinkRecord>& links,
                                             uint32_t max_iterations, double relative_tolerance,
                                             double h, ContactSolveScratch& scratch, Profile& profile,
                                             std::vector<BodyPairForce>& pair_forces, ThreadPool* pool) {
    // The whole solve is timed as the normal part; the friction passes' share of it is moved
    // to the friction part at the end.
    const auto solve_start = std::chrono::steady_clock::now();
    ContactSolveScratch::Arrays& s = scratch.arrays();
    std::vector<ConstraintPair>& pairs = s.pairs;
    make_link_pairs(bodies, body_of_slot, links, s.link_pairs);
    find_groups(bodies, body_of_slot, uint32_t(records.size()), runs, links, s.groups);
    const uint32_t groups = s.groups.count();
    const std::vector<uint32_t>& begin = s.groups.begin;
    const std::vector<uint32_t>& order = s.groups.order;
    std::vector<GroupResult>& results = s.results;
    results.assign(groups, GroupResult{});
    // Each group in one task: its pairs, in group order (pairs[begin[g] + k] is that of
    // records[order[begin[g] + k]]), its stopping tolerance, then its sweeps. On the thread that
    // stepped its bodies: their arrays are in that core's cache already (the groups come in body
    // order, as the bodies' own loops do), and its pairs stay there for the sweeps. One round of
    // the pool, not one to make the pairs and one to solve them.
    pairs.resize(records.size());
    s.fixed_points.resize(6 * records.size());
    s.forces.resize(records.size());
    parallel_for(pool, groups, [&](uint32_t g) {
        double motion = 0.0, load = 0.0, length = HUGE_VAL;
        for (uint32_t k = begin[g]; k < begin[g + 1]; ++k) {
            ContactRecord& r = records[order[k]];
            const ContactBody& a = bodies[body_of_slot[r.body_a]];
            const ContactBody& b = bodies[body_of_slot[r.body_b]];
            pairs[k] = make_constraint_pair(a, b, r, &s.fixed_points[6 * std::size_t(k)]);
            motion = std::max(motion, pair_motion(a, b, r, h));
            load = std::max({load, a.load_motion, b.load_motion});
            length = std::min({length, a.edge_length, b.edge_length});
        }
        const GroupLinks held{links, s.link_pairs, s.groups.link_order.data() + s.groups.link_begin[g],
                              s.groups.link_begin[g + 1] - s.groups.link_begin[g]};
        results[g].tolerance = stopping_tolerance(bodies, body_of_slot, links, held.order, held.count, motion, load,
                                                  length, relative_tolerance, h);
        solve_group(records, pairs.data() + begin[g], order.data() + begin[g], begin[g + 1] - begin[g], held,
                    max_iterations, results[g].tolerance, results[g]);
        tally_group(records, order.data() + begin[g], begin[g + 1] - begin[g], s.forces.data() + begin[g], results[g]);
    });
    pair_forces.clear();
    for (uint32_t g = 0; g < groups; ++g)
        for (uint32_t k = begin[g]; k < begin[g] + results[g].pair_forces; ++k) {
            const ForceEntry& e = s.forces[k];
            pair_forces.push_back(BodyPairForce{uint32_t(e.key >> 32), uint32_t(e.key), e.force});
        }

    // Iterations and residual of the slowest group to converge, the deepest penetration.
    ContactSolveResult result;
    result.converged = true;
    uint64_t all_ticks = 0, friction_ticks = 0;
    bool any_friction = false;
    for (const GroupResult& g : results) {
        result.iterations = std::max(result.iterations, g.solve.iterations);
        result.residual = std::max(result.residual, g.solve.residual);
        result.converged = result.converged && g.solve.residual <= g.tolerance;
        result.max_penetration = std::max(result.max_penetration, g.solve.max_penetration);
        result.deepest_kept_offset = std::max(result.deepest_kept_offset, g.deepest_kept_offset);
        all_ticks += g.ticks;
        profile.constraint_updates += g.updates;
        friction_ticks += g.friction_ticks;
        any_friction = any_friction || g.friction;
    }
    const double cpu[2] = {double(all_ticks - friction_ticks), double(friction_ticks)};
    PhaseTime* phases[2] = {&profile.normal_solve, &profile.friction};
    share_wall_time(seconds_since(solve_start), cpu, phases, 2);
    profile.friction.calls += any_friction;
    profile.normal_solve.calls += 1;
    profile.contact_sweeps += result.iterations;
    return result;
}

}  // namespace lfem
