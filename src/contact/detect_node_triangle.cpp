#include "contact/detect_node_triangle.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "common/profile.h"
#include "contact/detection_tolerances.h"
#include "contact/warm_start.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// Slave nodes per block of the parallel narrow phase. Fixed, not per thread, so the blocks
// and the order they are joined in are the same for any thread count. Far fewer than the
// node loops' kNodeBlock: a node's hash query and face tests cost much more than a predictor
// update, and a contact region of a few thousand nodes should still give every thread work.
constexpr uint32_t kSlaveBlock = 256;

Vec3 at(const double* x, uint32_t i) { return Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }

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

using Candidate = NodeCandidate;

// Test node p of `a` against triangle t of `b`; keep it in `best` if it is a valid contact
// with less penetration than what best holds.
void test_node_triangle(const ContactBody& a, uint32_t p, const Vec3& node_normal,
                        const ContactBody& b, uint32_t t, double depth_allowance, Candidate& best,
                        Candidate* deep) {
    const uint32_t* tri = &b.triangles[3 * t];
    if (a.slot == b.slot) return;  // self-contact is not handled here
    const Vec3 pa = at(b.x, tri[0]), pb = at(b.x, tri[1]), pc = at(b.x, tri[2]);
    const Vec3 qa = at(b.x_start, tri[0]), qb = at(b.x_start, tri[1]), qc = at(b.x_start, tri[2]);
    const Vec3 n_end = (pb - pa).cross(pc - pa), n_start = (qb - qa).cross(qc - qa);
    const double area2 = n_end.norm(), area2_start = n_start.norm();
    if (!(area2 > 0.0) || !(area2_start > 0.0)) return;  // a collapsed face has no normal
    const Vec3 n = n_end / area2;
    // Surfaces in contact face each other. A face whose normal points the same way as the
    // node's own surface normal is the far side of an edge the node sits on (a cube's corner
    // node resting on another cube's top face also lies in the plane of its side face): taking
    // it would push the node sideways off the edge. Convex edges thus keep the one right face.
    if (n.dot(node_normal) >= 0.0) return;
    const Vec3 x_end = at(a.x, p), x_start = at(a.x_start, p);
    const double gap = n.dot(x_end - pa);
    const double start_gap = (n_start / area2_start).dot(x_start - qa);
    const double l = b.edge_length;
    if (gap > kCaptureBand * l) return;
    Candidate* slot = &best;
    if (start_gap < -depth_allowance) {
        // Deeper than the pair was left: only a possible initial overlap (checked later).
        if (start_gap < -kInitialDepth * l || !deep) return;
        slot = deep;
    }
    double w[3];
    if (start_gap >= 0.0 && gap < 0.0) {
        // The path e -> f crossed the plane: the contact point is where it crossed (eq. 5),
        // with the triangle moved by the same fraction of its own step.
        const double s = start_gap / (start_gap - gap);
        barycentric(x_start + s * (x_end - x_start), qa + s * (pa - qa), qb + s * (pb - qb),
                    qc + s * (pc - qc), w);
    } else {
        barycentric(x_end, pa, pb, pc, w);  // at or behind the face: its projection
    }
    for (double wi : w)
        if (!(wi >= -kEdgeTolerance)) return;
    Candidate& c = *slot;
    if (c.found && gap <= c.gap) return;  // keep the face penetrated least
    c.found = true;
    c.triangle = t;
    c.shape = UINT32_MAX;
    c.gap = gap;
    c.start_gap = start_gap;
    c.normal = n;
    // Clamp the weights into the triangle: the force goes to its nodes, never outside.
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) sum += (c.w[k] = std::max(0.0, w[k]));
    for (int k = 0; k < 3; ++k) c.w[k] /= sum;
}

