// A slave node against one face of another body (a boundary triangle, eqs. 5 and 6) or one of
// its rigid shapes: the tests the narrow phase runs on every candidate, and the constraint
// record they make.
#include "contact/node_face.h"

#include <algorithm>
#include <cmath>

#include "common/ray_triangle.h"
#include "contact/contact_candidates.h"
#include "contact/detection_tolerances.h"
#include "contact/warm_start.h"

namespace lfem {
namespace {

// Barycentric weights (wa, wb, wc) of the projection of p onto the plane of triangle abc.
void barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double w[3]) {
    const Vec3 e0 = b - a, e1 = c - a, d = p - a;
    const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
    const double d20 = d.dot(e0), d21 = d.dot(e1);
    const double denom = d00 * d11 - d01 * d01;
    w[1] = (d11 * d20 - d01 * d21) / denom;
    w[2] = (d00 * d21 - d01 * d20) / denom;
    w[0] = 1.0 - w[1] - w[2];
}

// How deep behind triangle tri of b (unit normal n at the start of the step) node x may start,
// when the last step held it against triangle `held` of b and tri shares a vertex with it. A
// node held at a surface that bends round it (a soft body wrapped round a ridge's corner, a
// fold closing) starts behind the next face's plane by up to its distance from the vertex they
// share times the sine of their angle: deeper than the pair was left, yet still at the surface.
// That depth is allowed, up to half a contact length (the reach of an initial overlap, and what
// the narrow phase's skipping allows for), and let out gradually (make_record). Only where the surface turns towards the node
// (tri in front of the held face's plane): at a convex edge (a cube's bottom edge over another
// cube) the node is not behind the next face, and one found there lies beyond the edge; flat
// neighbours allow nothing more; the far side of a thin part shares no vertex with its near side.
double neighbour_allowance(const ContactBody& b, const uint32_t* tri, const Vec3& n, const uint32_t* held,
                           const Vec3& x, double l, double allowance) {
    if (tri[0] == held[0] && tri[1] == held[1] && tri[2] == held[2]) return allowance;
    bool shared[3] = {false, false, false};
    for (int u = 0; u < 3; ++u) shared[u] = tri[u] == held[0] || tri[u] == held[1] || tri[u] == held[2];
    if (!shared[0] && !shared[1] && !shared[2]) return allowance;
    const Vec3 t0 = position(b.x_start, tri[0]), t1 = position(b.x_start, tri[1]), t2 = position(b.x_start, tri[2]);
    const Vec3 h0 = position(b.x_start, held[0]);
    const Vec3 area_held = (position(b.x_start, held[1]) - h0).cross(position(b.x_start, held[2]) - h0);
    if (!(area_held.dot(t0 + t1 + t2 - 3.0 * h0) > 0.0)) return allowance;  // turned away: a convex edge
    double from_shared = HUGE_VAL;
    const Vec3* corner[3] = {&t0, &t1, &t2};
    for (int u = 0; u < 3; ++u)
        if (shared[u]) from_shared = std::min(from_shared, (x - *corner[u]).norm());
    const double sine = n.cross(area_held).norm() / area_held.norm();
    return std::max(allowance, std::min(kInitialDepth * l, from_shared * sine));
}

// The unit normal n of triangle t of b (corners pa, pb, pc at x*) at the end of the step; false
// for a collapsed face, which has none.
bool face_normal(const ContactBody& b, uint32_t t, const FaceStep* face, const Vec3& pa, const Vec3& pb,
                 const Vec3& pc, Vec3& n) {
    if (b.face_normals) {  // a static body's, made once
        n = position(b.face_normals, t);
        return n.squaredNorm() != 0.0;
    }
    if (face) {  // a moving body's, made once per sub-step
        n = face->normal_end;
        return face->valid;
    }
    const Vec3 n_end = (pb - pa).cross(pc - pa);  // a sleeping body: static while asleep, its
    const double area2 = n_end.norm();            // face normals not made
    n = n_end / area2;
    return area2 > 0.0;
}

// Does one of the triangles around node p of `a` (at x*) face n, within about 75 degrees?
bool some_face_faces(const ContactBody& a, uint32_t p, const Vec3& n) {
    for (uint32_t k = a.node_triangle_begin[p]; k < a.node_triangle_begin[p + 1]; ++k) {
        const uint32_t* tri = &a.triangles[3 * std::size_t(a.node_triangles[k])];
        const Vec3 x0 = position(a.x, tri[0]);
        const Vec3 m = (position(a.x, tri[1]) - x0).cross(position(a.x, tri[2]) - x0);
        if (m.dot(n) < -0.25 * m.norm()) return true;
    }
    return false;
}

// Does point x lie inside tet e of b (at x^n, by its corners) by more than 1e-3 of its height,
// and is e none of node p's own (when a is b)?
bool in_element(const ContactBody& a, uint32_t p, const ContactBody& b, uint32_t e, const Vec3& x) {
    const uint32_t* nodes = b.elements + std::size_t(b.element_stride) * e;
    if (&a == &b)
        for (uint32_t i = 0; i < b.element_stride; ++i)
            if (nodes[i] == p) return false;
    const Vec3 v0 = position(b.x_start, nodes[0]);
    const Vec3 e1 = position(b.x_start, nodes[1]) - v0, e2 = position(b.x_start, nodes[2]) - v0,
               e3 = position(b.x_start, nodes[3]) - v0, d = x - v0;
    const double volume = e1.dot(e2.cross(e3));
    if (!(volume > 0.0)) return false;
    const double margin = 1e-3 * volume;
    const double w1 = d.dot(e2.cross(e3)), w2 = e1.dot(d.cross(e3)), w3 = e1.dot(e2.cross(d));
    return w1 > margin && w2 > margin && w3 > margin && volume - w1 - w2 - w3 > margin;
}

}  // namespace

