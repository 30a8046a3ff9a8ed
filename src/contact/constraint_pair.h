// One node-to-triangle (or node-to-shape) constraint as the multiplier solve's sweeps read and
// write it: its points, weights, normal, response and multipliers side by side, so that a sweep
// streams over an array of these and the nodes' positions, and never reads the contact records
// (they are written back once the group has converged). Eq. (4) with the weights of eq. (6):
//   g = n . (x_node - sum N_k x_k) >= -offset.
#pragma once

#include <algorithm>
#include <cstdint>

#include "common/math.h"
#include "contact/constraint_point.h"
#include "contact/contact_body.h"
#include "contact/contact_record.h"

namespace lfem {

struct ConstraintPair {
    PointRef point[4];    // the node, then the triangle's nodes (or one immovable point)
    double move[4] = {0, 0, 0, 0};  // how far a unit force moves each along any direction: the
                                    // node's 1/mhat, triangle node k's N_k/mhat_k (0: it cannot move)
    double N[3] = {1, 0, 0};        // barycentric weights (1 - t1 - t2, t2, t1)
    Vec3 n = Vec3::Zero();          // the record's unit normal
    Vec3 start = Vec3::Zero();      // x_node - sum N_k x_k at the start of the step (the slip's origin)
    double offset = 0;              // the record's kept overlap: target gap -offset
    double H = 0;                   // the pair's scalar block of G Mhat^-1 G^T along the normal
    double mu = 0;
    double lambda_n = 0;            // N, the multipliers (the record's, written back)
    Vec3 lambda_t = Vec3::Zero();
    // What the last sweep found before updating the pair: its gap and its tangential slip (the
    // sweeps stop when these no longer change, solve_contact_multipliers.cpp).
    double seen_gap = 0;
    Vec3 seen_slip = Vec3::Zero();
    // m: how far the node closed on the face along n from the start of the step to the
    // prediction x*, before the solve (an impact's speed times h; the events report it).
    double approach = 0;
    uint8_t points = 4;             // 2: the other side is one immovable point (a shape's, a
                                    // static triangle's)
    bool rigid = false;             // some point is a rigid body's: the general path
    bool sliding = false;

    bool fixed() const { return points == 2; }
};

// The pair of record r (node of a against a triangle or shape of b), its multipliers the
// record's (the warm start). `fixed`: 6 numbers of scratch where the point of an immovable
// triangle goes (at the end of the step and at its start), kept for the solve.
ConstraintPair make_constraint_pair(const ContactBody& a, const ContactBody& b, const ContactRecord& r,
                                    double* fixed);

// The gap the solve left as the next step's detection will measure it (ContactRecord::plane_gap).
double plane_gap(const ConstraintPair& q, double gap_after);

// Move the pair's points by Mhat^-1 G^T d: the node by +d, triangle node k by -N_k d (linear
// momentum kept). Returns the largest move. Deformable nodes and immovable points, the sweeps'
// usual case, take the inline path: a call per point cost more than the arithmetic.
double apply_general(ConstraintPair& q, const Vec3& d);
inline double apply(ConstraintPair& q, const Vec3& d) {
    if (__builtin_expect(q.rigid, 0)) return apply_general(q, d);
    const double size = d.cwiseAbs().maxCoeff();
    double largest = 0.0;
    for (int i = 0; i < q.points; ++i) {
        const double m = q.move[i];
        if (m == 0.0) continue;
        double* x = q.point[i].x;
        const double s = i == 0 ? m : -m;
        x[0] += s * d[0], x[1] += s * d[1], x[2] += s * d[2];
        largest = std::max(largest, m * size);
    }
    return largest;
}

// x_node - sum N_k x_k, and its change over the step.
inline Vec3 relative_position(const ConstraintPair& q) {
    if (__builtin_expect(q.rigid, 0)) {
        Vec3 r = q.point[0].position();
        for (int v = 1; v < q.points; ++v) r -= q.N[v - 1] * q.point[v].position();
        return r;
    }
    const double* p = q.point[0].x;
    Vec3 r(p[0], p[1], p[2]);
    for (int v = 1; v < q.points; ++v) {
        const double* t = q.point[v].x;
        const double w = q.N[v - 1];
        r[0] -= w * t[0], r[1] -= w * t[1], r[2] -= w * t[2];
    }
    return r;
}
inline Vec3 relative_motion(const ConstraintPair& q) { return relative_position(q) - q.start; }

}  // namespace lfem