// Test node p of `a` against rigid shape j of `b`, same rules as for a triangle: within the
// capture band at the end of the step, no deeper at its start than the pair was left, facing
// the node's surface.
// The queries are counted in `counts` (its shape_tests and ccd_queries).
void test_node_shape(const ContactBody& a, uint32_t p, const Vec3& node_normal, const ContactBody& b,
                     uint32_t j, double depth_allowance, Candidate& best, DetectionBlock& counts) {
    const RigidShape& shape = b.shapes[j];
    const ShapePose pose_end = ShapePose::load(b.shape_pose + 7 * std::size_t(j));
    const ShapePose pose_start = ShapePose::load(b.shape_pose_start + 7 * std::size_t(j));
    const Vec3 x_end = at(a.x, p), x_start = at(a.x_start, p);
    const double band = kCaptureBand * a.edge_length;
    const double reach = shape_bounding_radius(shape) + band + (x_end - x_start).norm();
    if ((x_end - pose_end.center).norm() > reach) return;  // far from a bounded shape
    double gap, start_gap;
    Vec3 n, n_start;
    const uint64_t by_ccd = shape.type == LFEM_SHAPE_CONVEX_HULL;
    counts.shape_tests += 1, counts.ccd_queries += by_ccd;
    if (!shape_signed_distance(shape, pose_end, x_end, band, gap, n)) return;
    // At the start the node may be anywhere along its path: ask with the whole path as reach.
    const double path = (x_end - x_start).norm() + band;
    counts.shape_tests += 1, counts.ccd_queries += by_ccd;
    if (shape_signed_distance(shape, pose_start, x_start, path, start_gap, n_start) &&
        start_gap < -depth_allowance)
        return;
    if (n.dot(node_normal) >= 0.0) return;
    if (best.found && gap <= best.gap) return;
    best.found = true;
    best.shape = j;
    best.gap = gap;
    best.start_gap = std::min(0.0, start_gap);
    best.normal = n;
    best.point_end = x_end - gap * n;  // the nearest surface point
    // The same material point of the shape at the start of the step.
    best.point_start = pose_start.center +
                       pose_start.rotation * (pose_end.rotation.conjugate() * (best.point_end - pose_end.center));
}

// The constraint of node p of `a` against the candidate face or shape of `b`, warm-started
// from the pair's last record (nullable).
ContactRecord make_record(const ContactBody& a, uint32_t p, const ContactBody& b, const Candidate& c,
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
    // A node that starts the step inside is let out gradually (target gap < 0): by 20 % of
    // the overlap per step, but never faster than 1e-3 of an edge per step, so bodies created
    // deeply overlapping separate slowly instead of jumping apart.
    if (c.start_gap < 0.0) {
        const double overlap = -c.start_gap;
        const double l = c.shape == UINT32_MAX ? b.edge_length : a.edge_length;
        r.offset = overlap - std::min(kOverlapRecovery * overlap, kMaxRecovery * l);
    }
    return r;
}

// Does the open segment from `from` to `to` cross a boundary triangle of body b other than
// `skip`? (Möller-Trumbore against the triangles whose boxes the segment's box overlaps;
// `ids` is scratch for the hash's answer.)
bool segment_crosses_body(const Vec3& from, const Vec3& to, uint32_t bi, uint32_t skip,
                          const ContactBody& b, const BroadPhase& s, std::vector<uint32_t>& ids) {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(from[k], to[k]), box.hi[k] = std::max(from[k], to[k]);
    ids.clear();
    s.grid.query(box, ids);
    const Vec3 d = to - from;
    for (uint32_t id : ids) {
        if (s.box_body[id] != bi || s.box_triangle[id] == skip) continue;
        const uint32_t* tri = &b.triangles[3 * s.box_triangle[id]];
        const Vec3 v0 = at(b.x_start, tri[0]), e1 = at(b.x_start, tri[1]) - v0, e2 = at(b.x_start, tri[2]) - v0;
        const Vec3 pv = d.cross(e2);
        const double det = e1.dot(pv);
        if (std::fabs(det) < 1e-300) continue;
        const Vec3 tv = from - v0;
        const double u = tv.dot(pv) / det;
        if (u < 0.0 || u > 1.0) continue;
        const Vec3 qv = tv.cross(e1);
        const double v = d.dot(qv) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        const double t = e2.dot(qv) / det;
        if (t > 1e-9 && t < 1.0 - 1e-9) return true;
    }
    return false;
}

// How deep the last step left the pair: a kept overlap or the solver's residual.
double kept_offset(const ContactRecord* r) { return r ? std::max(0.0, -r->gap_after) : 0.0; }

