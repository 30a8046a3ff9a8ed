#include "contact/solve_contact_multipliers.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/thread_pool.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// One of the four points of a constraint (the node, or a triangle node): a free node that the
// solve moves directly, or a point of a rigid body, moved through the body's centre and
// rotation corrections (its position is evaluated from them when asked).
struct PointRef {
    double* x = nullptr;         // free node: its position (x*, corrected in place)
    const double* x0 = nullptr;  // position at the start of the step
    double w = 0;                // free node: 1/mhat
    RigidResponse* rigid = nullptr;
    Vec3 base = Vec3::Zero();    // rigid point: its predicted position
    Vec3 arm = Vec3::Zero();     // rigid point: predicted position minus predicted centre

    Vec3 position() const {
        if (rigid) return base + rigid->dc + rigid->dtheta.cross(arm);
        return Vec3(x[0], x[1], x[2]);
    }
    // Inverse effective mass along unit direction n.
    double response(const Vec3& n) const {
        if (rigid) {
            const Vec3 rn = arm.cross(n);
            return rigid->inv_mass + rn.dot(rigid->inv_inertia * rn);
        }
        return w;
    }
    // Apply the force increment d (N) to this point; returns how far it moved.
    double push(const Vec3& d) {
        if (rigid) {
            const Vec3 before = position();
            rigid->dc += rigid->inv_mass * d;
            rigid->dtheta += rigid->inv_inertia * arm.cross(d);
            return (position() - before).cwiseAbs().maxCoeff();
        }
        // An immovable point (static, kinematic or fixed) is not written at all: the contact
        // groups solved side by side may share it (a static floor's nodes).
        if (w == 0.0) return 0.0;
        for (int k = 0; k < 3; ++k) x[k] += w * d[k];
        return w * d.cwiseAbs().maxCoeff();
    }
};

// The pieces of one constraint the sweeps need, resolved once.
struct Pair {
    PointRef node;
    PointRef tri[3];
    double N[3];   // barycentric weights (1 - t1 - t2, t2, t1)
    double H;      // the pair's scalar block of G Mhat^-1 G^T along the normal
    double mu;
};

PointRef point_of(const ContactBody& b, uint32_t i) {
    PointRef p;
    p.x = b.x + 3 * std::size_t(i);
    p.x0 = b.x_start + 3 * std::size_t(i);
    if (b.rigid) {
        p.rigid = b.rigid;
        p.base = Vec3(p.x[0], p.x[1], p.x[2]);
        p.arm = p.base - b.rigid->center;
    } else {
        p.w = b.inv_mass ? b.inv_mass[i] : 0.0;
    }
    return p;
}

