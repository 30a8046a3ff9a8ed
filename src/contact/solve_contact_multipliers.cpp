#include "contact/solve_contact_multipliers.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/profile.h"
#include "common/thread_pool.h"
#include "contact/constraint_pair.h"
#include "contact/contact_groups.h"
#include "contact/group_partition.h"
#include "contact/sweeps.h"
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
        double rel = 0.0;  // a static body's: 0
        if (a.moves && !r.feature())
            rel = last_velocity(a, r.node, d, h);
        else if (a.moves)
            for (int v = 0; v < r.side_nodes(); ++v) rel += r.weights_a[v] * last_velocity(a, r.nodes_a[v], d, h);
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
        for (uint32_t j = 0; j < l.held.count; ++j)
            for (int d = 0; d < 3; ++d) motion = std::max(motion, std::fabs(last_velocity(a, l.held.node[j], d, h)) * h);
        length = std::min(length, a.edge_length);
        load = std::max(load, a.load_motion);
        if (l.target_nodes.count == 0) continue;
        const ContactBody& b = bodies[body_of_slot[l.body_b]];  // a deformable target moves too
        for (uint32_t j = 0; j < l.target_nodes.count; ++j)
            for (int d = 0; d < 3; ++d)
                motion = std::max(motion, std::fabs(last_velocity(b, l.target_nodes.node[j], d, h)) * h);
        length = std::min(length, b.edge_length);
        load = std::max(load, b.load_motion);
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
    for (uint32_t k = 0; k < held.count; ++k) warm_start_link(held.links[held.order[k]], held.pairs[held.order[k]]);
    const bool any_friction = warm_start_pairs(pairs, count);
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
    result.max_penetration = write_back(pairs, count, order, records);
    out.ticks = ticks() - group_start;
}

// One active record of a group, for its tally: its pair of bodies and its place in the group.
struct ForceEntry {
    uint64_t key;  // body_pair_key
    uint32_t k;    // in the group's list order; after the sum, that of the fastest approach
    double force;
    double approach;  // m/s
};

// What a group leaves for the events' tally (records[order[k]], k < count, in list order, with
// their pairs[k]): the sum of the active pairs' normal multipliers per pair of bodies, each added
// in list order (a sort by pair, then by place), with the fastest approach of each (the first in
// list order among equals), written as ForceEntries over the front of `entries` (`count` of
// scratch); and the deepest kept offset of its records.
void tally_group(const std::vector<ContactRecord>& records, const ConstraintPair* pairs, const uint32_t* order,
                 uint32_t count, double h, ForceEntry* entries, GroupResult& out) {
    uint32_t n = 0;
    double deepest = 0.0;
    for (uint32_t k = 0; k < count; ++k) {
        const ContactRecord& r = records[order[k]];
        deepest = std::max(deepest, r.kept_offset());
        if (!r.active()) continue;
        entries[n++] = ForceEntry{body_pair_key(r.body_a, r.body_b), k, r.lambda_n, pairs[k].approach / h};
    }
    std::sort(entries, entries + n,
              [](const ForceEntry& x, const ForceEntry& y) { return x.key != y.key ? x.key < y.key : x.k < y.k; });
    uint32_t sums = 0;
    for (uint32_t j = 0; j < n;) {
        ForceEntry sum{entries[j].key, entries[j].k, 0.0, entries[j].approach};
        for (; j < n && entries[j].key == sum.key; ++j) {
            sum.force += entries[j].force;
            if (entries[j].approach > sum.approach) sum.approach = entries[j].approach, sum.k = entries[j].k;
        }
        entries[sums++] = sum;  // sums <= j: never over an entry still to read
    }
    out.deepest_kept_offset = deepest;
    out.pair_forces = sums;
}

// A pair of bodies' tally as the events take it: the fastest record's node and normal (the
// record's points out of its body_b, toward the node's body: turned to point from the pair's
// lower slot toward the higher).
BodyPairForce pair_force_of(const ForceEntry& e, const std::vector<ContactRecord>& records, const ConstraintPair* pairs,
                            const uint32_t* order) {
    BodyPairForce f;
    f.slot_a = uint32_t(e.key >> 32), f.slot_b = uint32_t(e.key);
    f.force = e.force;
    f.approach_speed = e.approach;
    const ContactRecord& r = records[order[e.k]];
    const Vec3 at = side_a_point(pairs[e.k]);
    const double sign = r.body_b == f.slot_a ? 1.0 : -1.0;
    for (int d = 0; d < 3; ++d) f.point[d] = at[d], f.normal[d] = sign * r.normal[d];
    return f;
}

// What one task of a split group reports per sweep (solve_split).
struct TaskResult {
    double largest = 0;
    uint64_t ticks = 0, friction_ticks = 0;
    double deepest = 0;
    bool friction = false;
};

}  // namespace

