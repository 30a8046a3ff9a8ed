// One contact constraint as the multiplier solve's sweeps read and write it: its points, weights,
// normal, response and multipliers side by side, so that a sweep streams over an array of these
// and the nodes' positions, and never reads the contact records (they are written back once the
// group has converged). Eq. (4) with the weights of eq. (6), written for every kind of record
// (contact_record.h) as one signed sum over at most four points:
//   g = n . sum_i w_i x_i >= -offset,
// the weights of body_a's side positive and summing to 1, body_b's negative: a node against a
// triangle is w = (1, -N_1, -N_2, -N_3), crossed edges (1 - s, s, -(1 - t), -t), a triangle
// against a shape's point (N_1, N_2, N_3, -1).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/math.h"
#include "contact/constraint_point.h"
#include "contact/contact_body.h"
#include "contact/contact_record.h"

namespace lfem {

struct ConstraintPair {
    PointRef point[4];    // body_a's side (a node, an edge's two, a face's three), then body_b's
                          // (a triangle's nodes, an edge's two, or one immovable point)
    double move[4] = {0, 0, 0, 0};  // how far a unit force moves each along any direction,
                                    // signed: w_i/mhat_i (0: it cannot move)
    double w[4] = {1, 0, 0, 0};     // the signed weights
    Vec3 n = Vec3::Zero();          // the record's unit normal
    Vec3 start = Vec3::Zero();      // x_node - sum N_k x_k at the start of the step (the slip's origin)
    double offset = 0;              // the record's kept overlap: target gap -offset
    double H = 0;                   // the pair's scalar block of G Mhat^-1 G^T along the normal
    // An edge pair's compliance (m/N; 0 for every other pair): it may yield compliance * lambda_n,
    // at most `yield` (m) deep (constraint_pair.cpp, make_constraint_pair).
    double compliance = 0;
    double yield = 0;
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
    uint8_t points = 4;             // how many of point[] are used
    uint8_t a_points = 1;           // how many of them are body_a's
    bool fixed = false;             // body_b's side is one immovable point (a shape's, a static
                                    // triangle's)
    bool rigid = false;             // some point is a rigid body's: the general path
    bool sliding = false;
};

// The pair of record r (a point of a against a point of b), its multipliers the record's (the
// warm start). `fixed`: 6 numbers of scratch where the point of an immovable triangle or edge
// goes (at the end of the step and at its start), kept for the solve.
ConstraintPair make_constraint_pair(const ContactBody& a, const ContactBody& b, const ContactRecord& r,
                                    double* fixed);

// The gap the solve left as the next step's detection will measure it (ContactRecord::plane_gap).
double plane_gap(const ConstraintPair& q, double gap_after);

// Move the pair's points by Mhat^-1 G^T d: point i by w_i d / mhat_i (the node by +d, triangle
// node k by -N_k d: linear momentum kept). Returns the largest move. Deformable nodes and
// immovable points, the sweeps' usual case, take the inline path: a call per point cost more
// than the arithmetic.
double apply_general(ConstraintPair& q, const Vec3& d);
inline double apply(ConstraintPair& q, const Vec3& d) {
    if (__builtin_expect(q.rigid, 0)) return apply_general(q, d);
    const double size = d.cwiseAbs().maxCoeff();
    double largest = 0.0;
    for (int i = 0; i < q.points; ++i) {
        const double m = q.move[i];
        if (m == 0.0) continue;
        double* x = q.point[i].x;
        x[0] += m * d[0], x[1] += m * d[1], x[2] += m * d[2];
        largest = std::max(largest, std::fabs(m) * size);
    }
    return largest;
}

// sum w_i x_i (the node's place less the triangle point's), and its change over the step.
inline Vec3 relative_position(const ConstraintPair& q) {
    if (__builtin_expect(q.rigid, 0)) {
        Vec3 r = q.w[0] * q.point[0].position();
        for (int v = 1; v < q.points; ++v) r += q.w[v] * q.point[v].position();
        return r;
    }
    const double* p = q.point[0].x;
    const double w0 = q.w[0];
    Vec3 r(w0 * p[0], w0 * p[1], w0 * p[2]);
    for (int v = 1; v < q.points; ++v) {
        const double* t = q.point[v].x;
        const double w = q.w[v];
        r[0] += w * t[0], r[1] += w * t[1], r[2] += w * t[2];
    }
    return r;
}
inline Vec3 relative_motion(const ConstraintPair& q) { return relative_position(q) - q.start; }

// body_a's point: the node, or the weighted point of its edge or face.
Vec3 side_a_point(const ConstraintPair& q);

}  // namespace lfem