// What the narrow phase's blocks read and none of them writes: the broad phase's results in
// the scratch (everything but the blocks themselves), the bodies and the last step's list.
struct NarrowInput {
    const std::vector<ContactBody>& bodies;
    const std::vector<ContactRecord>& previous;
    const DetectionScratch& s;
    const BroadPhase& bp;
    bool scan_overlaps;
    bool any_shapes;
};

// Lays the tested bodies' slave nodes out as one sequence (slave_begin), and adds up, per
// node of each tested body, the area-weighted normals of the boundary triangles around it
// (node_normals, body ai's from node_begin[ai]). Serial: a node's triangles add in triangle
// order. Only the entries that are read or added to are zeroed, not every node of the body:
// the blocks normalize the slave nodes' sums. Returns the block count.
uint32_t prepare_slave_blocks(const std::vector<ContactBody>& bodies, DetectionScratch& s) {
    s.slave_begin.assign(1, 0);
    s.node_begin.assign(1, 0);
    for (uint32_t ai = 0; ai < bodies.size(); ++ai) {
        const bool tested = s.broad.tested[ai];  // else no slave nodes, or nothing within their reach
        s.slave_begin.push_back(s.slave_begin.back() + (tested ? bodies[ai].node_count : 0));
        s.node_begin.push_back(s.node_begin.back() + (tested ? bodies[ai].total_nodes : 0));
    }
    s.node_normals.resize(3 * std::size_t(s.node_begin.back()));
    s.slave_normals.resize(3 * std::size_t(s.slave_begin.back()));
    for (uint32_t ai = 0; ai < bodies.size(); ++ai) {
        if (!s.broad.tested[ai]) continue;
        const ContactBody& a = bodies[ai];
        double* sum = s.node_normals.data() + 3 * std::size_t(s.node_begin[ai]);
        for (uint32_t j = 0; j < a.node_count; ++j)
            for (int k = 0; k < 3; ++k) sum[3 * a.nodes[j] + k] = 0.0;
        for (uint32_t c = 0; c < 3 * a.triangle_count; ++c)
            for (int k = 0; k < 3; ++k) sum[3 * a.triangles[c] + k] = 0.0;
        for (uint32_t t = 0; t < a.triangle_count; ++t) {
            const uint32_t* tri = &a.triangles[3 * t];
            const Vec3 n2 = (at(a.x, tri[1]) - at(a.x, tri[0])).cross(at(a.x, tri[2]) - at(a.x, tri[0]));
            for (int v = 0; v < 3; ++v)
                for (int k = 0; k < 3; ++k) sum[3 * tri[v] + k] += n2[k];
        }
    }
    const uint32_t blocks = (s.slave_begin.back() + kSlaveBlock - 1) / kSlaveBlock;
    if (s.blocks.size() < blocks) s.blocks.resize(blocks);  // never shrinks: keeps capacity
    return blocks;
}

// Calls visit(ai, j, g) for the slave nodes g of block b of the sequence: node j of body ai.
template <class Visit>
void for_each_slave_of_block(const std::vector<uint32_t>& slave_begin, uint32_t b, const Visit& visit) {
    const uint32_t first = b * kSlaveBlock, last = std::min(slave_begin.back(), first + kSlaveBlock);
    // The body holding `first`: the last whose nodes start at or before it (bodies without
    // nodes in the sequence start where the next one does).
    uint32_t ai = uint32_t(std::upper_bound(slave_begin.begin(), slave_begin.end(), first) - slave_begin.begin()) - 1;
    for (uint32_t g = first; g < last; ++g) {
        while (slave_begin[ai + 1] <= g) ++ai;
        visit(ai, g - slave_begin[ai], g);
    }
}

