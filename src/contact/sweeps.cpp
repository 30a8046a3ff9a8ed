#include "contact/sweeps.h"

#include <algorithm>
#include <cmath>

namespace lfem {

bool warm_start_pairs(ConstraintPair* pairs, uint32_t count) {
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

namespace {

// A pair's multiplier for gap g (eq. 4's update, solved for the pair alone): its target gap is
// -compliance * lambda_n (constraint_pair.h; 0 but for an edge pair), the gap after the update
// g + H (lambda_n' - lambda_n), so lambda_n' = lambda_n - (g + compliance lambda_n) / (H +
// compliance), which is lambda_n - g / H to the bit at compliance 0; where it would yield
// deeper than q.yield, the exact update to the gap -yield.
double normal_update(const ConstraintPair& q, double g) {
    const double soft = q.lambda_n - (g + q.compliance * q.lambda_n) / (q.H + q.compliance);
    return q.compliance * soft <= q.yield ? soft : q.lambda_n - (g + q.yield) / q.H;
}

}  // namespace

double normal_pass(ConstraintPair* pairs, uint32_t count, bool first) {
    double largest = 0.0;
    for (uint32_t k = 0; k < count; ++k) {
        ConstraintPair& q = pairs[k];
        if (!(q.H > 0.0)) continue;  // both sides immovable: nothing to solve
        const double g = q.n.dot(relative_position(q)) + q.offset;
        const double lambda_n = std::max(0.0, normal_update(q, g));
        const double moved = apply(q, (lambda_n - q.lambda_n) * q.n);
        largest = std::max(largest, first ? moved : lambda_n > 0.0 || g < 0.0 ? std::fabs(g - q.seen_gap) : 0.0);
        q.seen_gap = g;
        q.lambda_n = lambda_n;
    }
    return largest;
}

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

double write_back(const ConstraintPair* pairs, uint32_t count, const uint32_t* order,
                  std::vector<ContactRecord>& records) {
    double deepest = 0.0;
    for (uint32_t k = 0; k < count; ++k) {
        ContactRecord& r = records[order[k]];
        const ConstraintPair& q = pairs[k];
        r.lambda_n = q.lambda_n;
        for (int d = 0; d < 3; ++d) r.lambda_t[d] = q.lambda_t[d];
        r.sliding = q.sliding;
        r.gap_after = q.n.dot(relative_position(q));
        r.plane_gap = plane_gap(q, r.gap_after);
        // The true depth, kept overlaps included (they are let out over several steps).
        deepest = std::max(deepest, -r.gap_after);
    }
    return deepest;
}

}  // namespace lfem