uint32_t across_edge(const ContactBody& b, uint32_t t, uint32_t u, uint32_t v) {
    for (uint32_t j = b.node_triangle_begin[u]; j < b.node_triangle_begin[u + 1]; ++j) {
        const uint32_t o = b.node_triangles[j];
        const uint32_t* other = &b.triangles[3 * std::size_t(o)];
        if (o != t && (other[0] == v || other[1] == v || other[2] == v)) return o;
    }
    return UINT32_MAX;
}

bool inside_near(const ContactBody& a, uint32_t p, const ContactBody& b, const uint32_t* tri, const Vec3& x) {
    if (!b.node_elements) return false;
    for (int v = 0; v < 3; ++v)
        for (uint32_t k = b.node_element_begin[tri[v]]; k < b.node_element_begin[tri[v] + 1]; ++k)
            if (in_element(a, p, b, b.node_elements[k], x)) return true;
    return false;
}

namespace {

// The rule that a face turned the same way as the node's surface is the far side of an edge
// the node sits on (test_node_triangle), for a node at triangle t of b (unit normal n) whose
// point w lies within the edge band of an edge. It holds when the node's averaged normal
// points the same way as n and none of the triangles around the node faces n (a thin strip's
// corner: its averaged normal lies between its two faces' and may point away from a face that
// one of them meets), unless the node has passed the face across every edge near its point:
// started behind it deeper than the pair was left (`allowance`) and lies inside b. Then this
// face is the last one between it and the outside (a corner of a soft cube on another, which
// bulges out under it and engulfs it: the face it rested on is behind it, the side face holds).
bool faces_away(const ContactBody& a, uint32_t p, const Vec3& node_normal, const ContactBody& b, uint32_t t,
                const double w[3], const Vec3& n, const Vec3& x_start, double allowance) {
    if (!(node_normal.squaredNorm() > 0.0) || !(n.dot(node_normal) >= 0.0) || some_face_faces(a, p, n)) return false;
    const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
    for (int k = 0; k < 3; ++k) {
        if (!(w[k] < kEdgeBand)) continue;
        const uint32_t o = across_edge(b, t, tri[(k + 1) % 3], tri[(k + 2) % 3]);
        if (o == UINT32_MAX) return true;  // an open border
        const uint32_t* other = &b.triangles[3 * std::size_t(o)];
        const Vec3 s0 = position(b.x_start, other[0]);
        const Vec3 m = (position(b.x_start, other[1]) - s0).cross(position(b.x_start, other[2]) - s0);
        if (!(m.dot(x_start - s0) < -allowance * m.norm()) || !inside_near(a, p, b, tri, x_start)) return true;
    }
    return false;
}

// The barycentric weights w of the point where node x meets triangle q (corners at the start
// of the step) -> e (at its end). A path that crossed the plane: where it crossed (eq. 5), the
// triangle moved by the same fraction of its own step; at or behind the face: the projection at
// the end. False when the node passes beside a static face (see below).
bool contact_point(const Vec3& x_start, const Vec3& x_end, double start_gap, double gap, const Vec3 q[3],
                   const Vec3 e[3], bool still, double residual, double w[3]) {
    if (!(start_gap >= 0.0 && gap < 0.0)) {
        barycentric(x_end, e[0], e[1], e[2], w);
        return true;
    }
    // Against a static face the weights are affine along the path: outside at both ends by
    // more than the edge tolerance (and a margin for rounding), outside in between.
    double w_end[3];
    bool end_known = false;  // w_end holds the projection of x*
    if (still) {
        double w_start[3];
        barycentric(x_start, e[0], e[1], e[2], w_start);
        barycentric(x_end, e[0], e[1], e[2], w_end);
        end_known = true;
        for (int k = 0; k < 3; ++k)
            if (w_start[k] < -kEdgeTolerance - 1e-9 && w_end[k] < -kEdgeTolerance - 1e-9) return false;
    }
    const double s = start_gap / (start_gap - gap);
    barycentric(x_start + s * (x_end - x_start), q[0] + s * (e[0] - q[0]), q[1] + s * (e[1] - q[1]),
                q[2] + s * (e[2] - q[2]), w);
    // A node that starts at the face (no further in front than the residual depth) crossed
    // where it started. Sliding across an edge onto this face it started just outside it, on
    // the neighbour, whose test takes its point at the end (it ends behind that one's plane
    // too, beyond the shared edge): neither would hold it. Its point at the end is then its
    // point here, as for a node at or behind the face.
    if (start_gap <= residual && !(std::min({w[0], w[1], w[2]}) >= -kEdgeTolerance)) {
        if (!end_known) barycentric(x_end, e[0], e[1], e[2], w_end);
        for (int k = 0; k < 3; ++k) w[k] = w_end[k];
    }
    return true;
}

}  // namespace

