#include "contact/constraint_pair.h"

namespace lfem {
namespace {

// An edge pair's compliance, as a fraction of its own response H, and the deepest it yields,
// as a fraction of the contact length (make_constraint_pair).
constexpr double kEdgeCompliance = 0.1;
constexpr double kEdgeYield = 5e-3;

// The inverse effective mass along the normal of side [first, end) of q, added to H term by
// term (the order of the sums is the order of the points). Two weights on one rigid body add
// up before squaring: the exact block is (sum w_k J_k) M^-1 (sum w_k J_k)^T; with the centre
// and arm of a weighted point of a rigid body, it is the response at that point.
// `sign`: the side's sign (+1 for body_a's, -1 for body_b's), which makes its weights positive.
void add_side_response(ConstraintPair& q, int first, int end, const RigidResponse* rigid, double sign) {
    if (rigid) {
        Vec3 arm = Vec3::Zero();
        for (int v = first; v < end; ++v) arm += (sign * q.w[v]) * q.point[v].arm();
        q.H += rigid_response(*rigid, arm, q.n);
        return;
    }
    for (int v = first; v < end; ++v) q.H += q.w[v] * q.w[v] * q.point[v].response(q.n);
}

// body_b's side as one immovable point (a shape's surface point, or the weighted point of a
// static triangle or edge), at index i.
void set_fixed_point(ConstraintPair& q, int i, double* end, const double* start) {
    q.point[i] = PointRef{};
    q.point[i].x = end;  // never written: its move is 0
    q.point[i].x0 = start;
    q.w[i] = -1.0;
    q.points = uint8_t(i + 1);
    q.fixed = true;
}

}  // namespace

ConstraintPair make_constraint_pair(const ContactBody& a, const ContactBody& b, const ContactRecord& r,
                                    double* fixed) {
    ConstraintPair q;
    q.n = Vec3(r.normal);
    q.offset = r.offset;
    q.lambda_n = r.lambda_n;
    q.lambda_t = Vec3(r.lambda_t);
    q.sliding = r.sliding;
    // body_a's side: the node, or an edge's or a face's nodes with their weights.
    if (r.kind == ContactKind::node_face) {
        q.point[0] = point_of(a, r.node);
        q.w[0] = 1.0;
        q.a_points = 1;
    } else {
        q.a_points = r.side_nodes();
        for (int i = 0; i < q.a_points; ++i) q.point[i] = point_of(a, r.nodes_a[i]), q.w[i] = r.weights_a[i];
    }
    const int na = q.a_points;
    const double N[3] = {1.0 - r.t1 - r.t2, r.t2, r.t1};
    const int nb = r.side_nodes();
    q.H = 0.0;
    add_side_response(q, 0, na, a.rigid, 1.0);
    if (r.shape != UINT32_MAX) {
        // A rigid shape: one immovable point, the touched surface point, moving with the
        // shape from its start to its end position (friction slips relative to it). The record
        // lends it (its point_end, point_start), and outlives the solve.
        set_fixed_point(q, na, const_cast<double*>(r.point_end), r.point_start);
    } else if (!is_movable(b)) {
        // A triangle (or an edge) of a static or kinematic body (or of a sleeping one): the
        // solve cannot move it, so its point sum N_k x_k is taken once, not in every sweep, and
        // the pair is against one immovable point, as against a shape.
        Vec3 end = Vec3::Zero(), start = Vec3::Zero();
        for (int v = 0; v < nb; ++v) {
            end += N[v] * Vec3(b.x + 3 * std::size_t(r.triangle[v]));
            start += N[v] * Vec3(b.x_start + 3 * std::size_t(r.triangle[v]));
        }
        for (int k = 0; k < 3; ++k) fixed[k] = end[k], fixed[3 + k] = start[k];
        set_fixed_point(q, na, fixed, fixed + 3);
    } else {
        for (int v = 0; v < nb; ++v) q.point[na + v] = point_of(b, r.triangle[v]), q.w[na + v] = -N[v];
        q.points = uint8_t(na + nb);
        add_side_response(q, na, na + nb, b.rigid, -1.0);
    }
    // An edge pair yields a little under its force. A lower cube's top edge under a shifted
    // upper face (a pile, a pyramid) is held by the edge pair where it crosses the upper's
    // bottom edge and by the node pairs of all four nodes around it: constraints so nearly
    // dependent that projected Gauss-Seidel crawled. A compliance of a tenth of the pair's own
    // response conditions them; under-relaxing the updates instead (the same step towards the
    // exact target) did not. Measured over four placements of each scene (the cubes shifted by
    // up to 0.5 mm), sweeps per sub-step on one thread: the 55-cube pyramid 27 exact, 10 with
    // the compliance (11 without the edge pass); the 48-cube pile landing 27.5 and 23 (18);
    // at rest the same, 15.5 and 15.6 over ten placements. The depth it lets the edges cross is
    // capped at half the 1 % of an element a contact may reach, beyond which the pair is exact
    // again (a large force cannot push an edge deeper); capped at the residual depth of a
    // resting contact (1e-3) instead, pairs at rest switched between the two and the pile at
    // rest took up to 32 sweeps.
    if (r.kind == ContactKind::edge_edge) {
        q.compliance = kEdgeCompliance * q.H;
        q.yield = kEdgeYield * contact_length(a, b);
    }
    q.rigid = a.rigid != nullptr || (!q.fixed && b.rigid != nullptr);
    q.start = q.w[0] * Vec3(q.point[0].x0);
    Vec3 predicted = q.w[0] * Vec3(q.point[0].x);  // x*: a rigid point's x is its prediction
    for (int v = 1; v < q.points; ++v) {
        q.start += q.w[v] * Vec3(q.point[v].x0);
        predicted += q.w[v] * Vec3(q.point[v].x);
    }
    q.approach = q.n.dot(q.start - predicted);
    for (int v = 0; v < q.points; ++v) q.move[v] = q.point[v].rigid ? 0.0 : q.w[v] * q.point[v].w;
    q.mu = pair_friction(a.friction, b.friction);
    return q;
}

double apply_general(ConstraintPair& q, const Vec3& d) {
    double largest = 0.0;
    for (int v = 0; v < q.points; ++v)
        if (q.w[v] != 0.0) largest = std::max(largest, q.point[v].push(q.w[v] * d));
    return largest;
}

Vec3 side_a_point(const ConstraintPair& q) {
    Vec3 p = q.w[0] * q.point[0].position();
    for (int v = 1; v < q.a_points; ++v) p += q.w[v] * q.point[v].position();
    return p;
}

// The node's distance from the plane of the triangle where its corners are now. The constraint
// held the gap along the normal the triangle had at x*, at the weights of the point found
// there; a triangle that the solve turned (a soft face pressed at one corner, a fold closing)
// leaves the node off its new plane by the turn times the node's distance from the corner. The
// next step allows the pair that depth and makes it up (detect_node_triangle.cpp,
// kept_offset); measured along the old normal, the miss grew unseen, step after step, until the
// node was deeper than the pair had been left and was dropped. A shape's surface point, an
// immovable triangle's, and the features (an edge's point, a face's against a shape): along the
// normal (gap_after).
double plane_gap(const ConstraintPair& q, double gap_after) {
    if (q.fixed || q.a_points != 1 || q.points != 4) return gap_after;
    const Vec3 a = q.point[1].position();
    const Vec3 plane = (q.point[2].position() - a).cross(q.point[3].position() - a);
    const double area2 = plane.norm();
    if (!(area2 > 0.0)) return q.n.dot(relative_position(q));  // collapsed: no plane
    return plane.dot(q.point[0].position() - a) / area2;
}

}  // namespace lfem
