#include "contact/solve_contact_multipliers.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/profile.h"
#include "common/thread_pool.h"
#include "contact/constraint_point.h"
#include "contact/link_constraint.h"

namespace lfem {
namespace {

// The pieces of one constraint the sweeps need, resolved once.
struct Pair {
    PointRef node;
    PointRef tri[3];
    double N[3];   // barycentric weights (1 - t1 - t2, t2, t1)
    double H;      // the pair's scalar block of G Mhat^-1 G^T along the normal
    double mu;
    bool fixed = false;  // the other side is one immovable point (a shape's, a static triangle's)
};

// Move the pair's points by Mhat^-1 G_j^T d: the node by +d, triangle node k by -N_k d.
// Linear momentum is kept exactly. Returns the largest move.
double apply(Pair& q, const Vec3& d) {
    double largest = q.node.push(d);
    if (q.fixed) return largest;  // the other side does not move
    for (int v = 0; v < 3; ++v)
        if (q.N[v] != 0.0) largest = std::max(largest, q.tri[v].push(-q.N[v] * d));
    return largest;
}

// n . (x_node - sum N_k x_k) and the relative displacement over the step.
Vec3 relative_position(const Pair& q) {
    Vec3 r = q.node.position();
    for (int v = 0; v < 3; ++v)
        if (q.N[v] != 0.0) r -= q.N[v] * q.tri[v].position();
    return r;
}
Vec3 relative_motion(const Pair& q) {
    Vec3 r = q.node.position() - Vec3(q.node.x0);
    for (int v = 0; v < 3; ++v)
        if (q.N[v] != 0.0) r -= q.N[v] * (q.tri[v].position() - Vec3(q.tri[v].x0));
    return r;
}

// The gap the solve left as the next step's detection will measure it: the node's distance
// from the plane of the triangle where its corners are now. The constraint held the gap along
// the normal the triangle had at x*, at the weights of the point found there; a triangle that
// the solve turned (a soft face pressed at one corner, a fold closing) leaves the node off its
// new plane by the turn times the node's distance from the corner. The next step allows the
// pair that depth and makes it up (detect_node_triangle.cpp, kept_offset); measured along the
// old normal, the miss grew unseen, step after step, until the node was deeper than the pair
// had been left and was dropped. A shape's surface point or an immovable triangle's: along
// the normal (r.gap_after, set before).
double plane_gap(const ContactRecord& r, const Pair& q) {
    const Vec3 n(r.normal);
    if (q.fixed) return r.gap_after;  // a plane that does not turn: the gap along the normal
    const Vec3 a = q.tri[0].position();
    const Vec3 plane = (q.tri[1].position() - a).cross(q.tri[2].position() - a);
    const double area2 = plane.norm();
    if (!(area2 > 0.0)) return n.dot(relative_position(q));  // collapsed: no plane
    return plane.dot(q.node.position() - a) / area2;
}

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

// The stopping tolerance of one group: relative_tolerance times the largest relative motion of
// its pairs (`motion`, the records' largest pair_motion, here joined by the links' in
// links[order[0 .. count)]), at least 1e-9 of its finest boundary edge (`length`, likewise),
// for when nothing moves. Each group's own: a body falling fast elsewhere in the world neither
// loosens nor tightens the solve of a resting pile, and a group's result depends on its own
// pairs alone.
double stopping_tolerance(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                          const std::vector<LinkRecord>& links, const uint32_t* order, uint32_t count, double motion,
                          double length, double relative_tolerance, double h) {
    for (uint32_t k = 0; k < count; ++k) {  // a held node: its own motion against its target's
        const LinkRecord& l = links[order[k]];
        const ContactBody& a = bodies[body_of_slot[l.body_a]];
        for (int d = 0; d < 3; ++d) motion = std::max(motion, std::fabs(last_velocity(a, l.node, d, h)) * h);
        length = std::min(length, a.edge_length);
    }
    return std::max(relative_tolerance * motion, 1e-9 * length);
}

// Union-find root of body i (path halving).
uint32_t root_of(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
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
// order; pairs[k] is the pair of records[order[k]]): the warm start, then sweeps until one
// moves no point by more than `tolerance`.
void solve_group(std::vector<ContactRecord>& records, Pair* pairs, const uint32_t* order, uint32_t count,
                 const GroupLinks& held, uint32_t max_iterations, double tolerance, GroupResult& out) {
    const uint64_t group_start = ticks();
    ContactSolveResult& result = out.solve;
    for (uint32_t k = 0; k < held.count; ++k) warm_start_link(held.links[held.order[k]], held.pairs[held.order[k]]);
    // Warm start: the multipliers the records carry in (last step's, for the same node and
    // body) are applied first, so a resting contact starts converged.
    for (uint32_t k = 0; k < count; ++k) {
        ContactRecord& r = records[order[k]];
        if (!(pairs[k].H > 0.0)) {
            r.lambda_n = 0.0, r.lambda_t[0] = r.lambda_t[1] = r.lambda_t[2] = 0.0;
            continue;
        }
        const Vec3 n(r.normal);
        Vec3 lt(r.lambda_t);
        lt -= n * n.dot(lt);  // the normal may have turned since: keep the tangential part
        if (pairs[k].mu == 0.0) lt.setZero();
        for (int d = 0; d < 3; ++d) r.lambda_t[d] = lt[d];
        apply(pairs[k], r.lambda_n * n + lt);
    }

    // Each sweep: the normal updates of every pair, then the friction updates of the pairs
    // that have friction (in the same sweep, as the paper's forward increment asks; split into
    // two passes so each part's time can be measured on its own).
    bool any_friction = false;
    for (uint32_t k = 0; k < count; ++k) {
        const Pair& q = pairs[k];
        any_friction = any_friction || (q.mu > 0.0 && q.H > 0.0);
    }
    out.friction = any_friction && max_iterations > 0;  // a friction pass will run
    for (uint32_t sweep = 0; sweep < max_iterations; ++sweep) {
        double largest = 0.0;
        for (uint32_t k = 0; k < count; ++k) {
            ContactRecord& r = records[order[k]];
            Pair& q = pairs[k];
            if (!(q.H > 0.0)) continue;  // both sides immovable: nothing to solve
            const Vec3 n(r.normal);
            // Normal: lambda_n <- max(0, lambda_n - (g - g_target)/H); the clamp is the
            // paper's tension release.
            const double g = n.dot(relative_position(q)) + r.offset;
            const double lambda_n = std::max(0.0, r.lambda_n - g / q.H);
            largest = std::max(largest, apply(q, (lambda_n - r.lambda_n) * n));
            r.lambda_n = lambda_n;
        }
        for (uint32_t k = 0; k < held.count; ++k)
            largest = std::max(largest, update_link(held.links[held.order[k]], held.pairs[held.order[k]]));
        if (any_friction) {
            const uint64_t start = ticks();
            for (uint32_t k = 0; k < count; ++k) {
                ContactRecord& r = records[order[k]];
                Pair& q = pairs[k];
                if (!(q.H > 0.0) || q.mu == 0.0) continue;  // frictionless: no tangential work
                const Vec3 n(r.normal);
                // Friction: the tangential slip of the node relative to the triangle over the
                // step, cancelled by the stick trial, then returned onto the Coulomb cone (eq. 7).
                Vec3 slip = relative_motion(q);
                slip -= n * n.dot(slip);
                const Vec3 lt_old(r.lambda_t);
                Vec3 lt = lt_old - slip / q.H;
                const double cap = q.mu * r.lambda_n, norm = lt.norm();
                r.sliding = norm > cap;
                if (r.sliding) lt *= norm > 0.0 ? cap / norm : 0.0;
                largest = std::max(largest, apply(q, lt - lt_old));
                for (int d = 0; d < 3; ++d) r.lambda_t[d] = lt[d];
            }
            out.friction_ticks += ticks() - start;
        }
        result.iterations = sweep + 1;
        result.residual = largest;
        out.updates += count + held.count;
        if (largest <= tolerance) break;
    }
    for (uint32_t k = 0; k < count; ++k) {
        ContactRecord& r = records[order[k]];
        r.gap_after = Vec3(r.normal).dot(relative_position(pairs[k]));
        r.plane_gap = plane_gap(r, pairs[k]);
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

// The pieces of record r's constraint: its points, weights, H and friction. `fixed`: 6 numbers
// of scratch, where the point of an immovable triangle goes (at the end of the step and at its
// start), kept for the solve.
Pair make_pair(const ContactBody& a, const ContactBody& b, ContactRecord& r, double* fixed) {
    Pair q;  // shape contacts lend their surface points (r's)
    const Vec3 n(r.normal);
    q.node = point_of(a, r.node);
    q.N[0] = 1.0 - r.t1 - r.t2;
    q.N[1] = r.t2;
    q.N[2] = r.t1;
    q.H = q.node.response(n);
    if (r.shape != UINT32_MAX) {
        // A rigid shape: one immovable point, the touched surface point, moving with the
        // shape from its start to its end position (friction slips relative to it).
        q.N[0] = 1.0, q.N[1] = q.N[2] = 0.0;
        q.tri[0].x = r.point_end;
        q.tri[0].x0 = r.point_start;
        q.fixed = true;
    } else if (!is_movable(b)) {
        // A triangle of a static or kinematic body (or of a sleeping one): the solve cannot
        // move it, so its point sum N_k x_k is taken once, not in every sweep, and the pair is
        // a node against one immovable point, as against a shape.
        Vec3 end = Vec3::Zero(), start = Vec3::Zero();
        for (int v = 0; v < 3; ++v) {
            end += q.N[v] * Vec3(b.x + 3 * std::size_t(r.triangle[v]));
            start += q.N[v] * Vec3(b.x_start + 3 * std::size_t(r.triangle[v]));
        }
        for (int k = 0; k < 3; ++k) fixed[k] = end[k], fixed[3 + k] = start[k];
        q.N[0] = 1.0, q.N[1] = q.N[2] = 0.0;
        q.tri[0].x = fixed;
        q.tri[0].x0 = fixed + 3;
        q.fixed = true;
    } else {
        for (int v = 0; v < 3; ++v) {
            q.tri[v] = point_of(b, r.triangle[v]);
            q.H += q.N[v] * q.N[v] * q.tri[v].response(n);
        }
        // Two weights on one rigid body add up before squaring: the exact block is
        // (sum N_k J_k) M^-1 (sum N_k J_k)^T; with the centre and arm of a barycentric
        // point of a rigid triangle, it is the response at that point.
        if (b.rigid) {
            Vec3 arm = Vec3::Zero();
            for (int v = 0; v < 3; ++v) arm += q.N[v] * q.tri[v].arm();
            q.H = q.node.response(n) + rigid_response(*b.rigid, arm, n);
        }
    }
    q.mu = pair_friction(a.friction, b.friction);
    return q;
}

// Groups: pairs that share no movable point cannot affect each other, so each group of pairs
// linked through movable bodies is solved on its own, to its own convergence, and the groups
// side by side on the pool. Static and kinematic bodies do not link (their points never move):
// sixteen cubes on one static floor are sixteen groups. A group's result does not depend on the
// others or on the thread count: on one thread the groups simply run one after another. The
// pairs of group g are order[begin[g] .. begin[g+1]), in list order; returns the group count.
// (group_pairs, below the scratch it fills.)

// A run of records of one pair of bodies: from records[first] to the next run's first; a and b
// index the bodies of the node and of the triangle.
struct Run {
    uint32_t first, a, b, group;
};

}  // namespace

// The solve's arrays, kept from sub-step to sub-step for their capacity.
struct ContactSolveScratch::Arrays {
    std::vector<Pair> pairs;
    std::vector<double> fixed_points;  // 6 per pair: an immovable triangle's point (make_pair)
    std::vector<LinkPair> link_pairs;
    std::vector<uint32_t> parent, group_of_root, group_begin, order, next;
    std::vector<Run> runs;  // the records' runs of one pair of bodies (group_pairs)
    std::vector<ForceEntry> forces;  // per record: the groups' tallies (tally_group)
    std::vector<uint8_t> movable;  // per body
    std::vector<uint32_t> group_of_link, link_begin, link_order;
    std::vector<GroupResult> results;
};

ContactSolveScratch::ContactSolveScratch() : arrays_(new Arrays) {}
ContactSolveScratch::~ContactSolveScratch() = default;

namespace {

// The members of each group in list order (a counting sort): order[begin[g] .. begin[g+1]).
void sort_by_group(const std::vector<uint32_t>& group_of, uint32_t groups, std::vector<uint32_t>& begin,
                   std::vector<uint32_t>& order, std::vector<uint32_t>& next) {
    begin.assign(groups + 1, 0);
    order.resize(group_of.size());
    for (uint32_t g : group_of) ++begin[g + 1];
    for (uint32_t g = 0; g < groups; ++g) begin[g + 1] += begin[g];
    next.assign(begin.begin(), begin.end() - 1);
    for (std::size_t j = 0; j < group_of.size(); ++j) order[next[group_of[j]]++] = uint32_t(j);
}

uint32_t group_pairs(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     const std::vector<ContactRecord>& records, const std::vector<RecordRun>& record_runs,
                     const std::vector<LinkRecord>& links, ContactSolveScratch::Arrays& s) {
    const uint32_t nb = uint32_t(bodies.size());
    std::vector<uint32_t>& parent = s.parent;
    std::vector<uint8_t>& movable = s.movable;
    parent.resize(nb);
    movable.resize(nb);
    for (uint32_t i = 0; i < nb; ++i) parent[i] = i, movable[i] = is_movable(bodies[i]);
    // The records come in runs of one pair of bodies (a body's nodes against another's faces,
    // in node order), found by the detection: the work below is done once per run (a few dozen
    // runs for hundreds of records), and the records are not read.
    std::vector<Run>& runs = s.runs;
    runs.clear();
    for (const RecordRun& r : record_runs) runs.push_back(Run{r.first, body_of_slot[r.body_a], body_of_slot[r.body_b], 0});
    auto link_bodies = [&](uint32_t a, uint32_t b) {
        if (movable[a] && movable[b]) parent[root_of(parent, a)] = root_of(parent, b);
    };
    for (const Run& r : runs) link_bodies(r.a, r.b);
    for (const LinkRecord& l : links)
        if (l.body_b != UINT32_MAX) link_bodies(body_of_slot[l.body_a], body_of_slot[l.body_b]);
    // A pair's group is that of its movable body (the node's, or else the triangle's). Groups
    // are numbered in the order of their first body: the pool gives each thread a contiguous
    // range of groups as it gives it one of bodies, so a body's group is solved on the thread
    // that predicted the body and computed its forces, from that core's cache. (Numbered in
    // order of first appearance in the list, where a static floor's nodes come first, the
    // cubes on the floor were scattered over both threads, and their nodes crossed between the
    // cores twice a sub-step.)
    std::vector<uint32_t>& group_of_root = s.group_of_root;
    constexpr uint32_t kNone = UINT32_MAX, kUsed = UINT32_MAX - 1;
    group_of_root.assign(nb, kNone);
    const auto root_of_pair = [&](uint32_t a, uint32_t b) { return root_of(parent, b == kNone || movable[a] ? a : b); };
    const auto slot_body = [&](uint32_t slot) { return slot == kNone ? kNone : body_of_slot[slot]; };
    for (const Run& r : runs) group_of_root[root_of_pair(r.a, r.b)] = kUsed;
    for (const LinkRecord& l : links) group_of_root[root_of_pair(slot_body(l.body_a), slot_body(l.body_b))] = kUsed;
    uint32_t groups = 0;
    for (uint32_t i = 0; i < nb; ++i) {
        uint32_t& group = group_of_root[root_of(parent, i)];
        if (group == kUsed) group = groups++;
    }
    const auto group_of = [&](uint32_t a, uint32_t b) { return group_of_root[root_of_pair(a, b)]; };
    // Each group's records in list order (a counting sort by runs): order[begin[g] .. begin[g+1]).
    std::vector<uint32_t>& begin = s.group_begin;
    begin.assign(groups + 1, 0);
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const uint32_t end = k + 1 < runs.size() ? runs[k + 1].first : uint32_t(records.size());
        runs[k].group = group_of(runs[k].a, runs[k].b);
        begin[runs[k].group + 1] += end - runs[k].first;
    }
    for (uint32_t g = 0; g < groups; ++g) begin[g + 1] += begin[g];
    s.next.assign(begin.begin(), begin.end() - 1);
    s.order.resize(records.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const uint32_t end = k + 1 < runs.size() ? runs[k + 1].first : uint32_t(records.size());
        uint32_t& next = s.next[runs[k].group];
        for (uint32_t j = runs[k].first; j < end; ++j) s.order[next++] = j;
    }
    s.group_of_link.resize(links.size());
    for (std::size_t j = 0; j < links.size(); ++j)
        s.group_of_link[j] = group_of(slot_body(links[j].body_a), slot_body(links[j].body_b));
    sort_by_group(s.group_of_link, groups, s.link_begin, s.link_order, s.next);
    return groups;
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
    std::vector<Pair>& pairs = s.pairs;
    make_link_pairs(bodies, body_of_slot, links, s.link_pairs);
    const uint32_t groups = group_pairs(bodies, body_of_slot, records, runs, links, s);
    const std::vector<uint32_t>& begin = s.group_begin;
    const std::vector<uint32_t>& order = s.order;
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
        double motion = 0.0, length = HUGE_VAL;
        for (uint32_t k = begin[g]; k < begin[g + 1]; ++k) {
            ContactRecord& r = records[order[k]];
            const ContactBody& a = bodies[body_of_slot[r.body_a]];
            const ContactBody& b = bodies[body_of_slot[r.body_b]];
            pairs[k] = make_pair(a, b, r, &s.fixed_points[6 * std::size_t(k)]);
            motion = std::max(motion, pair_motion(a, b, r, h));
            length = std::min({length, a.edge_length, b.edge_length});
        }
        const GroupLinks held{links, s.link_pairs, s.link_order.data() + s.link_begin[g],
                              s.link_begin[g + 1] - s.link_begin[g]};
        results[g].tolerance = stopping_tolerance(bodies, body_of_slot, links, held.order, held.count, motion, length,
                                                  relative_tolerance, h);
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
