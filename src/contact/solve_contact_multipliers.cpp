#include "contact/solve_contact_multipliers.h"

#include <algorithm>
#include <cmath>

#include "fem/tet_element.h"

namespace lfem {
namespace {

// The pieces of one constraint the sweeps need, resolved once.
struct Pair {
    double* xp;          // the node
    const double* xp0;   // its step-start position
    double wp;           // its 1/mhat
    double* xk[3];       // the triangle's nodes
    const double* xk0[3];
    double wk[3];        // N_k / mhat_k
    double N[3];         // barycentric weights (1 - t1 - t2, t2, t1)
    double H;            // 1/mhat_node + sum N_k^2 / mhat_k: the pair's scalar block of G M^-1 G^T
    double mu;
};

// Move the pair's nodes by Mhat^-1 G_j^T d: the node by +d/mhat, triangle node k by
// -N_k d/mhat_k. Linear momentum is kept exactly. Returns the largest move.
double apply(Pair& q, const Vec3& d) {
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
        q.xp[k] += q.wp * d[k];
        largest = std::max(largest, std::fabs(q.wp * d[k]));
    }
    for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) {
            const double move = q.N[v] * q.wk[v] * d[k];
            q.xk[v][k] -= move;
            largest = std::max(largest, std::fabs(move));
        }
    return largest;
}

// Gap n . (x_node - sum N_k x_k) of the pair's current positions.
double gap_of(const Pair& q, const Vec3& n) {
    double g = 0.0;
    for (int k = 0; k < 3; ++k) {
        double s = q.xp[k];
        for (int v = 0; v < 3; ++v) s -= q.N[v] * q.xk[v][k];
        g += n[k] * s;
    }
    return g;
}

}  // namespace

ContactSolveResult solve_contact_multipliers(const std::vector<ContactBody>& bodies,
                                             const std::vector<uint32_t>& body_of_slot,
                                             std::vector<ContactRecord>& records,
                                             uint32_t max_iterations, double tolerance) {
    ContactSolveResult result;
    std::vector<Pair> pairs(records.size());
    for (std::size_t j = 0; j < records.size(); ++j) {
        ContactRecord& r = records[j];  // shape contacts lend their surface points
        const ContactBody& a = bodies[body_of_slot[r.body_a]];
        const ContactBody& b = bodies[body_of_slot[r.body_b]];
        Pair& q = pairs[j];
        q.xp = a.x + 3 * std::size_t(r.node);
        q.xp0 = a.x_start + 3 * std::size_t(r.node);
        q.wp = a.inv_mass ? a.inv_mass[r.node] : 0.0;
        q.N[0] = 1.0 - r.t1 - r.t2;
        q.N[1] = r.t2;
        q.N[2] = r.t1;
        q.H = q.wp;
        if (r.shape != UINT32_MAX) {
            // A rigid shape: one immovable point, the touched surface point, moving with the
            // shape from its start to its end position (friction slips relative to it).
            for (int v = 0; v < 3; ++v) {
                q.xk[v] = r.point_end;
                q.xk0[v] = r.point_start;
                q.wk[v] = 0.0;
            }
        } else {
            for (int v = 0; v < 3; ++v) {
                q.xk[v] = b.x + 3 * std::size_t(r.triangle[v]);
                q.xk0[v] = b.x_start + 3 * std::size_t(r.triangle[v]);
                q.wk[v] = b.inv_mass ? b.inv_mass[r.triangle[v]] : 0.0;
                q.H += q.N[v] * q.N[v] * q.wk[v];
            }
        }
        q.mu = pair_friction(a.friction, b.friction);
    }
    // Warm start: the multipliers the records carry in (last step's, for the same node and
    // body) are applied first, so a resting contact starts converged.
    for (std::size_t j = 0; j < records.size(); ++j) {
        ContactRecord& r = records[j];
        if (!(pairs[j].H > 0.0)) {
            r.lambda_n = 0.0, r.lambda_t[0] = r.lambda_t[1] = r.lambda_t[2] = 0.0;
            continue;
        }
        const Vec3 n(r.normal);
        Vec3 lt(r.lambda_t);
        lt -= n * n.dot(lt);  // the normal may have turned since: keep the tangential part
        if (pairs[j].mu == 0.0) lt.setZero();
        for (int k = 0; k < 3; ++k) r.lambda_t[k] = lt[k];
        apply(pairs[j], r.lambda_n * n + lt);
    }

    for (uint32_t sweep = 0; sweep < max_iterations; ++sweep) {
        double largest = 0.0;
        for (std::size_t j = 0; j < records.size(); ++j) {
            ContactRecord& r = records[j];
            Pair& q = pairs[j];
            if (!(q.H > 0.0)) continue;  // both sides immovable: nothing to solve
            const Vec3 n(r.normal);
            // Normal: lambda_n <- max(0, lambda_n - (g - g_target)/H); the clamp is the
            // paper's tension release.
            const double g = gap_of(q, n) + r.offset;
            const double lambda_n = std::max(0.0, r.lambda_n - g / q.H);
            largest = std::max(largest, apply(q, (lambda_n - r.lambda_n) * n));
            r.lambda_n = lambda_n;
            if (q.mu == 0.0) continue;  // frictionless: no tangential work at all
            // Friction: the tangential slip of the node relative to the triangle over the step,
            // cancelled by the stick trial, then returned onto the Coulomb cone (eq. 7).
            Vec3 slip;
            for (int k = 0; k < 3; ++k) {
                double s = q.xp[k] - q.xp0[k];
                for (int v = 0; v < 3; ++v) s -= q.N[v] * (q.xk[v][k] - q.xk0[v][k]);
                slip[k] = s;
            }
            slip -= n * n.dot(slip);
            const Vec3 lt_old(r.lambda_t);
            Vec3 lt = lt_old - slip / q.H;
            const double cap = q.mu * r.lambda_n, norm = lt.norm();
            r.sliding = norm > cap;
            if (r.sliding) lt *= norm > 0.0 ? cap / norm : 0.0;
            largest = std::max(largest, apply(q, lt - lt_old));
            for (int k = 0; k < 3; ++k) r.lambda_t[k] = lt[k];
        }
        result.iterations = sweep + 1;
        result.residual = largest;
        if (largest <= tolerance) break;
    }
    for (std::size_t j = 0; j < records.size(); ++j) {
        records[j].gap_after = gap_of(pairs[j], Vec3(records[j].normal));
        result.max_penetration = std::max(result.max_penetration, -(records[j].gap_after + records[j].offset));
    }
    return result;
}

}  // namespace lfem
