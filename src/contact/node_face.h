// A slave node against one face of another body: a boundary triangle, by the path of the node
// from x^n to x* and its projection onto the face (eqs. 5 and 6), or a rigid shape, by signed
// distance. The narrow phase runs these on every candidate and keeps, per node and other body,
// the face penetrated least; make_record turns it into the constraint of eq. (6).
#pragma once

#include <cstdint>
#include <vector>

#include "common/math.h"
#include "contact/contact_body.h"
#include "contact/contact_record.h"
#include "contact/triangle_bvh.h"

namespace lfem {

inline Vec3 position(const double* x, uint32_t i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }

// Do triangles u and v (3 node indices each) share a node?
inline bool shares_node(const uint32_t* u, const uint32_t* v) {
    for (int i = 0; i < 3; ++i)
        if (u[i] == v[0] || u[i] == v[1] || u[i] == v[2]) return true;
    return false;
}

// The boundary triangle of b across edge (u, v) from triangle t, or UINT32_MAX at an open border.
uint32_t across_edge(const ContactBody& b, uint32_t t, uint32_t u, uint32_t v);

// Are u and v the same triangle (the same three nodes, in the same order)?
inline bool same_triangle(const uint32_t* u, const uint32_t* v) { return u[0] == v[0] && u[1] == v[1] && u[2] == v[2]; }

// The best face (or rigid shape) of another body found so far for one slave node.
struct NodeCandidate {
    bool found = false;
    uint32_t triangle = 0;
    uint32_t shape = UINT32_MAX;  // a rigid shape instead of a triangle
    Vec3 point_start = Vec3::Zero(), point_end = Vec3::Zero();
    double gap = 0;        // g* at the end of the step (m)
    double start_gap = 0;  // g^n
    double w[3] = {0, 0, 0};
    Vec3 normal = Vec3::Zero();
    bool fallen = false;   // found inside during the run, not among new bodies' overlaps
    bool slid = false;     // taken deeper than the pair was left: held last step (neighbour_allowance),
                           // or found inside a deformable body
    bool initial = false;  // found when new bodies are checked for overlaps
    double lowest = 0;     // the lowest barycentric weight of its point before clamping
};

// The profile's counts of rigid-shape queries.
struct ShapeQueryCounts {
    uint64_t shape_tests = 0, ccd_queries = 0;
};

// A face of a moving body over one sub-step, made once for every node that may meet it: its
// box over the step (not grown) and its unit normals at x* and at x^n, as the node test would
// compute them itself, and how far its vertices move in the sub-step (what the narrow phase's
// skipping of faces needs, detect_node_triangle.cpp). A face collapsed at either end (zero
// area) is not `valid`: no node meets it.
struct FaceStep {
    Aabb box;
    Vec3 normal_end = Vec3::Zero(), normal_start = Vec3::Zero();
    double motion = 0;  // the largest |x* - x^n| of its vertices (m)
    bool valid = false;
};

// The smallest height of triangle abc: twice its area over its longest edge.
double smallest_height(const Vec3& a, const Vec3& b, const Vec3& c);
FaceStep face_step(const ContactBody& b, uint32_t t);

// Node p of `a` (its outward normal at x*: node_normal) against triangle t of `b`: kept in
// slots.best if it is a valid contact penetrated less than what best holds (NodeSlots says
// where else it may go). A node that starts the step deeper than depth_allowance behind the
// face is only a possible initial overlap, kept in slots.deep when given, or else a possible
// node inside a deformable body, kept in slots.inside when given, for the caller to check
// (keep_records in detect_node_triangle.cpp). `held`: the triangle of b (3 node indices) that
// held the node last step, nullable: neighbours the surface bends from it towards the node
// allow more depth (node_face.cpp). `face` is face_step(b, t), required when b moves;
// null for a static body (its face normals made once) and for a sleeping one (static while
// asleep: its normals are made here).
//
// Returns, when the node was turned away because its point on the face lies outside the
// triangle (a barycentric weight below -kEdgeTolerance), by how much: the margin sigma of the
// lowest weight below -kEdgeTolerance (at most 0.25), in `margin`, and the smallest height of
// the triangle that was tested, in `height`; both 0 when it was turned away for any other reason
// or kept. How far node and face must then move before the node could meet the face:
// still_outside in detect_node_triangle.cpp. (Against a deformable body the margin is measured
// from the wider band, kInsideBand, in which a node inside it is taken.)
struct Outside {
    double margin = 0, height = 0;
};
// The outward unit normal of node p of `a` at x*: the normalised sum of the area-weighted normals
// of the triangles around it (zero for an interior node).
Vec3 node_normal(const ContactBody& a, uint32_t p);

// Node p's normal, made when first asked for (the facing rule needs it only for a node at a
// face's edge) and kept in *value, with *ready set.
struct NodeNormal {
    const ContactBody& a;
    uint32_t p;
    Vec3* value;
    uint8_t* ready;
    const Vec3& get() const {
        if (!*ready) *value = node_normal(a, p), *ready = 1;
        return *value;
    }
};

// Where test_node_triangle keeps what it finds for one node and other body: the face
// penetrated least (best); a node that starts deeper than the pair was left, as a possible
// initial overlap (deep, when given) or, against a deformable body, as possibly inside it
// (inside, when given); the faces no better than best turned from it by more than the valley
// angle, with every best it replaced (accepted, when given: keep_records' second faces).
struct NodeSlots {
    NodeCandidate& best;
    NodeCandidate* deep = nullptr;
    NodeCandidate* inside = nullptr;
    std::vector<NodeCandidate>* accepted = nullptr;
};
Outside test_node_triangle(const ContactBody& a, uint32_t p, const NodeNormal& node_normal, const ContactBody& b,
                           uint32_t t, const FaceStep* face, double depth_allowance, const uint32_t* held,
                           const NodeSlots& slots);

// Does point x (node p of `a` at the start of the step) lie inside body b, in one of the tets
// around the corners of triangle tri (node indices of b)? Never in a tet of p's own.
bool inside_near(const ContactBody& a, uint32_t p, const ContactBody& b, const uint32_t* tri, const Vec3& x);

// Node p of `a` against rigid shape j of `b`, by the same rules: within the capture band at the
// end of the step, no deeper at its start than the pair was left, facing the node's surface.
void test_node_shape(const ContactBody& a, uint32_t p, const Vec3& node_normal, const ContactBody& b,
                     uint32_t j, double depth_allowance, NodeCandidate& best, ShapeQueryCounts& counts);

// The constraint of node p of `a` against the candidate face or shape of `b`, warm-started
// from the pair's last record (nullable).
ContactRecord make_record(const ContactBody& a, uint32_t p, const ContactBody& b, const NodeCandidate& c,
                          const ContactRecord* last);

// Does the open segment from `from` to `to` cross a boundary triangle of body b other than
// `skip`, at the start of the step? Möller-Trumbore against the triangles the tree (built on
// positions up to `drift` per axis away from x_start) finds near the segment.
bool segment_crosses_body(const Vec3& from, const Vec3& to, uint32_t skip, const ContactBody& b,
                          const TriangleBvh& tree, double drift);

}  // namespace lfem