// Move the pair's points by Mhat^-1 G_j^T d: the node by +d, triangle node k by -N_k d.
// Linear momentum is kept exactly. Returns the largest move.
double apply(Pair& q, const Vec3& d) {
    double largest = q.node.push(d);
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

// Velocity of point i of body b over the last step, along axis k.
double last_velocity(const ContactBody& b, uint32_t i, int k, double h) {
    return b.v_last ? b.v_last[3 * i + k] : (b.x[3 * i + k] - b.x_start[3 * i + k]) / h;
}

// The stopping tolerance: relative_tolerance times the largest relative motion of a pair, the
// relative velocity at the start of the step (last step's mid-step velocities) times h; not the
// predicted motion, which under a resting load is mostly the sag that contact undoes. At least
// 1e-9 of the finest boundary edge, for when nothing moves.
double stopping_tolerance(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                          const std::vector<ContactRecord>& records, double relative_tolerance, double h) {
    double motion = 0.0, length = HUGE_VAL;
    for (const ContactRecord& r : records) {
        const ContactBody& a = bodies[body_of_slot[r.body_a]];
        const ContactBody& b = bodies[body_of_slot[r.body_b]];
        const double w[3] = {1.0 - r.t1 - r.t2, r.t2, r.t1};
        for (int d = 0; d < 3; ++d) {
            double rel = a.moves ? last_velocity(a, r.node, d, h) : 0.0;  // a static body's: 0
            if (r.shape != UINT32_MAX)
                rel -= (r.point_end[d] - r.point_start[d]) / h;  // the shape's surface moves rigidly
            else if (b.moves)
                for (int v = 0; v < 3; ++v) rel -= w[v] * last_velocity(b, r.triangle[v], d, h);
            motion = std::max(motion, std::fabs(rel) * h);
        }
        length = std::min({length, a.edge_length, b.edge_length});
    }
    return std::max(relative_tolerance * motion, 1e-9 * length);
}

// Union-find root of body i (path halving).
uint32_t root_of(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// What one group's solve reports; CPU seconds, so that the solve's wall time can be split
// between its normal and friction parts however the groups ran.
struct GroupResult {
    ContactSolveResult solve;
    double seconds = 0, friction_seconds = 0;
};

// Projected Gauss-Seidel over one group's pairs (indices `order`, in list order): the warm
// start, then sweeps until one moves no point by more than `tolerance`.
void solve_group(std::vector<ContactRecord>& records, std::vector<Pair>& pairs, const uint32_t* order,
                 uint32_t count, uint32_t max_iterations, double tolerance, GroupResult& out) {
    const auto group_start = std::chrono::steady_clock::now();
    ContactSolveResult& result = out.solve;
    // Warm start: the multipliers the records carry in (last step's, for the same node and
    // body) are applied first, so a resting contact starts converged.
    for (uint32_t k = 0; k < count; ++k) {
        const uint32_t j = order[k];
        ContactRecord& r = records[j];
        if (!(pairs[j].H > 0.0)) {
            r.lambda_n = 0.0, r.lambda_t[0] = r.lambda_t[1] = r.lambda_t[2] = 0.0;
            continue;
        }
        const Vec3 n(r.normal);
        Vec3 lt(r.lambda_t);
        lt -= n * n.dot(lt);  // the normal may have turned since: keep the tangential part
        if (pairs[j].mu == 0.0) lt.setZero();
        for (int d = 0; d < 3; ++d) r.lambda_t[d] = lt[d];
        apply(pairs[j], r.lambda_n * n + lt);
    }

    // Each sweep: the normal updates of every pair, then the friction updates of the pairs
    // that have friction (in the same sweep, as the paper's forward increment asks; split into
    // two passes so each part's time can be measured on its own).
    bool any_friction = false;
    for (uint32_t k = 0; k < count; ++k) {
        const Pair& q = pairs[order[k]];
        any_friction = any_friction || (q.mu > 0.0 && q.H > 0.0);
    }
    for (uint32_t sweep = 0; sweep < max_iterations; ++sweep) {
        double largest = 0.0;
        for (uint32_t k = 0; k < count; ++k) {
            ContactRecord& r = records[order[k]];
            Pair& q = pairs[order[k]];
            if (!(q.H > 0.0)) continue;  // both sides immovable: nothing to solve
            const Vec3 n(r.normal);
            // Normal: lambda_n <- max(0, lambda_n - (g - g_target)/H); the clamp is the
            // paper's tension release.
            const double g = n.dot(relative_position(q)) + r.offset;
            const double lambda_n = std::max(0.0, r.lambda_n - g / q.H);
            largest = std::max(largest, apply(q, (lambda_n - r.lambda_n) * n));
            r.lambda_n = lambda_n;
        }
        if (any_friction) {
            const auto start = std::chrono::steady_clock::now();
            for (uint32_t k = 0; k < count; ++k) {
                ContactRecord& r = records[order[k]];
                Pair& q = pairs[order[k]];
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
            out.friction_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        result.iterations = sweep + 1;
        result.residual = largest;
        if (largest <= tolerance) break;
    }
    for (uint32_t k = 0; k < count; ++k) {
        ContactRecord& r = records[order[k]];
        r.gap_after = Vec3(r.normal).dot(relative_position(pairs[order[k]]));
        // The true depth, kept overlaps included (they are let out over several steps).
        result.max_penetration = std::max(result.max_penetration, -r.gap_after);
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - group_start).count();
}

// The pieces of every record's constraint: its points, weights, H and friction.
void make_pairs(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                std::vector<ContactRecord>& records, std::vector<Pair>& pairs) {
    pairs.assign(records.size(), Pair{});
    for (std::size_t j = 0; j < records.size(); ++j) {
        ContactRecord& r = records[j];  // shape contacts lend their surface points
        const ContactBody& a = bodies[body_of_slot[r.body_a]];
        const ContactBody& b = bodies[body_of_slot[r.body_b]];
        Pair& q = pairs[j];
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
        } else {
            for (int v = 0; v < 3; ++v) {
                q.tri[v] = point_of(b, r.triangle[v]);
                q.H += q.N[v] * q.N[v] * q.tri[v].response(n);
            }
            // Two weights on one rigid body add up before squaring: the exact block is
            // (sum N_k J_k) M^-1 (sum N_k J_k)^T; with the centre and arm of a barycentric
            // point of a rigid triangle, it is the response at that point.
            if (b.rigid) {
                PointRef p = q.tri[0];
                p.base = Vec3::Zero(), p.arm = Vec3::Zero();
                for (int v = 0; v < 3; ++v) p.base += q.N[v] * q.tri[v].base, p.arm += q.N[v] * q.tri[v].arm;
                q.H = q.node.response(n) + p.response(n);
            }
        }
        q.mu = pair_friction(a.friction, b.friction);
    }
}

// Groups: pairs that share no movable point cannot affect each other, so each group of pairs
// linked through movable bodies is solved on its own, to its own convergence, and the groups
// side by side on the pool. Static and kinematic bodies do not link (their points never move):
// sixteen cubes on one static floor are sixteen groups. A group's result does not depend on the
// others or on the thread count: on one thread the groups simply run one after another. The
// pairs of group g are order[begin[g] .. begin[g+1]), in list order; returns the group count.
}  // namespace

// The solve's arrays, kept from sub-step to sub-step for their capacity.
struct ContactSolveScratch::Arrays {
    std::vector<Pair> pairs;
    std::vector<uint32_t> parent, group_of_root, group_of_pair, group_begin, order, next;
    std::vector<GroupResult> results;
};

ContactSolveScratch::ContactSolveScratch() : arrays_(new Arrays) {}
ContactSolveScratch::~ContactSolveScratch() = default;

namespace {

uint32_t group_pairs(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     const std::vector<ContactRecord>& records, ContactSolveScratch::Arrays& s) {
    const uint32_t nb = uint32_t(bodies.size());
    std::vector<uint32_t>& parent = s.parent;
    parent.resize(nb);
    for (uint32_t i = 0; i < nb; ++i) parent[i] = i;
    for (const ContactRecord& r : records) {
        const uint32_t a = body_of_slot[r.body_a], b = body_of_slot[r.body_b];
        if (is_movable(bodies[a]) && is_movable(bodies[b])) parent[root_of(parent, a)] = root_of(parent, b);
    }
    // Group numbers in order of first appearance in the list; a pair's group is that of its
    // movable body (the node's, or else the triangle's).
    std::vector<uint32_t>& group_of_root = s.group_of_root;
    std::vector<uint32_t>& group_of_pair = s.group_of_pair;
    group_of_root.assign(nb, UINT32_MAX);
    group_of_pair.resize(records.size());
    uint32_t groups = 0;
    for (std::size_t j = 0; j < records.size(); ++j) {
        const uint32_t a = body_of_slot[records[j].body_a], b = body_of_slot[records[j].body_b];
        const uint32_t root = root_of(parent, is_movable(bodies[a]) ? a : b);
        if (group_of_root[root] == UINT32_MAX) group_of_root[root] = groups++;
        group_of_pair[j] = group_of_root[root];
    }
    // The pairs of each group, in list order (a counting sort).
    std::vector<uint32_t>& begin = s.group_begin;
    std::vector<uint32_t>& order = s.order;
    begin.assign(groups + 1, 0);
    order.resize(records.size());
    for (uint32_t g : group_of_pair) ++begin[g + 1];
    for (uint32_t g = 0; g < groups; ++g) begin[g + 1] += begin[g];
    s.next.assign(begin.begin(), begin.end() - 1);
    for (std::size_t j = 0; j < records.size(); ++j) order[s.next[group_of_pair[j]]++] = uint32_t(j);
    return groups;
}

}  // namespace

ContactSolveResult solve_contact_multipliers(const std::vector<ContactBody>& bodies,
                                             const std::vector<uint32_t>& body_of_slot,
                                             std::vector<ContactRecord>& records,
                                             uint32_t max_iterations, double relative_tolerance,
                                             double h, ContactSolveScratch& scratch, lfem_profile& profile,
                                             ThreadPool* pool) {
    // The whole solve is timed as the normal part; the friction passes' share of it is moved
    // to the friction part at the end.
    const auto solve_start = std::chrono::steady_clock::now();
    const double tolerance = stopping_tolerance(bodies, body_of_slot, records, relative_tolerance, h);
    ContactSolveScratch::Arrays& s = scratch.arrays();
    std::vector<Pair>& pairs = s.pairs;
    make_pairs(bodies, body_of_slot, records, pairs);
    const uint32_t groups = group_pairs(bodies, body_of_slot, records, s);
    const std::vector<uint32_t>& begin = s.group_begin;
    const std::vector<uint32_t>& order = s.order;
    std::vector<GroupResult>& results = s.results;
    results.assign(groups, GroupResult{});
    parallel_for(pool, groups, [&](uint32_t g) {
        solve_group(records, pairs, order.data() + begin[g], begin[g + 1] - begin[g], max_iterations,
                    tolerance, results[g]);
    });

    // Iterations and residual of the slowest group to converge, the deepest penetration.
    ContactSolveResult result;
    result.converged = true;
    double seconds = 0.0, friction_seconds = 0.0;
    bool any_friction = false;
    for (const GroupResult& g : results) {
        result.iterations = std::max(result.iterations, g.solve.iterations);
        result.residual = std::max(result.residual, g.solve.residual);
        result.converged = result.converged && g.solve.residual <= tolerance;
        result.max_penetration = std::max(result.max_penetration, g.solve.max_penetration);
        seconds += g.seconds;
        friction_seconds += g.friction_seconds;
        any_friction = any_friction || g.friction_seconds > 0.0;
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - solve_start).count();
    const double friction = seconds > 0.0 ? total * friction_seconds / seconds : 0.0;
    if (any_friction) {
        profile.friction.seconds += friction;
        profile.friction.calls += 1;
    }
    profile.normal_solve.seconds += total - friction;
    profile.normal_solve.calls += 1;
    return result;
}

}  // namespace lfem