Vec3 node_normal(const ContactBody& a, uint32_t p) {
    Vec3 sum = Vec3::Zero();
    for (uint32_t k = a.node_triangle_begin[p]; k < a.node_triangle_begin[p + 1]; ++k) {
        const uint32_t* tri = &a.triangles[3 * std::size_t(a.node_triangles[k])];
        const Vec3 x0 = position(a.x, tri[0]);
        sum += (position(a.x, tri[1]) - x0).cross(position(a.x, tri[2]) - x0);
    }
    return sum.normalized();
}

double smallest_height(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double longest = std::sqrt(std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
    return longest > 0.0 ? (b - a).cross(c - a).norm() / longest : 0.0;
}

FaceStep face_step(const ContactBody& b, uint32_t t) {
    FaceStep f;
    const uint32_t* tri = &b.triangles[3 * t];
    f.box = triangle_step_box(b, t, 0.0);
    const Vec3 p[3] = {position(b.x, tri[0]), position(b.x, tri[1]), position(b.x, tri[2])};
    const Vec3 q[3] = {position(b.x_start, tri[0]), position(b.x_start, tri[1]), position(b.x_start, tri[2])};
    const Vec3 n_end = (p[1] - p[0]).cross(p[2] - p[0]);
    const Vec3 n_start = (q[1] - q[0]).cross(q[2] - q[0]);
    const double area2 = n_end.norm(), area2_start = n_start.norm();
    f.valid = area2 > 0.0 && area2_start > 0.0;
    if (f.valid) f.normal_end = n_end / area2, f.normal_start = n_start / area2_start;
    const double most = std::max({(p[0] - q[0]).squaredNorm(), (p[1] - q[1]).squaredNorm(), (p[2] - q[2]).squaredNorm()});
    f.motion = std::sqrt(most);
    return f;
}

// Test node p of `a` against triangle t of `b`; keep it in `best` if it is a valid contact
// with less penetration than what best holds.
Outside test_node_triangle(const ContactBody& a, uint32_t p, const NodeNormal& node_normal, const ContactBody& b,
                           uint32_t t, const FaceStep* face, double depth_allowance, const uint32_t* held,
                           const NodeSlots& slots) {
    const uint32_t* tri = &b.triangles[3 * t];
    const Vec3 pa = position(b.x, tri[0]), pb = position(b.x, tri[1]), pc = position(b.x, tri[2]);
    Vec3 n;
    if (!face_normal(b, t, face, pa, pb, pc, n)) return {};
    // Surfaces in contact face each other. A face whose normal points the same way as the
    // node's own surface normal is the far side of an edge the node sits on (a cube's corner
    // node resting on another cube's top face also lies in the plane of its side face, on its
    // edge): taking it would push the node sideways off the edge. Convex edges thus keep the
    // one right face. That choice is for a node at the face and on its edge: one deeper than the
    // residual depth behind it has passed it, whichever way its surface turns (a soft body's
    // bulging side sinking into a floor), one whose point lies well inside the face sits on the
    // face, not on an edge (a corner of a tumbling soft body, its normal turned up by the bend,
    // pressing down on it), and an interior node (no surface around it: normal zero) faces every
    // way. The rule's details are in faces_away below.
    const Vec3 x_end = position(a.x, p), x_start = position(a.x_start, p);
    const double gap = n.dot(x_end - pa);
    const double l = contact_length(a, b);
    if (gap > kCaptureBand * l) return {};
    // A static face is where it was at the start (the same bits), so its start normal is n.
    const bool still = !b.moves;
    const Vec3 qa = still ? pa : position(b.x_start, tri[0]);
    const Vec3& n_start = still ? n : face->normal_start;
    const double start_gap = n_start.dot(x_start - qa);
    const double pair_allowance = depth_allowance;
    if (start_gap < -depth_allowance && held)
        depth_allowance = neighbour_allowance(b, tri, n_start, held, x_start, l, depth_allowance);
    NodeCandidate* slot = &slots.best;
    if (start_gap < -depth_allowance) {
        // Deeper than the pair was left: only a possible initial overlap (checked later), or,
        // against a deformable body, possibly a node inside it (keep_records decides).
        if (start_gap < -kInitialDepth * l) return {};
        slot = slots.deep ? slots.deep : slots.inside;
        if (!slot) return {};
    }
    NodeCandidate& best = slots.best;
    const bool is_inside = slot == slots.inside;
    // The held face counts kHeldFaceMargin better than it is against a face in its plane (within
    // a degree): another face must beat it by more to take the node (detection_tolerances.h).
    double favour = 0.0;
    if (held && slot == &best && best.found && n.dot(best.normal) > kHeldFaceCos) {
        if (same_triangle(tri, held)) favour = kHeldFaceMargin * l;
        else if (best.shape == UINT32_MAX && same_triangle(&b.triangles[3 * std::size_t(best.triangle)], held))
            favour = -kHeldFaceMargin * l;
    }
    // A face no better than the best so far matters only as the second face of a valley
    // (keep_records): one turned from the best's by more than the valley angle.
    const bool second_only = slot == &best && best.found && gap + favour <= best.gap;
    // A face no better than what its slot holds is not taken. Where its point lies outside the
    // triangle, that is noted all the same, so that the narrow phase skips the face until the
    // point could reach it (still_outside in detect_node_triangle.cpp): otherwise the faces
    // around a resting node's, in its plane and as near, came here every sub-step.
    const bool no_better = (second_only && !(slots.accepted && n.dot(best.normal) < kValleyCos)) ||
                           (slot != &best && slot->found && gap <= slot->gap);
    double w[3];
    const Vec3 q[3] = {qa, still ? pb : position(b.x_start, tri[1]), still ? pc : position(b.x_start, tri[2])};
    const Vec3 e[3] = {pa, pb, pc};
    if (!contact_point(x_start, x_end, start_gap, gap, q, e, still, kResidualDepth * l, w)) return {};
    const double lowest = std::min({w[0], w[1], w[2]});
    // A possibly inside node is taken within a wider band: the face is its way out.
    const double band = slots.inside ? kInsideBand : kEdgeTolerance;
    if (!(lowest >= -(is_inside ? kInsideBand : kEdgeTolerance))) {
        // Outside the triangle that was tested (the crossing's, moved part way, or the end's):
        // its smallest height, the end's less what the vertices moved on the way. The margin is
        // what the weight lacks for the widest band this pair may be taken in. (Turned away
        // whether or not it faces away: the skip holds whichever rule would turn it away.)
        Outside out;
        const double margin = -band - lowest;
        if (!(margin > 0.0)) return out;  // a NaN
        out.height = std::max(0.0, smallest_height(pa, pb, pc) - 2.0 * (face ? face->motion : 0.0));
        out.margin = std::min(margin, 0.25);
        return out;
    }
    if (no_better) return {};
    if (!is_inside && gap > -kResidualDepth * l && !(lowest >= kEdgeBand) &&
        faces_away(a, p, node_normal.get(), b, t, w, n, x_start, pair_allowance))
        return {};
    NodeCandidate taken;
    NodeCandidate& c = second_only ? taken : *slot;
    if (slot == &best && best.found && !second_only && slots.accepted) slots.accepted->push_back(best);
    c.found = true;
    c.triangle = t;
    c.shape = UINT32_MAX;
    c.gap = gap;
    c.start_gap = start_gap;
    c.slid = (held && start_gap < -pair_allowance) || is_inside;  // taken deeper than the pair was left
    c.lowest = lowest;
    c.normal = n;
    // Clamp the weights into the triangle: the force goes to its nodes, never outside.
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) sum += (c.w[k] = std::max(0.0, w[k]));
    for (int k = 0; k < 3; ++k) c.w[k] /= sum;
    if (second_only) slots.accepted->push_back(c);
    return {};
}

