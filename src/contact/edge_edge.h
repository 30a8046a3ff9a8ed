// Crossed edges: a boundary edge of one body against a boundary edge of another, where the
// nodes of neither see the other (two bars crossed edge on edge, a cube's edge across a face's
// inner edges). The constraint joins the closest points of the two segments, (1 - s) a0 + s a1
// and (1 - t) b0 + t b1, with those parameters as the weights on the four nodes, along their
// common normal turned out of b (the sides the edges' faces put outside). The edges are the
// bodies' sharp edges at rest (mesh/surface.h), against each other and against the folds of
// others' faces where the load bends those outward (a knife edge pressed into a face between
// its nodes); two folds meet with their nodes. A rigid box's edges meet a body's edges the same
// way.
#pragma once

#include <cstdint>

#include "common/math.h"
#include "contact/contact_body.h"

namespace lfem {

// Whether fold e of b (is_fold) bends outward at x* by more than a few degrees: only then can an
// edge lying across it between its nodes be inside b (a knife edge across a face the load
// bends), as the deepest point of a straight edge under a surface of flat faces lies at a
// convex fold or a sharp edge. The edge pass tests a fold against the sharp edges of others
// only while it holds.
bool fold_bends_out(const ContactBody& b, uint32_t e);
// The same in two parts, for a fold tested at many sub-steps: its corners u, v (the edge, in
// the turn of its first face), w0 and w1 (its faces' corners off the edge), then the test on
// the positions x.
void fold_corners(const ContactBody& b, uint32_t e, uint32_t corners[4]);
bool fold_bends(const double* x, const uint32_t corners[4]);

// The lines of edges ea of a and eb of b (contact_body.h edge_of) at x*, for
// edges_may_meet and test_edge_edge.
struct EdgeLines {
    Vec3 p0, q0;     // a's first node, b's
    Vec3 u, v;       // a's edge, b's (second node less first)
    Vec3 cross;      // u x v
    Vec3 start;      // a's point less b's at x^n (the same parameters s, t)
    double s = 0, t = 0;  // the parameters of the lines' closest points (at most an end)
    bool inside = false;  // both well inside their edges (a new pair's condition)
};

// Whether the edges may touch (the cheap part of the test, alone for most candidate pairs):
// they cross at an angle, their lines' closest points lie within both (a new pair's well
// inside, `inside`: node contacts take their ends; a held pair's up to just beyond an end), and
// these are within `reach` of each other along the lines' common normal at x* or at x^n, or
// changed sides in between.
// `line_a`, `line_b`: the edges' lines at x* (the first node, then the second less the first).
bool edges_may_meet(const ContactBody& a, uint32_t ea, const double* line_a, const ContactBody& b, uint32_t eb,
                    const double* line_b, double reach, EdgeLines& lines);

// Then the pair: the common normal turned out of b lies on the outer side of both edges' faces,
// and the closest points are within the capture band at the end of the step and were no
// deeper than `allowance` at its start (the gap along the common normal is the same for any
// two points of the lines at x*; at x^n it is measured at the same parameters).
struct EdgeEdgeHit {
    double s = 0, t = 0;            // the points' parameters on a's edge and on b's
    Vec3 normal = Vec3::Zero();     // unit, out of b
    double gap = 0, start_gap = 0;  // along the normal, at x* and at x^n (m)
};
bool test_edge_edge(const ContactBody& a, uint32_t ea, const ContactBody& b, uint32_t eb, const EdgeLines& lines,
                    double band, double allowance, EdgeEdgeHit& hit);

// A sharp edge of a against an edge of a rigid box (a shape of a static or kinematic body) the
// same way: the box's edge from b0 to b0 + v at the end of the step and from b0_start to
// b0_start + v_start at its start, `out_b` the sum of its two faces' unit normals. Both tests
// in one (a box has twelve edges: no candidate pairs are kept between searches).
// `held`: the pair was held at the last step (its points may lie just beyond an end).
bool test_edge_box_edge(const ContactBody& a, uint32_t ea, const double* line_a, const Vec3& b0, const Vec3& v,
                        const Vec3& b0_start, const Vec3& v_start, const Vec3& out_b, double reach, double band,
                        double allowance, bool held, EdgeEdgeHit& hit);

}  // namespace lfem