// Node p of body ai against the triangles near its path: at most one record per other body,
// in body order, appended to the block's records.
void test_node_triangles(const NarrowInput& in, uint32_t ai, uint32_t p, const Vec3& node_normal,
                         DetectionBlock& block) {
    const BroadPhase& s = in.bp;
    const ContactBody& a = in.bodies[ai];
    const uint32_t* partner = s.partners.data() + s.partner_begin[ai];
    const uint32_t partner_count = s.partner_begin[ai + 1] - s.partner_begin[ai];
    Aabb box;
    for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(a.x_start[3 * p + k], a.x[3 * p + k]);
        box.hi[k] = std::max(a.x_start[3 * p + k], a.x[3 * p + k]);
    }
    bool reaches = false;  // some partner body's box: else nothing to ask the hash
    for (uint32_t q = 0; q < partner_count && !reaches; ++q) reaches = overlaps(box, s.body_box[partner[q]]);
    if (!reaches || s.boxes.empty()) return;
    block.candidates.clear();
    s.grid.query(box, block.candidates);
    // Candidates come in box order, which is body order: `touched` stays sorted, and a body's
    // best and deepest faces are the last entries while its triangles are tested.
    block.touched.clear();
    block.best.clear();
    block.deep.clear();
    block.last.clear();
    // The last step's record of (node, body): looked up once per body met.
    double allowance = 0.0;
    bool first_touch = false;
    for (uint32_t id : block.candidates) {
        const uint32_t bi = s.box_body[id];
        const ContactBody& b = in.bodies[bi];
        if (bi == ai || !bodies_may_touch(a, b)) continue;
        if (block.touched.empty() || block.touched.back() != bi) {
            block.touched.push_back(bi);
            block.best.emplace_back();
            block.deep.emplace_back();
            const ContactRecord* last = previous_record(in.previous, a.slot, p, b.slot);
            block.last.push_back(last);
            allowance = 1.25 * kept_offset(last) + kResidualDepth * b.edge_length;
            first_touch = in.scan_overlaps && last == nullptr;
        }
        test_node_triangle(a, p, node_normal, b, s.box_triangle[id], allowance, block.best.back(),
                           first_touch ? &block.deep.back() : nullptr);
    }
    // An overlap met for the first time: accepted when nothing of the other body lies between
    // the node and the face (then the node is inside, and this face is its nearest way out);
    // otherwise the node is merely beyond a thin part.
    for (std::size_t k = 0; k < block.touched.size(); ++k) {
        const Candidate& c = block.deep[k];
        if (!c.found || block.best[k].found) continue;
        const uint32_t bi = block.touched[k];
        const Vec3 x = at(a.x_start, p);
        if (!segment_crosses_body(x, x - c.start_gap * c.normal, bi, c.triangle, in.bodies[bi], s, block.crossing))
            block.best[k] = c;
    }
    for (std::size_t k = 0; k < block.touched.size(); ++k) {
        if (!block.best[k].found) continue;
        block.records.push_back(make_record(a, p, in.bodies[block.touched[k]], block.best[k], block.last[k]));
        if (in.any_shapes) block.record_gap.push_back(block.best[k].gap);
    }
}

// Every slave node of block b against the triangles near its path; its unit normal goes to
// slave_normals (3 per node of the sequence). When some body has rigid shapes, where each
// node's records start and the gap of every record are kept for the shape pass.
void test_block_triangles(const NarrowInput& in, uint32_t b, DetectionBlock& block, double* slave_normals) {
    block.records.clear();
    block.record_begin.clear();
    block.record_gap.clear();
    block.shape_tests = block.ccd_queries = 0;
    for_each_slave_of_block(in.s.slave_begin, b, [&](uint32_t ai, uint32_t j, uint32_t g) {
        // The node's outward unit normal at x*, kept for the shape pass (the block's own
        // entries of slave_normals).
        const uint32_t p = in.bodies[ai].nodes[j];
        const Vec3 n = at(in.s.node_normals.data() + 3 * std::size_t(in.s.node_begin[ai]), p).normalized();
        for (int k = 0; k < 3; ++k) slave_normals[3 * std::size_t(g) + k] = n[k];
        if (in.any_shapes) block.record_begin.push_back(uint32_t(block.records.size()));
        test_node_triangles(in, ai, p, n, block);
    });
    if (in.any_shapes) block.record_begin.push_back(uint32_t(block.records.size()));
}

