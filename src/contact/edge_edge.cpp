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

// The sum of the unit normals of the faces sharp edge e of b joins (one at a border): out of b.
Vec3 outward_of(const ContactBody& b, uint32_t e) {
    const uint32_t* edge = &b.sharp_edges[4 * std::size_t(e)];
    Vec3 out = unit_normal(b, edge[2]);
    if (edge[3] != UINT32_MAX) out += unit_normal(b, edge[3]);
    return out;
}

}  // namespace

bool edges_may_meet(const ContactBody& a, uint32_t ea, const double* line_a, const ContactBody& b, uint32_t eb,
                    const double* line_b, double reach, EdgeLines& lines) {
    const uint32_t* na = &a.sharp_edges[4 * std::size_t(ea)];
    const uint32_t* nb = &b.sharp_edges[4 * std::size_t(eb)];
    const Vec3 p0(line_a), q0(line_b), u(line_a + 3), v(line_b + 3);
    const Vec3 cross = u.cross(v);
    const double uu = u.squaredNorm(), vv = v.squaredNorm(), cross2 = cross.squaredNorm();
    if (!(cross2 > kCrossingSin2 * uu * vv)) return false;  // near parallel (or collapsed)
    // The closest points of the two lines (Ericson, 5.1.8).
    const Vec3 r = p0 - q0;
    const double uv = u.dot(v), ur = u.dot(r), vr = v.dot(r), denom = uu * vv - uv * uv;
    const double s_line = (uv * vr - ur * vv) / denom, t_line = (uu * vr - uv * ur) / denom;
    if (!(s_line > -kEdgeEnd && s_line < 1.0 + kEdgeEnd && t_line > -kEdgeEnd && t_line < 1.0 + kEdgeEnd)) return false;
    lines.inside = s_line > kEdgeEnd && s_line < 1.0 - kEdgeEnd && t_line > kEdgeEnd && t_line < 1.0 - kEdgeEnd;
    const double s = std::clamp(s_line, 0.0, 1.0), t = std::clamp(t_line, 0.0, 1.0);
    // The points' separation along the common normal (unnormalised) at x* and at x^n: on the
    // same side both times, and further apart than `reach` both times, they neither touch nor
    // crossed (most candidate pairs end here, before the faces' normals are made).
    const Vec3 a_start = (1.0 - s) * position(a.x_start, na[0]) + s * position(a.x_start, na[1]);
    const Vec3 b_start = (1.0 - t) * position(b.x_start, nb[0]) + t * position(b.x_start, nb[1]);
    const Vec3 apart = a_start - b_start;
    const double end = cross.dot(r), start = cross.dot(apart), far2 = reach * reach * cross2;
    if ((end > 0.0) == (start > 0.0) && end * end > far2 && start * start > far2) return false;
    lines.p0 = p0, lines.q0 = q0, lines.u = u, lines.v = v, lines.cross = cross, lines.start = apart;
    lines.s = s, lines.t = t;
    return true;
}

bool test_edge_edge(const ContactBody& a, uint32_t ea, const ContactBody& b, uint32_t eb, const EdgeLines& lines,
                    double band, double allowance, EdgeEdgeHit& hit) {
    const double s = lines.s, t = lines.t;
    Vec3 n = lines.cross.normalized();
    const Vec3 out_a = outward_of(a, ea), out_b = outward_of(b, eb);
    if (n.dot(out_b - out_a) < 0.0) n = -n;
    if (!(n.dot(out_b) > kOuterSide * out_b.norm() && -n.dot(out_a) > kOuterSide * out_a.norm())) return false;
    hit.gap = n.dot(lines.p0 + s * lines.u - lines.q0 - t * lines.v);
    if (!(hit.gap < band)) return false;
    hit.start_gap = n.dot(lines.start);
    if (!(hit.start_gap > -allowance)) return false;
    hit.s = s, hit.t = t, hit.normal = n;
    return true;
}

}  // namespace lfem