// Test node p of `a` against rigid shape j of `b`, same rules as for a triangle: within the
// capture band at the end of the step, no deeper at its start than the pair was left, facing
// the node's surface.
// The queries are counted in `counts` (its shape_tests and ccd_queries).
void test_node_shape(const ContactBody& a, uint32_t p, const Vec3& node_normal, const ContactBody& b,
                     uint32_t j, double depth_allowance, NodeCandidate& best, ShapeQueryCounts& counts) {
    const RigidShape& shape = b.shapes[j];
    const ShapePose pose_end = ShapePose::load(b.shape_pose + 7 * std::size_t(j));
    const ShapePose pose_start = ShapePose::load(b.shape_pose_start + 7 * std::size_t(j));
    const Vec3 x_end = position(a.x, p), x_start = position(a.x_start, p);
    const double band = kCaptureBand * a.edge_length;
    const double reach = shape_bounding_radius(shape) + band + (x_end - x_start).norm();
    if ((x_end - pose_end.center).norm() > reach) return;  // far from a bounded shape
    double gap, start_gap;
    Vec3 n, n_start;
    const uint64_t by_ccd = shape.type == ShapeType::convex_hull;
    counts.shape_tests += 1, counts.ccd_queries += by_ccd;
    if (!shape_signed_distance(shape, pose_end, x_end, band, gap, n)) return;
    // At the start the node may be anywhere along its path: ask with the whole path as reach.
    const double path = (x_end - x_start).norm() + band;
    counts.shape_tests += 1, counts.ccd_queries += by_ccd;
    // A node that starts deeper than the pair was left is inside the solid shape all the same
    // (a shape is convex and solid: no thin part to be beyond): it is pushed out, not forgotten.
    const bool fallen = shape_signed_distance(shape, pose_start, x_start, path, start_gap, n_start) &&
                        start_gap < -depth_allowance;
    if (gap > -kResidualDepth * a.edge_length && node_normal.squaredNorm() > 0.0 && n.dot(node_normal) >= 0.0) return;
    if (best.found && gap <= best.gap) return;
    best.found = true;
    best.fallen = fallen;
    best.shape = j;
    best.gap = gap;
    best.start_gap = std::min(0.0, start_gap);
    best.normal = n;
    best.point_end = x_end - gap * n;  // the nearest surface point
    // The same material point of the shape at the start of the step.
    best.point_start = pose_start.center +
                       pose_start.rotation * (pose_end.rotation.conjugate() * (best.point_end - pose_end.center));
}