// Rigid shapes: each slave node of block b against the shapes of the other bodies; a shape
// replaces the node's triangle of the same body when it is penetrated less. The block's
// records are rebuilt in the same order (body, node, other body).
void test_block_shapes(const NarrowInput& in, uint32_t b, DetectionBlock& block) {
    const DetectionScratch& s = in.s;
    block.merged.clear();
    const std::vector<ContactRecord>& found = block.records;
    uint32_t local = 0;  // the node's place in the block
    for_each_slave_of_block(s.slave_begin, b, [&](uint32_t ai, uint32_t j, uint32_t g) {
        const ContactBody& a = in.bodies[ai];
        const uint32_t p = a.nodes[j];
        const Vec3 node_normal = at(s.slave_normals.data(), g);
        const uint32_t begin = block.record_begin[local], end = block.record_begin[local + 1];
        ++local;
        uint32_t next = begin;  // this node's records, ordered by body
        for (uint32_t bi : in.bp.shape_bodies) {
            const ContactBody& o = in.bodies[bi];
            while (next < end && found[next].body_b < o.slot) block.merged.push_back(found[next++]);
            const bool has_triangle = next < end && found[next].body_b == o.slot;
            if (bi != ai && bodies_may_touch(a, o)) {
                Candidate c;
                c.found = has_triangle;
                if (has_triangle) c.gap = block.record_gap[next];
                const ContactRecord* last = previous_record(in.previous, a.slot, p, o.slot);
                const double allowance = 1.25 * kept_offset(last) + kResidualDepth * a.edge_length;
                for (uint32_t k = 0; k < o.shape_count; ++k)
                    test_node_shape(a, p, node_normal, o, k, allowance, c, block);
                if (c.found && c.shape != UINT32_MAX) {
                    block.merged.push_back(make_record(a, p, o, c, last));
                    next += has_triangle;  // replaced by the shape
                    continue;
                }
            }
            if (has_triangle) block.merged.push_back(found[next++]);
        }
        while (next < end) block.merged.push_back(found[next++]);
    });
    block.records.swap(block.merged);
}

// The blocks' records joined in block order, which is the list's order; their counts added
// to the profile in the same order.
void join_blocks(const DetectionScratch& s, uint32_t blocks, std::vector<ContactRecord>& out,
                 lfem_profile& profile) {
    std::size_t total = out.size();
    for (uint32_t b = 0; b < blocks; ++b) total += s.blocks[b].records.size();
    out.reserve(total);
    for (uint32_t b = 0; b < blocks; ++b) {
        const DetectionBlock& block = s.blocks[b];
        out.insert(out.end(), block.records.begin(), block.records.end());
        profile.shape_tests += block.shape_tests;
        profile.ccd_queries += block.ccd_queries;
    }
}

}  // namespace

void detect_node_triangle(const std::vector<ContactBody>& bodies,
                          const std::vector<ContactRecord>& previous, bool scan_overlaps,
                          DetectionScratch& s, std::vector<ContactRecord>& out,
                          lfem_profile& profile, ThreadPool* pool) {
    out.clear();
    double max_offset = 0.0;
    for (const ContactRecord& r : previous) max_offset = std::max(max_offset, -r.gap_after);
    {
        PhaseTimer timer(profile.broad_phase);
        run_broad_phase(bodies, max_offset, scan_overlaps, s.broad, pool);
    }
    const bool any_shapes = !s.broad.shape_bodies.empty();
    if (s.broad.boxes.empty() && !any_shapes) return;

    // Narrow phase: every slave node of a tested body against the triangles near its path,
    // in blocks on the pool, each block writing only its own records and scratch.
    const NarrowInput in{bodies, previous, s, s.broad, scan_overlaps, any_shapes};
    uint32_t blocks = 0;
    {
        PhaseTimer timer(profile.narrow_phase);
        blocks = prepare_slave_blocks(bodies, s);
        parallel_for(pool, blocks,
                     [&](uint32_t b) { test_block_triangles(in, b, s.blocks[b], s.slave_normals.data()); });
        if (!any_shapes) join_blocks(s, blocks, out, profile);
    }
    if (!any_shapes) return;
    PhaseTimer timer(profile.shape_queries);
    parallel_for(pool, blocks, [&](uint32_t b) { test_block_shapes(in, b, s.blocks[b]); });
    join_blocks(s, blocks, out, profile);
}

}  // namespace lfem
