#include "contact/constraint_pair.h"

namespace lfem {

ConstraintPair make_constraint_pair(const ContactBody& a, const ContactBody& b, const ContactRecord& r,
                                    double* fixed) {
    ConstraintPair q;
    q.n = Vec3(r.normal);
    q.offset = r.offset;
    q.lambda_n = r.lambda_n;
    q.lambda_t = Vec3(r.lambda_t);
    q.sliding = r.sliding;
    q.point[0] = point_of(a, r.node);
    q.N[0] = 1.0 - r.t1 - r.t2;
    q.N[1] = r.t2;
    q.N[2] = r.t1;
    q.H = q.point[0].response(q.n);
    if (r.shape != UINT32_MAX) {
        // A rigid shape: one immovable point, the touched surface point, moving with the
        // shape from its start to its end position (friction slips relative to it). The record
        // lends it (its point_end, point_start), and outlives the solve.
        q.N[0] = 1.0, q.N[1] = q.N[2] = 0.0;
        q.point[1].x = const_cast<double*>(r.point_end);  // never written: its move is 0
        q.point[1].x0 = r.point_start;
        q.points = 2;
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
        q.point[1].x = fixed;
        q.point[1].x0 = fixed + 3;
        q.points = 2;
    } else {
        for (int v = 0; v < 3; ++v) {
            q.point[v + 1] = point_of(b, r.triangle[v]);
            q.H += q.N[v] * q.N[v] * q.point[v + 1].response(q.n);
        }
        // Two weights on one rigid body add up before squaring: the exact block is
        // (sum N_k J_k) M^-1 (sum N_k J_k)^T; with the centre and arm of a barycentric
        // point of a rigid triangle, it is the response at that point.
        if (b.rigid) {
            Vec3 arm = Vec3::Zero();
            for (int v = 0; v < 3; ++v) arm += q.N[v] * q.point[v + 1].arm();
            q.H = q.point[0].response(q.n) + rigid_response(*b.rigid, arm, q.n);
        }
    }
    q.rigid = a.rigid != nullptr || (q.points == 4 && b.rigid != nullptr);
    q.start = Vec3(q.point[0].x0);
    Vec3 predicted(q.point[0].x);  // x*: a rigid point's x is its prediction
    for (int v = 1; v < q.points; ++v) {
        q.start -= q.N[v - 1] * Vec3(q.point[v].x0);
        predicted -= q.N[v - 1] * Vec3(q.point[v].x);
    }
    q.approach = q.n.dot(q.start - predicted);
    q.move[0] = q.point[0].rigid ? 0.0 : q.point[0].w;
    for (int v = 1; v < q.points; ++v) q.move[v] = q.point[v].rigid ? 0.0 : q.N[v - 1] * q.point[v].w;
    q.mu = pair_friction(a.friction, b.friction);
    return q;
}

double apply_general(ConstraintPair& q, const Vec3& d) {
    double largest = q.point[0].push(d);
    for (int v = 1; v < q.points; ++v)
        if (q.N[v - 1] != 0.0) largest = std::max(largest, q.point[v].push(-q.N[v - 1] * d));
    return largest;
}

// The node's distance from the plane of the triangle where its corners are now. The constraint
// held the gap along the normal the triangle had at x*, at the weights of the point found
// there; a triangle that the solve turned (a soft face pressed at one corner, a fold closing)
// leaves the node off its new plane by the turn times the node's distance from the corner. The
// next step allows the pair that depth and makes it up (detect_node_triangle.cpp,
// kept_offset); measured along the old normal, the miss grew unseen, step after step, until the
// node was deeper than the pair had been left and was dropped. A shape's surface point or an
// immovable triangle's: along the normal (gap_after).
double plane_gap(const ConstraintPair& q, double gap_after) {
    if (q.fixed()) return gap_after;  // a plane that does not turn: the gap along the normal
    const Vec3 a = q.point[1].position();
    const Vec3 plane = (q.point[2].position() - a).cross(q.point[3].position() - a);
    const double area2 = plane.norm();
    if (!(area2 > 0.0)) return q.n.dot(relative_position(q));  // collapsed: no plane
    return plane.dot(q.point[0].position() - a) / area2;
}

}  // namespace lfem
