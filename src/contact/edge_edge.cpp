#include "contact/edge_edge.h"

#include <algorithm>
#include <cmath>

#include "contact/node_face.h"

namespace lfem {
namespace {

// A new pair's closest points lie inside both edges: within 2 % of an end the node's own
// constraints (node against face) hold it. A held pair's may lie up to 2 % beyond an end (its
// points stop at the end node), so that a crossing running along an edge is held until the
// next edge's pair, 2 % inside that edge, takes it over.
constexpr double kEdgeEnd = 0.02;
// Edges within 10 degrees of parallel have no well-defined common normal: the nodes of the
// one lying along the other meet its faces instead.
constexpr double kCrossingSin2 = 0.0302;  // sin^2(10 degrees)
// The common normal must lie this far (a cosine) on the outer side of each edge's faces.
constexpr double kOuterSide = 0.1;

// A static body's normals were made once (the same bits), a moving one's at x*.
Vec3 unit_normal(const ContactBody& b, uint32_t t) {
    return b.face_normals ? position(b.face_normals, t) : unit_triangle_normal(b.x, &b.triangles[3 * std::size_t(t)]);
}

// The sum of the unit normals of the faces edge e of b joins (one at a border): out of b.
Vec3 outward_of(const ContactBody& b, uint32_t e) {
    const uint32_t* edge = edge_of(b, e);
    Vec3 out = unit_normal(b, edge[2]);
    if (edge[3] != UINT32_MAX) out += unit_normal(b, edge[3]);
    return out;
}

// The closest points of the lines p0 + s u and q0 + t v (Ericson, 5.1.8) into lines (p0, q0,
// u, v, cross, s, t, inside): false when the lines are near parallel or the points lie beyond
// the edges (a new pair's well inside, a held pair's up to just beyond an end).
bool closest_of_lines(const Vec3& p0, const Vec3& u, const Vec3& q0, const Vec3& v, EdgeLines& lines) {
    const Vec3 cross = u.cross(v);
    const double uu = u.squaredNorm(), vv = v.squaredNorm(), cross2 = cross.squaredNorm();
    if (!(cross2 > kCrossingSin2 * uu * vv)) return false;  // near parallel (or collapsed)
    const Vec3 r = p0 - q0;
    const double uv = u.dot(v), ur = u.dot(r), vr = v.dot(r), denom = uu * vv - uv * uv;
    const double s_line = (uv * vr - ur * vv) / denom, t_line = (uu * vr - uv * ur) / denom;
    if (!(s_line > -kEdgeEnd && s_line < 1.0 + kEdgeEnd && t_line > -kEdgeEnd && t_line < 1.0 + kEdgeEnd)) return false;
    lines.inside = s_line > kEdgeEnd && s_line < 1.0 - kEdgeEnd && t_line > kEdgeEnd && t_line < 1.0 - kEdgeEnd;
    lines.s = std::clamp(s_line, 0.0, 1.0), lines.t = std::clamp(t_line, 0.0, 1.0);
    lines.p0 = p0, lines.q0 = q0, lines.u = u, lines.v = v, lines.cross = cross;
    return true;
}

// Whether the points, a_start less b_start at x^n (lines.start), are on the same side along
// the common normal at x* and at x^n and further apart than `reach` both times: then they
// neither touch nor crossed (most candidate pairs end here, before the faces' normals are made).
bool apart(const EdgeLines& lines, double reach) {
    const double end = lines.cross.dot(lines.p0 - lines.q0);  // the same for any points of the lines
    const double start = lines.cross.dot(lines.start), far2 = reach * reach * lines.cross.squaredNorm();
    return (end > 0.0) == (start > 0.0) && end * end > far2 && start * start > far2;
}

// The common normal turned out of b, on the outer side of both edges' faces (out_a, out_b: the
// sums of their unit normals), and the gaps along it at x* and at x^n.
bool oriented_gap(const EdgeLines& lines, const Vec3& out_a, const Vec3& out_b, double band, double allowance,
                  EdgeEdgeHit& hit) {
    Vec3 n = lines.cross.normalized();
    if (n.dot(out_b - out_a) < 0.0) n = -n;
    if (!(n.dot(out_b) > kOuterSide * out_b.norm() && -n.dot(out_a) > kOuterSide * out_a.norm())) return false;
    hit.gap = n.dot(lines.p0 + lines.s * lines.u - lines.q0 - lines.t * lines.v);
    if (!(hit.gap < band)) return false;
    hit.start_gap = n.dot(lines.start);
    if (!(hit.start_gap > -allowance)) return false;
    hit.s = lines.s, hit.t = lines.t, hit.normal = n;
    return true;
}

// The point of a's edge e at parameter s at x^n.
Vec3 start_point(const ContactBody& a, uint32_t e, double s) {
    const uint32_t* n = edge_of(a, e);
    return (1.0 - s) * position(a.x_start, n[0]) + s * position(a.x_start, n[1]);
}

// A fold holds a crossing once its faces turn outward by more than 2 degrees: a straight edge
// lying across a fold bent by alpha, on both faces half an element l from it, is at most
// l tan(alpha / 2) / 2 ~ l alpha / 4 inside at the fold: 0.9 % of l at 2 degrees, under the
// 1 % that contact allows. Flatter folds (most of a resting face) are left to the nodes. At
// 1 degree (0.44 %) the folds under resting cubes' edges gave so many more pairs that the
// piles' solve took 32 sweeps a sub-step instead of 24 landing, 36 instead of 14 at rest.
constexpr double kFoldBendSin2 = 0.0012179748700878;  // sin^2(2 degrees)

}  // namespace

void fold_corners(const ContactBody& b, uint32_t e, uint32_t corners[4]) {
    const uint32_t* edge = edge_of(b, e);
    const uint32_t* f0 = &b.triangles[3 * std::size_t(edge[2])];
    const uint32_t* f1 = &b.triangles[3 * std::size_t(edge[3])];
    const auto off_edge = [&](const uint32_t* f) {
        return f[0] != edge[0] && f[0] != edge[1] ? 0 : f[1] != edge[0] && f[1] != edge[1] ? 1 : 2;
    };
    const int k = off_edge(f0);  // f0 turns from f0[k + 1] to f0[k + 2] along the edge
    corners[0] = f0[(k + 1) % 3], corners[1] = f0[(k + 2) % 3], corners[2] = f0[k], corners[3] = f1[off_edge(f1)];
}

bool fold_bends(const double* x, const uint32_t corners[4]) {
    // The corner w1 of the second face lies a height h = -n0.(w1 - u) inside the first face's
    // plane (n0 its unit normal) and d from the edge's line: the fold turns outward by theta
    // with h = d sin(theta). Without a square root or the second face's normal (every watched
    // fold is tested each sub-step): N0 = (v - u) x (w0 - u) = n0 |N0|, h > 0 and
    // (N0.(w1 - u))^2 > sin^2(2 degrees) |N0|^2 d^2.
    const Vec3 u = position(x, corners[0]), along = position(x, corners[1]) - u;
    const Vec3 n0 = along.cross(position(x, corners[2]) - u), r = position(x, corners[3]) - u;
    const double h = -n0.dot(r), along2 = along.squaredNorm();
    if (!(h > 0.0) || !(along2 > 0.0)) return false;
    const double ra = r.dot(along), d2 = r.squaredNorm() - ra * ra / along2;
    return h * h > kFoldBendSin2 * n0.squaredNorm() * d2;
}

bool fold_bends_out(const ContactBody& b, uint32_t e) {
    uint32_t corners[4];
    fold_corners(b, e, corners);
    return fold_bends(b.x, corners);
}

bool edges_may_meet(const ContactBody& a, uint32_t ea, const double* line_a, const ContactBody& b, uint32_t eb,
                    const double* line_b, double reach, EdgeLines& lines) {
    if (!closest_of_lines(Vec3(line_a), Vec3(line_a + 3), Vec3(line_b), Vec3(line_b + 3), lines)) return false;
    lines.start = start_point(a, ea, lines.s) - start_point(b, eb, lines.t);
    return !apart(lines, reach);
}

bool test_edge_edge(const ContactBody& a, uint32_t ea, const ContactBody& b, uint32_t eb, const EdgeLines& lines,
                    double band, double allowance, EdgeEdgeHit& hit) {
    return oriented_gap(lines, outward_of(a, ea), outward_of(b, eb), band, allowance, hit);
}

bool test_edge_box_edge(const ContactBody& a, uint32_t ea, const double* line_a, const Vec3& b0, const Vec3& v,
                        const Vec3& b0_start, const Vec3& v_start, const Vec3& out_b, double reach, double band,
                        double allowance, bool held, EdgeEdgeHit& hit) {
    EdgeLines lines;
    if (!closest_of_lines(Vec3(line_a), Vec3(line_a + 3), b0, v, lines) || !(held || lines.inside)) return false;
    lines.start = start_point(a, ea, lines.s) - (b0_start + lines.t * v_start);
    return !apart(lines, reach) && oriented_gap(lines, outward_of(a, ea), out_b, band, allowance, hit);
}

}  // namespace lfem
