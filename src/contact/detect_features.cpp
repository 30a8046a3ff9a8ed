#include "contact/detect_features.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>

#include "contact/detection_tolerances.h"
#include "contact/edge_edge.h"
#include "contact/face_shape.h"
#include "contact/node_face.h"
#include "contact/warm_start.h"

namespace lfem {
namespace {

// A face needs its own constraint against a shape only where the shape's point under it lies
// deeper than the face's nodes see the shape (their weighted distances) by more than 0.5 % of
// the face's edge length: a rod or a stud between the nodes; not a box's face lying under the
// face (the nodes hold it, as on a floor), nor a shape touching the face at its nodes. With no
// threshold (or a tiny one), a soft block balanced on a sphere's crown or on a rod, both at its
// nodes, rocked at 1e-3 to 1e-2 m/s under damping that stops it within 0.1 s: one contact held
// at the crown node and others around it in the faces made the block pivot from one to the
// next. The shape may then lie up to 0.5 % of an edge inside the face between the nodes, half
// the 1 % the face constraints are there to keep. A face that had a constraint against the
// shape nearby at the last step keeps one while the shape lies deeper than the nodes see it at
// all, so that the constraint does not come and go at the threshold.
constexpr double kFaceSag = 5e-3;
// A shape's point within a tenth of an edge of a node (a barycentric weight above 0.9) is that
// node's to hold: a soft bar folding over a thin rod right under a column of its nodes had face
// constraints 2 mm beside the column, pushing the faces out along the rod's normals, which
// slid the column off the rod's crown and let the bar fall through it (the nodes alone hold
// it). The shape may then lie between the node and the face's point, at most (0.1 l)^2 / 2r
// deep for a rod of radius r: 1 % of the edge for r = l / 2.
constexpr double kNodeDomain = 0.9;

// Whether a face constraint is needed (the rule above): `held`, a constraint of the same shape
// and body lay within an edge of the point at the last step.
bool nodes_miss(const FaceShapeHit& hit, bool held, double l) {
    const double nearest_node = std::max({hit.weights[0], hit.weights[1], hit.weights[2]});
    if (nearest_node > kNodeDomain) return false;
    return held ? hit.unseen > 0.0 : hit.unseen > kFaceSag * l;
}

// Whether one of the shape's last records (s.previous_places) lies within `reach` of point p.
bool held_near(const FeatureScratch& s, const Vec3& p, double reach) {
    bool found = false;
    s.previous_places.near(p.data(), reach, [&](uint32_t, double) { found = true; });
    return found;
}

auto key_of(const ContactRecord& r) {
    return std::make_tuple(r.body_a, r.body_b, uint8_t(r.kind), r.shape, r.nodes_a[0], r.nodes_a[1], r.nodes_a[2],
                           r.triangle[0], r.triangle[1], r.end);
}

// The last list's record of the same feature, or nullptr.
const ContactRecord* last_of(const FeatureScratch& s, const ContactRecord& r) {
    const auto it = std::lower_bound(s.previous.begin(), s.previous.end(), &r,
                                     [](const ContactRecord* x, const ContactRecord* y) { return feature_less(*x, *y); });
    return it != s.previous.end() && key_of(**it) == key_of(r) ? *it : nullptr;
}

// The overlap a record lets out gradually (its target gap is -offset), as for a node
// (make_record, node_face.cpp): none for a pair held at the last step (`last`, not letting out
// an overlap itself), which has only the solve's residual to make up, at once; else 20 % of the
// overlap it started the step with, at most 1e-2 of an edge l.
double overlap_kept(double start_gap, const ContactRecord* last, double l) {
    if (start_gap >= 0.0 || (last && last->offset <= 0.0)) return 0.0;
    const double overlap = -start_gap;
    return overlap - std::min(kOverlapRecovery * overlap, kFallenRecovery * l);
}

// Where the last list's records of shape k of body o against faces of body a lie in s.previous.
std::pair<std::size_t, std::size_t> previous_of_shape(const FeatureScratch& s, uint32_t a, uint32_t o, uint32_t k) {
    ContactRecord lo;
    lo.body_a = a, lo.body_b = o, lo.kind = ContactKind::face_shape, lo.shape = k;
    lo.nodes_a[0] = lo.nodes_a[1] = lo.nodes_a[2] = 0;
    lo.triangle[0] = lo.triangle[1] = lo.triangle[2] = UINT32_MAX;
    lo.end = 0;
    const auto less = [](const ContactRecord* x, const ContactRecord* y) { return feature_less(*x, *y); };
    const std::size_t from = std::size_t(std::lower_bound(s.previous.begin(), s.previous.end(), &lo, less) - s.previous.begin());
    std::size_t to = from;
    while (to < s.previous.size() && s.previous[to]->body_a == a && s.previous[to]->body_b == o &&
           s.previous[to]->kind == ContactKind::face_shape && s.previous[to]->shape == k)
        ++to;
    return {from, to};
}

// A shape's face records warm-start from the last ones of the same face; those met on another
// face than last step's, by place: as a body rocks on a shape, the deepest point under its faces
// moves from one triangle to the next. Each new record (s.found[first ..], its start gap in
// s.start_gaps) found on a face that had none takes the multipliers of the nearest last record
// within `reach` (the face's edge length) that no face kept, shared equally among the new
// records that take the same one (the load they carry stays the load it carried), and is held
// as that one was.
void warm_start_by_place(FeatureScratch& s, std::size_t from, std::size_t to, std::size_t first, double reach) {
    const std::size_t count = s.found.size() - first;
    s.match.assign(count, UINT32_MAX);
    s.shares.assign(to - from, 0);
    // The same face: the last records are in key order, as the new ones are (faces ascending).
    for (std::size_t i = 0, j = from; i < count && j < to;) {
        if (feature_less(s.found[first + i], *s.previous[j])) ++i;
        else if (feature_less(*s.previous[j], s.found[first + i])) ++j;
        else s.match[i] = uint32_t(j - from), s.shares[j - from] = UINT32_MAX, ++i, ++j;
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (s.match[i] != UINT32_MAX) continue;
        double best = HUGE_VAL;
        uint32_t nearest = UINT32_MAX;
        s.previous_places.near(s.found[first + i].point_end, reach, [&](uint32_t j, double d2) {
            if (s.shares[j] == UINT32_MAX) return;  // kept by its own face
            if (d2 < best || (d2 == best && j < nearest)) best = d2, nearest = j;
        });
        if (nearest != UINT32_MAX) s.match[i] = nearest, s.shares[nearest] += 1;
    }
    for (std::size_t i = 0; i < count; ++i) {
        const uint32_t m = s.match[i];
        ContactRecord& r = s.found[first + i];
        const ContactRecord* last = m == UINT32_MAX ? nullptr : s.previous[from + m];
        r.offset = overlap_kept(s.start_gaps[first + i], last, reach);
        if (!last) continue;
        const double share = s.shares[m] == UINT32_MAX ? 1.0 : 1.0 / s.shares[m];
        r.lambda_n = share * last->lambda_n;
        for (int d = 0; d < 3; ++d) r.lambda_t[d] = share * last->lambda_t[d];
    }
}

// Every face of a moving body under every shape of static and kinematic bodies.
void shapes_against_faces(const std::vector<ContactBody>& bodies, const ContactCandidates& c, FeatureScratch& s) {
    for (uint32_t oi : c.shape_bodies) {
        const ContactBody& o = bodies[oi];
        for (uint32_t k = 0; k < o.shape_count; ++k) {
            if (o.shapes[k].type == ShapeType::plane) continue;  // no point between a face's nodes
            const RigidShape& shape = o.shapes[k];
            const ShapePose end = ShapePose::load(o.shape_pose + 7 * std::size_t(k));
            const ShapePose start = ShapePose::load(o.shape_pose_start + 7 * std::size_t(k));
            // Where to look: the shape's own box over the step, or for a box, the boxes of its
            // twelve edges: a face lying on a box's face is held by its nodes (a body on a box
            // floor), so only faces near the box's edges can need more, and a large floor's
            // faces are not searched under every body on it every sub-step.
            s.regions.clear();
            if (shape.type == ShapeType::box) {
                box_edge_boxes(shape, end, s.regions);
                const std::size_t half = s.regions.size();
                box_edge_boxes(shape, start, s.regions);
                for (std::size_t i = 0; i < half; ++i) join(s.regions[i], s.regions[half + i]);
                s.regions.resize(half);
            } else {
                Aabb whole = shape_box(shape, end);
                join(whole, shape_box(shape, start));
                s.regions.push_back(whole);
            }
            Aabb box = empty_box();
            for (const Aabb& r : s.regions) join(box, r);
            s.near.clear();
            c.body_grid.query(box, s.near);
            for (uint32_t ai : s.near) {
                const ContactBody& a = bodies[ai];
                if (ai == oi || !a.moves || !is_movable(a) || a.triangle_count == 0 || !bodies_may_touch(a, o)) continue;
                const double band = kCaptureBand * a.edge_length;
                s.triangles.clear();
                for (const Aabb& region : s.regions)
                    c.tree_of(bodies, ai).query(grown(region, band + 2.0 * c.budget[ai]), a.x, a.triangles, c.budget[ai],
                                                [&](uint32_t t) { s.triangles.push_back(t); });
                std::sort(s.triangles.begin(), s.triangles.end());
                s.triangles.erase(std::unique(s.triangles.begin(), s.triangles.end()), s.triangles.end());
                const std::size_t first = s.found.size();
                const auto [from, to] = previous_of_shape(s, a.slot, o.slot, k);
                // Allowed as deep as the shape's deepest kept offset under this body.
                double kept = 0.0;
                s.previous_places.clear();
                for (std::size_t j = from; j < to; ++j) {
                    kept = std::max(kept, s.previous[j]->kept_offset());
                    s.previous_places.add(s.previous[j]->point_end, uint32_t(j - from));
                }
                s.previous_places.sort();
                for (uint32_t t : s.triangles)
                    for (int end = 0; end < 2; ++end) {
                        ContactRecord r;
                        r.body_a = a.slot, r.node = kFeatureNode, r.body_b = o.slot, r.shape = k;
                        r.kind = ContactKind::face_shape;
                        r.end = uint8_t(end);
                        r.triangle[0] = r.triangle[1] = r.triangle[2] = UINT32_MAX;  // a shape's, as a node's
                        for (int v = 0; v < 3; ++v) r.nodes_a[v] = a.triangles[3 * std::size_t(t) + v];
                        // A pair stuck at the last step (active, not sliding, no overlap kept) keeps
                        // the face's material point it stuck at, as a node stuck to a face does
                        // (make_record, node_face.cpp): taken anew every step, the stuck point
                        // crept by the predictor's tangential motion, and a block crept off a
                        // sphere's crown at 4e-4 m/s under damping that should have stopped it.
                        const ContactRecord* last = last_of(s, r);
                        const bool stuck = last && last->active() && !last->sliding && last->offset <= 0.0;
                        FaceShapeHit hit;
                        const bool found = test_face_shape(a, t, o, k, band, end, stuck ? last->weights_a : nullptr, hit);
                        if (end + 1 >= hit.ends) end = 2;  // no second point: this face is done
                        if (!found) continue;
                        // Not deeper at the start than the pair was left (a thin part's far face is
                        // no way out), but a face held against the shape nearby at the last step may
                        // start as deep as the turn of the face takes its point in a step (1e-2 of
                        // an edge, as a node held at a face that bends round it, node_face.cpp).
                        const bool held = held_near(s, hit.point_end, a.edge_length);
                        const double allowance =
                            allowed_depth(kept, a.edge_length) + (held ? kFallenRecovery * a.edge_length : 0.0);
                        if (!(hit.start_gap > -allowance) || !nodes_miss(hit, held, a.edge_length)) continue;
                        for (int d = 0; d < 3; ++d) {
                            r.weights_a[d] = hit.weights[d], r.normal[d] = hit.normal[d];
                            r.point_end[d] = hit.point_end[d], r.point_start[d] = hit.point_start[d];
                        }
                        s.found.push_back(r);
                        s.start_gaps.push_back(hit.start_gap);
                    }
                warm_start_by_place(s, from, to, first, a.edge_length);
            }
        }
    }
}

// Candidate edge pairs per block of the parallel edge pass (fixed: the same blocks, and so the
// same records in the same order, for any thread count).
constexpr uint32_t kEdgeBlock = 1024;

// An edge record of edge e of body a against body_b (its side set by the caller).
ContactRecord edge_record(const ContactBody& a, uint32_t e, uint32_t body_b) {
    const uint32_t* n = edge_of(a, e);
    ContactRecord r;
    r.body_a = a.slot, r.node = kFeatureNode, r.body_b = body_b, r.kind = ContactKind::edge_edge;
    r.nodes_a[0] = n[0], r.nodes_a[1] = r.nodes_a[2] = n[1];
    return r;
}

// How far apart an edge pair's points may be and still be tested (edges_may_meet's reach): as
// deep as any pair may start, the deepest kept offset the search allowed for. How deep one may
// start the step: as deep as the faces' turn takes the edges' points in a step (as a face held
// against a shape, above), a held one as deep as it was left besides.
double edge_reach(const ContactCandidates& c, double l) {
    return triangle_growth(l, c.offset_allowed, false) + kFallenRecovery * l;
}
double edge_allowance(const ContactRecord* last, double l) {
    return allowed_depth(last ? last->kept_offset() : 0.0, l) + kFallenRecovery * l;
}

// The last list's record of a pair of edges next to r's (the same edge of one body, the other
// body's edge sharing one node with r's), or nullptr: a crossing that ran past the end of that
// pair's edge onto this one (a soft edge squeezed along its length carries the crossing over
// its node), taken over as held, with its force. Without it the new pair, already crossed,
// was refused, and two plates swung together at 15 m/s locked 5 mm past each other.
const ContactRecord* handed_over(const FeatureScratch& s, const ContactRecord& r) {
    ContactRecord probe;  // the first record of r's pair of bodies and kind
    probe.body_a = r.body_a, probe.body_b = r.body_b, probe.kind = r.kind, probe.shape = r.shape;
    probe.nodes_a[0] = probe.nodes_a[1] = probe.nodes_a[2] = 0, probe.triangle[0] = probe.triangle[1] = 0, probe.end = 0;
    const auto shares_one = [](uint32_t a0, uint32_t a1, uint32_t b0, uint32_t b1) {
        return (a0 == b0) + (a0 == b1) + (a1 == b0) + (a1 == b1) == 1;
    };
    auto it = std::lower_bound(s.previous.begin(), s.previous.end(), &probe,
                               [](const ContactRecord* x, const ContactRecord* y) { return feature_less(*x, *y); });
    for (; it != s.previous.end(); ++it) {
        const ContactRecord& q = **it;
        if (q.body_a != r.body_a || q.body_b != r.body_b || q.kind != r.kind || q.shape != r.shape) break;
        const bool same_a = q.nodes_a[0] == r.nodes_a[0] && q.nodes_a[1] == r.nodes_a[1];
        const bool same_b = q.triangle[0] == r.triangle[0] && q.triangle[1] == r.triangle[1];
        if ((same_a && shares_one(q.triangle[0], q.triangle[1], r.triangle[0], r.triangle[1])) ||
            (same_b && shares_one(q.nodes_a[0], q.nodes_a[1], r.nodes_a[0], r.nodes_a[1])))
            return &q;
    }
    return nullptr;
}

// A hit becomes record r: a new pair only where the edges cross by the end of the step, then
// kept while within the band (warm-started). False: no record.
bool take_edge_hit(const EdgeEdgeHit& hit, const ContactRecord* last, double l, ContactRecord& r) {
    if (!last && !(hit.gap < 0.0)) return false;
    r.weights_a[0] = 1.0 - hit.s, r.weights_a[1] = hit.s;
    for (int d = 0; d < 3; ++d) r.normal[d] = hit.normal[d];
    if (last) warm_start(*last, r);
    r.offset = overlap_kept(hit.start_gap, last, l);
    return true;
}

// Edge ea of a (its line at x* `line_a`: first node, second less first) against edge eb of b:
// a record appended to `found` where they cross, or crossed and are still within the band.
void edge_pair(const ContactBody& a, uint32_t ea, const double* line_a, const ContactBody& b, uint32_t eb,
               const double* line_b, const ContactCandidates& c, const FeatureScratch& s,
               std::vector<ContactRecord>& found) {
    const double l = contact_length(a, b), band = kCaptureBand * l;
    EdgeLines lines;
    if (!edges_may_meet(a, ea, line_a, b, eb, line_b, edge_reach(c, l), lines)) return;
    const uint32_t* nb = edge_of(b, eb);
    ContactRecord r = edge_record(a, ea, b.slot);
    r.triangle[0] = nb[0], r.triangle[1] = r.triangle[2] = nb[1];
    const ContactRecord* last = last_of(s, r);
    if (!last) last = handed_over(s, r);
    if (!last && !lines.inside) return;
    EdgeEdgeHit hit;
    if (!test_edge_edge(a, ea, b, eb, lines, band, edge_allowance(last, l), hit) || !take_edge_hit(hit, last, l, r))
        return;
    r.t2 = hit.t;
    found.push_back(r);
}

// The candidate pairs [first, end) of sharp edges.
void edge_block(const std::vector<ContactBody>& bodies, const ContactCandidates& c, const FeatureScratch& s,
                uint32_t first, uint32_t end, std::vector<ContactRecord>& found) {
    for (uint32_t k = first; k < end; ++k) {
        const EdgePair& p = s.edges.pairs[k];
        const ContactBody& a = bodies[p.a];
        const ContactBody& b = bodies[p.b];
        if (!a.moves && !b.moves) continue;  // asleep, or static
        edge_pair(a, p.edge_a, &s.edges.lines[6 * std::size_t(p.line_a)], b, p.edge_b,
                  &s.edges.lines[6 * std::size_t(p.line_b)], c, s, found);
    }
}

// Edge e of b: its line at x* (first node, second less first) and its box from x^n to x*.
Aabb swept_edge(const ContactBody& b, uint32_t e, double* line) {
    const uint32_t* n = edge_of(b, e);
    Aabb box = empty_box();
    for (const double* x : {static_cast<const double*>(b.x), b.x_start})
        for (int v = 0; v < 2; ++v)
            for (int d = 0; d < 3; ++d) {
                const double y = x[3 * std::size_t(n[v]) + d];
                box.lo[d] = std::min(box.lo[d], y), box.hi[d] = std::max(box.hi[d], y);
            }
    for (int d = 0; d < 3; ++d) line[d] = b.x[3 * std::size_t(n[0]) + d], line[3 + d] = b.x[3 * std::size_t(n[1]) + d] - line[d];
    return box;
}

// The watched folds [first, end) bent outward against their groups' sharp edges whose boxes
// from x^n to x*, grown by the reach, meet theirs (edges_may_meet accepts nothing beyond).
void fold_block(const std::vector<ContactBody>& bodies, const ContactCandidates& c, const FeatureScratch& s,
                uint32_t first, uint32_t end, std::vector<ContactRecord>& found) {
    bool bends = false;  // of the fold of the last entry (a fold's groups are side by side)
    for (uint32_t k = first; k < end; ++k) {
        const EdgeCandidates::WatchedFold& w = s.edges.watched[k];
        const EdgeCandidates::FoldGroup& g = s.edges.fold_groups[w.group];
        const ContactBody& a = bodies[g.sharp_body];
        const ContactBody& b = bodies[g.fold_body];
        const EdgeCandidates::WatchedFold* last = k > first ? &s.edges.watched[k - 1] : nullptr;
        if (!last || last->fold != w.fold || s.edges.fold_groups[last->group].fold_body != g.fold_body)
            bends = fold_bends(b.x, w.corners);
        if (!bends || (!a.moves && !b.moves)) continue;
        double line_b[6], line_a[6];
        const Aabb fold_box = grown(swept_edge(b, w.fold, line_b), edge_reach(c, contact_length(a, b)));
        for (uint32_t q = g.sharp_begin; q < g.sharp_end; ++q) {
            const uint32_t ea = s.edges.group_sharp[q];
            if (&a == &b && !own_edges_may_cross(a, ea, w.fold)) continue;
            if (!overlaps(swept_edge(a, ea, line_a), fold_box)) continue;
            edge_pair(a, ea, line_a, b, w.fold, line_b, c, s, found);
        }
    }
}

// Every candidate pair of sharp edges and every watched fold, in blocks on the pool; the
// blocks' records join s.found in block order.
void edges_against_edges(const std::vector<ContactBody>& bodies, const ContactCandidates& c, FeatureScratch& s,
                         ThreadPool* pool) {
    update_edge_pairs(bodies, c, s.edges, pool);
    update_edge_lines(bodies, s.edges);
    const uint32_t pairs = uint32_t(s.edges.pairs.size()), folds = uint32_t(s.edges.watched.size());
    const uint32_t pair_blocks = (pairs + kEdgeBlock - 1) / kEdgeBlock, blocks = pair_blocks + (folds + kEdgeBlock - 1) / kEdgeBlock;
    if (s.edge_found.size() < blocks) s.edge_found.resize(blocks);
    parallel_for(pool, blocks, [&](uint32_t b) {
        s.edge_found[b].clear();
        if (b < pair_blocks)
            edge_block(bodies, c, s, b * kEdgeBlock, std::min(pairs, (b + 1) * kEdgeBlock), s.edge_found[b]);
        else
            fold_block(bodies, c, s, (b - pair_blocks) * kEdgeBlock, std::min(folds, (b - pair_blocks + 1) * kEdgeBlock),
                       s.edge_found[b]);
    });
    for (uint32_t b = 0; b < blocks; ++b) s.found.insert(s.found.end(), s.edge_found[b].begin(), s.edge_found[b].end());
}

// Edge i of a box or a convex hull at a pose, from `from` to `from + along`; `out` the sum of
// its two faces' unit normals. A box's: along axis i / 4 from its first corner, the other two
// axes' sides from bits 0 and 1 of i; a hull's: its edge i (hull_edges.h).
struct ShapeEdge {
    Vec3 from, along, out;
};
ShapeEdge shape_edge(const RigidShape& shape, const ShapePose& pose, uint32_t i) {
    Vec3 corner, along = Vec3::Zero(), out = Vec3::Zero();
    if (shape.type == ShapeType::convex_hull) {
        corner = Vec3(&shape.points[3 * std::size_t(shape.hull_edges[2 * i])]);
        along = Vec3(&shape.points[3 * std::size_t(shape.hull_edges[2 * i + 1])]) - corner;
        out = Vec3(&shape.hull_edge_out[3 * std::size_t(i)]);
    } else {
        const uint32_t axis = i / 4, a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        const double* h = shape.half_extents;
        const double s1 = i & 1 ? 1.0 : -1.0, s2 = i & 2 ? 1.0 : -1.0;
        corner[axis] = -h[axis], corner[a1] = s1 * h[a1], corner[a2] = s2 * h[a2];
        along[axis] = 2.0 * h[axis];
        out[a1] = s1, out[a2] = s2;
    }
    return {pose.center + pose.rotation * corner, pose.rotation * along, pose.rotation * out};
}

// How many edges a shape's edge pass tests: a box's twelve, a hull's edges, no other's.
uint32_t shape_edge_count(const RigidShape& shape) {
    return shape.type == ShapeType::box ? 12 : shape.type == ShapeType::convex_hull ? uint32_t(shape.hull_edges.size() / 2) : 0;
}

// The edges of body a (sharp, and folds bent outward) near edge i of shape k (a box or a hull)
// of body o (at the step's start and end) against it: a crossing between the nodes of a's edge,
// which no face's point under the shape sees (the shape's deepest point under a face lies at
// the face's border there). The record names the shape's edge: a box's by `end`, a hull's by its
// points (triangle[0..1]).
void edges_against_shape_edge(const ContactBody& a, uint32_t ai, const ContactBody& o, uint32_t k, uint32_t i,
                              const ContactCandidates& c, FeatureScratch& s, const std::vector<ContactBody>& bodies) {
    const RigidShape& shape = o.shapes[k];
    const ShapeEdge end = shape_edge(shape, ShapePose::load(o.shape_pose + 7 * std::size_t(k)), i);
    const ShapeEdge start = shape_edge(shape, ShapePose::load(o.shape_pose_start + 7 * std::size_t(k)), i);
    const double l = a.edge_length, band = kCaptureBand * l, reach = edge_reach(c, l);
    Aabb region = empty_box();
    for (const Vec3& p : {end.from, Vec3(end.from + end.along), start.from, Vec3(start.from + start.along)})
        for (int d = 0; d < 3; ++d) region.lo[d] = std::min(region.lo[d], p[d]), region.hi[d] = std::max(region.hi[d], p[d]);
    region = grown(region, band + reach + 2.0 * c.budget[ai]);
    if (!overlaps(region, grown(c.body_box[ai], c.budget[ai]))) return;  // most of a large hull's edges
    s.triangles.clear();
    c.tree_of(bodies, ai).query(region, a.x, a.triangles, c.budget[ai], [&](uint32_t t) { s.triangles.push_back(t); });
    edges_of(a, s.triangles, s.edges.marks, s.match);
    const bool hull = shape.type == ShapeType::convex_hull;
    for (uint32_t ea : s.match) {
        if (is_fold(a, ea) && !fold_bends_out(a, ea)) continue;
        ContactRecord r = edge_record(a, ea, o.slot);
        r.shape = k, r.end = hull ? 0 : uint8_t(i);
        r.triangle[0] = hull ? shape.hull_edges[2 * std::size_t(i)] : UINT32_MAX;
        r.triangle[1] = hull ? shape.hull_edges[2 * std::size_t(i) + 1] : UINT32_MAX;
        r.triangle[2] = UINT32_MAX;
        const ContactRecord* last = last_of(s, r);
        const uint32_t* na = edge_of(a, ea);
        double line[6];
        for (int d = 0; d < 3; ++d) line[d] = a.x[3 * std::size_t(na[0]) + d], line[3 + d] = a.x[3 * std::size_t(na[1]) + d] - line[d];
        EdgeEdgeHit hit;
        if (!test_edge_box_edge(a, ea, line, end.from, end.along, start.from, start.along, end.out, reach, band,
                                edge_allowance(last, l), last != nullptr, hit) ||
            !take_edge_hit(hit, last, l, r))
            continue;
        for (int d = 0; d < 3; ++d) {
            r.point_end[d] = end.from[d] + hit.t * end.along[d];
            r.point_start[d] = start.from[d] + hit.t * start.along[d];
        }
        s.found.push_back(r);
    }
}

// Every box and convex hull of static and kinematic bodies against the edges of the moving
// bodies near it.
void edges_against_shapes(const std::vector<ContactBody>& bodies, const ContactCandidates& c, FeatureScratch& s) {
    for (uint32_t oi : c.shape_bodies) {
        const ContactBody& o = bodies[oi];
        for (uint32_t k = 0; k < o.shape_count; ++k) {
            const uint32_t edges = shape_edge_count(o.shapes[k]);
            if (edges == 0) continue;
            Aabb box = shape_box(o.shapes[k], ShapePose::load(o.shape_pose + 7 * std::size_t(k)));
            join(box, shape_box(o.shapes[k], ShapePose::load(o.shape_pose_start + 7 * std::size_t(k))));
            s.near.clear();
            c.body_grid.query(box, s.near);
            for (uint32_t ai : s.near) {
                const ContactBody& a = bodies[ai];
                if (ai == oi || !a.moves || !is_movable(a) || edge_count(a) == 0 || !bodies_may_touch(a, o)) continue;
                for (uint32_t i = 0; i < edges; ++i) edges_against_shape_edge(a, ai, o, k, i, c, s, bodies);
            }
        }
    }
}

}  // namespace

bool feature_less(const ContactRecord& x, const ContactRecord& y) { return key_of(x) < key_of(y); }

void detect_features(const std::vector<ContactBody>& bodies, const ContactCandidates& c,
                     const std::vector<ContactRecord>& previous, FeatureScratch& s, std::vector<ContactRecord>& list,
                     std::vector<RecordRun>& runs, Profile& profile, ThreadPool* pool) {
    if (!c.valid) return;
    // Part of the sub-step's narrow phase: its time is added there, not its call.
    PhaseTimer timer(profile.narrow_phase, 0);
    s.previous.clear();
    for (const ContactRecord& r : previous)
        if (r.feature()) s.previous.push_back(&r);
    s.found.clear();
    s.start_gaps.clear();
    shapes_against_faces(bodies, c, s);
    edges_against_shapes(bodies, c, s);
    edges_against_edges(bodies, c, s, pool);
    if (s.found.empty()) return;
    std::sort(s.found.begin(), s.found.end(), feature_less);
    // In the list's order: the features after the nodes of their body_a.
    s.merged.clear();
    std::merge(list.begin(), list.end(), s.found.begin(), s.found.end(), std::back_inserter(s.merged), list_order);
    list.swap(s.merged);
    runs.clear();
    append_runs(list.data(), uint32_t(list.size()), runs);
}

}  // namespace lfem