bool own_triangle_in_reach(const ContactBody& a, uint32_t p, const uint32_t* triangle) {
    const uint32_t begin = a.node_triangle_begin[p], end = a.node_triangle_begin[p + 1];
    if (begin == end) return false;  // an interior node
    return triangle[0] != p && triangle[1] != p && triangle[2] != p;
}

// The constraint of node p of `a` against the candidate face or shape of `b`, warm-started
// from the pair's last record (nullable).
ContactRecord make_record(const ContactBody& a, uint32_t p, const ContactBody& b, const NodeCandidate& c,
                          const ContactRecord* last) {
    ContactRecord r;
    if (last) warm_start(*last, r);
    r.body_a = a.slot;
    r.node = p;
    r.body_b = b.slot;
    r.shape = c.shape;
    for (int k = 0; k < 3; ++k) {
        r.triangle[k] = c.shape == UINT32_MAX ? b.triangles[3 * c.triangle + k] : UINT32_MAX;
        r.normal[k] = c.normal[k];
        r.point_start[k] = c.point_start[k];
        r.point_end[k] = c.point_end[k];
    }
    // eq. (6): weights (1 - t1 - t2, t2, t1) on (a, b, c); a shape point: none
    r.t2 = c.shape == UINT32_MAX ? c.w[1] : 0.0;
    r.t1 = c.shape == UINT32_MAX ? c.w[2] : 0.0;
    // A node that stuck to this face at the last step stays at the same point of it (the
    // material point it stuck to: its weights), not at its new projection. The projection
    // follows the node where the predictor moved it; taken anew every step, the point a node
    // 'sticks' to crept by the predictor's relative tangential motion each step (h^2 times the
    // tangential acceleration friction holds back), and stacked soft cubes rang at 1e-3 m/s.
    if (c.shape == UINT32_MAX && last && same_triangle(last->triangle, r.triangle) && last->active() &&
        !last->sliding && last->offset <= 0.0)
        r.t1 = last->t1, r.t2 = last->t2;
    // A node that starts the step inside is let out gradually (target gap < 0): by 20 % of
    // the overlap per step, but never faster than 1e-3 of an edge per step while the overlap is
    // one of bodies as they were added (`gentle`: they separate slowly instead of jumping
    // apart), never faster than 1e-2 of an edge for one that came about during the run (a node
    // fallen in, one left deep by a face that turned under it: at 1e-3 of an edge a step, what a
    // turning face adds back each step can match it). A pair in contact at the last step (and
    // not letting out an overlap) has only the solve's residual to make up: at once.
    // A held node found deeper than the pair was left (it slid onto a neighbour of its face, or
    // the face bent round it), or found inside a deformable body (`slid` as well), makes up 1e-2
    // of an edge at once and is let out of the rest: made up at once, a depth of up to half an
    // edge would crush its tets.
    const bool held = last && last->offset <= 0.0;
    const double l = c.shape == UINT32_MAX ? contact_length(a, b) : a.edge_length;
    const bool gentle = (c.initial && c.start_gap < 0.0 && !held) || (last && last->gentle);
    if (c.start_gap < 0.0 && c.slid) {
        r.offset = std::max(0.0, -c.start_gap - kFallenRecovery * l);
    } else if (c.start_gap < 0.0 && !held) {
        const double overlap = -c.start_gap;
        r.offset = overlap - std::min(kOverlapRecovery * overlap, (gentle ? kMaxRecovery : kFallenRecovery) * l);
    }
    r.gentle = gentle && r.offset > 0.0;
    return r;
}

bool segment_crosses_body(const Vec3& from, const Vec3& to, uint32_t skip, const ContactBody& b,
                          const TriangleBvh& tree, double drift) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(from[k], to[k]), box.hi[k] = std::max(from[k], to[k]);
    const Vec3 d = to - from;
    bool crosses = false;
    tree.query(box, b.x_start, b.triangles, drift, [&](uint32_t t) {
        if (crosses || t == skip) return;
        const uint32_t* tri = &b.triangles[3 * t];
        const Vec3 v0 = position(b.x_start, tri[0]), e1 = position(b.x_start, tri[1]) - v0, e2 = position(b.x_start, tri[2]) - v0;
        double s, u, v;
        if (line_meets_triangle(from, d, v0, e1, e2, s, u, v)) crosses = s > 1e-9 && s < 1.0 - 1e-9;
    });
    return crosses;
}


}  // namespace lfem