// The solve's arrays, kept from sub-step to sub-step for their capacity.
struct ContactSolveScratch::Arrays {
    std::vector<ConstraintPair> pairs;
    std::vector<double> fixed_points;  // 6 per pair: an immovable triangle's point (make_constraint_pair)
    std::vector<LinkPair> link_pairs;
    ContactGroups groups;
    std::vector<ForceEntry> forces;  // per record: the groups' tallies (tally_group)
    std::vector<GroupResult> results;
    std::vector<GroupPartition> partitions;  // per group: its split, for the groups split (split[g])
    std::vector<uint8_t> split;
    std::vector<TaskResult> tasks;           // per task of the split group being solved
};

ContactSolveScratch::ContactSolveScratch() : arrays_(new Arrays) {}
ContactSolveScratch::~ContactSolveScratch() = default;

namespace {

// The sweeps of a group split for the threads (group_partition.h): the warm start, the sweeps
// and the write-back, each phase by phase, the tasks of a phase side by side on the pool. The
// same measure of change and stopping rule as solve_group; each task runs its pairs' normal
// updates, then their friction updates.
void solve_split(std::vector<ContactRecord>& records, ConstraintPair* pairs, const uint32_t* order,
                 const GroupPartition& part, uint32_t max_iterations, double tolerance, std::vector<TaskResult>& tasks,
                 GroupResult& out, ThreadPool* pool) {
    const std::vector<uint32_t>& tb = part.task_begin;
    const uint32_t count = tb.back();
    tasks.assign(tb.size() - 1, TaskResult{});
    const auto each_phase = [&](const auto& work) {
        for (uint32_t ph = 0; ph < part.phases(); ++ph) {
            const uint32_t first = part.phase_begin[ph];
            parallel_for(pool, part.phase_begin[ph + 1] - first, [&](uint32_t i) {
                const uint32_t t = first + i;
                const uint64_t start = ticks();
                work(t, pairs + tb[t], tb[t + 1] - tb[t]);
                tasks[t].ticks += ticks() - start;
            });
        }
    };
    each_phase([&](uint32_t t, ConstraintPair* p, uint32_t n) { tasks[t].friction = warm_start_pairs(p, n); });
    bool any_friction = false;
    for (const TaskResult& t : tasks) any_friction = any_friction || t.friction;
    out.friction = any_friction && max_iterations > 0;
    for (uint32_t sweep = 0; sweep < max_iterations; ++sweep) {
        each_phase([&](uint32_t t, ConstraintPair* p, uint32_t n) {
            double largest = normal_pass(p, n, sweep == 0);
            if (any_friction) {
                const uint64_t start = ticks();
                largest = std::max(largest, friction_pass(p, n, sweep == 0));
                tasks[t].friction_ticks += ticks() - start;
            }
            tasks[t].largest = largest;
        });
        double largest = 0.0;
        for (const TaskResult& t : tasks) largest = std::max(largest, t.largest);
        out.solve.iterations = sweep + 1;
        out.solve.residual = largest;
        out.updates += count;
        if (largest <= tolerance) break;
    }
    each_phase([&](uint32_t t, ConstraintPair* p, uint32_t n) { tasks[t].deepest = write_back(p, n, order + tb[t], records); });
    for (const TaskResult& t : tasks) {
        out.solve.max_penetration = std::max(out.solve.max_penetration, t.deepest);
        out.ticks += t.ticks;
        out.friction_ticks += t.friction_ticks;
    }
}

}  // namespace

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
    s.partitions.resize(groups);
    s.split.assign(groups, 0);
    parallel_for(pool, groups, [&](uint32_t g) {
        // A big group without links is split for the threads (solved after this round).
        const bool split = s.groups.link_begin[g + 1] == s.groups.link_begin[g] &&
                           partition_group(bodies, body_of_slot, records, s.groups.order.data() + begin[g],
                                           begin[g + 1] - begin[g], s.partitions[g]);
        s.split[g] = split;
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
        if (split) return;
        solve_group(records, pairs.data() + begin[g], order.data() + begin[g], begin[g + 1] - begin[g], held,
                    max_iterations, results[g].tolerance, results[g]);
        tally_group(records, pairs.data() + begin[g], order.data() + begin[g], begin[g + 1] - begin[g], h,
                    s.forces.data() + begin[g], results[g]);
    });
    for (uint32_t g = 0; g < groups; ++g) {
        if (!s.split[g]) continue;
        solve_split(records, pairs.data() + begin[g], order.data() + begin[g], s.partitions[g], max_iterations,
                    results[g].tolerance, s.tasks, results[g], pool);
        tally_group(records, pairs.data() + begin[g], order.data() + begin[g], begin[g + 1] - begin[g], h,
                    s.forces.data() + begin[g], results[g]);
    }
    pair_forces.clear();
    for (uint32_t g = 0; g < groups; ++g)
        for (uint32_t k = begin[g]; k < begin[g] + results[g].pair_forces; ++k)
            pair_forces.push_back(pair_force_of(s.forces[k], records, pairs.data() + begin[g], order.data() + begin[g]));

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
