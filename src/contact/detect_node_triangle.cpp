#include "contact/detect_node_triangle.h"

#include <algorithm>
#include <cmath>

#include "common/profile.h"
#include "contact/detection_tolerances.h"
#include "contact/warm_start.h"

namespace lfem {
namespace {

// Candidate nodes per block of the parallel narrow phase. Fixed, not per thread, so the blocks
// and the order they are joined in are the same for any thread count. Far fewer than the node
// loops' kNodeBlock: a node's face tests cost much more than a predictor update, and the few
// hundred candidate nodes of 32 small cubes on a floor should still share out evenly (512 of
// them: 16 blocks, not 8 of 64, whose last one kept a thread waiting 2 % of a frame).
constexpr uint32_t kSlaveBlock = 32;
// Moving candidate faces per block of the pass that makes their FaceSteps (cheap, one each).
constexpr uint32_t kFaceBlock = 256;

// How deep the last step left the pair (ContactRecord::kept_offset), 0 for a new one.
double kept_offset(const ContactRecord* r) { return r ? r->kept_offset() : 0.0; }

// What the narrow phase's blocks read and none of them writes (but each its own nodes' tracks
// and pairs' skips).
struct NarrowInput {
    const std::vector<ContactBody>& bodies;
    const std::vector<ContactRecord>& previous;
    const DetectionScratch& s;  // s.faces: this sub-step's moving faces
    bool scan_overlaps;
    double max_offset;  // the deepest overlap being recovered (m)
    bool any_shapes;
    NodeTrack* node_tracks;
    PairSkip* pair_skips;
};

// Skipping faces a node cannot meet yet. A pair turned away because the node's point on the
// face lies outside the triangle by a barycentric margin sigma stays turned away while the
// weights cannot have moved by sigma. A weight moves by at most (the point's move + 2.1 times
// the vertices' move + the tilt of the face times the point's distance from it) / the
// triangle's smallest height: 1 / height for the point (a weight is its distance from an edge's
// line over that height); 1 + 2 (0.26 + 0.26) < 2.1 for the vertices (moving them by d moves the
// weights as moving the point by sum |w| d would, and a point within 0.26 of the triangle has
// sum |w| below 2.04); a tilt of 2 d / height for the face. The moves are bounded by the
// odometers: between two sub-steps the point tested moves by at most its path in the first,
// the move of its step-start position and its path in the second. A pair is skipped only while
// that bound stays below half of sigma, and the triangle keeps at least half its height: a
// skipped pair is one the test would have turned away, so the records are bitwise those of
// testing every pair. Not while new bodies are searched for overlaps (a half-edge deep reach).
// skip.margin > 0: the pair was turned away as lying outside.
bool still_outside(const PairSkip& skip, bool scan_overlaps, double node_odometer, double node_path,
                   const FaceTrack* face_track, const FaceStep* face, double far_reach) {
    if (scan_overlaps) return false;
    const double dp = node_odometer - skip.node_mark + node_path;
    const double df = face_track ? face_track->odometer - skip.face_mark + face->motion : 0.0;
    const double h = skip.height - 2.0 * df;
    if (!(h > 0.5 * skip.height)) return false;
    // (dp + (2.1 + 2 far_reach / h) df) / h < sigma / 2, multiplied by h^2 > 0: no division in
    // the test that every skipped pair takes at every sub-step.
    return dp * h + (2.1 * h + 2.0 * far_reach) * df < 0.5 * skip.margin * h * h;
}

// How far from a face's plane a node may be when it meets the face (its distance bounds the
// tilt term above): the capture band in front, the depth allowance or half a contact length
// behind (an initial overlap's reach, and a held node's on the neighbours of the triangle that
// held it, node_face.cpp), and the node's path.
double far_reach(const ContactCandidates& c, double l, bool deep, double node_path) {
    const double behind = std::max(allowed_depth(c.offset_allowed, l), deep ? kInitialDepth * l : 0.0);
    return std::max(kCaptureBand * l, behind) + 2.0 * node_path;
}

// Was the pair held at a triangle last step (not at a shape, not letting out an overlap)?
bool held_at_face(const ContactRecord* last) { return last && last->shape == UINT32_MAX && last->offset <= 0.0; }

// The box of node p's path x^n -> x*.
Aabb path_box(const ContactBody& a, uint32_t p) {
    Aabb box;
    for (int k = 0; k < 3; ++k) {
        box.lo[k] = std::min(a.x_start[3 * p + k], a.x[3 * p + k]);
        box.hi[k] = std::max(a.x_start[3 * p + k], a.x[3 * p + k]);
    }
    return box;
}

// Candidate node g (node p of body ai) against its candidate triangles whose box over the step
// reaches its path: at most one record per other body, in body order, appended to the block's
// records. The candidates come in body order, then triangle order: `touched` stays sorted, and
// a body's best and deepest faces are the last entries while its triangles are tested.
// Candidate node g's outward normal, made when first asked for and kept in slave_normals.
NodeNormal normal_of(const NarrowInput& in, uint32_t g, Vec3* slave_normals, uint8_t* ready) {
    const ContactCandidates& c = in.s.candidates;
    return NodeNormal{in.bodies[c.body[g]], c.node[g], &slave_normals[g], &ready[g]};
}

// Two faces that both hold a node and face each other across it (a valley of a fold closing
// on it, or two parts squeezing it): turned from each other by more than the valley angle,
// each in front of the other's plane. One constraint would push the node along its face's
// normal into the other; the node needs both.
Vec3 centroid(const ContactBody& b, uint32_t t) {
    const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
    return (position(b.x, tri[0]) + position(b.x, tri[1]) + position(b.x, tri[2])) / 3.0;
}
bool form_valley(const ContactBody& b, const NodeCandidate& u, const NodeCandidate& v) {
    if (!(u.normal.dot(v.normal) < kValleyCos)) return false;
    const Vec3 cu = centroid(b, u.triangle), cv = centroid(b, v.triangle);
    return u.normal.dot(cv - cu) > 0.0 && v.normal.dot(cu - cv) > 0.0;
}

// The last step's record of the pair with the same triangle as c, if there is one (a pair may
// have had two), else the pair's first.
const ContactRecord* same_face(const NarrowInput& in, const ContactBody& b, const ContactRecord* last,
                               const NodeCandidate& c) {
    if (!last || c.shape != UINT32_MAX) return last;
    const uint32_t* tri = &b.triangles[3 * std::size_t(c.triangle)];
    const ContactRecord* end = in.previous.data() + in.previous.size();
    for (const ContactRecord* r = last;
         r < end && r->body_a == last->body_a && r->node == last->node && r->body_b == last->body_b; ++r)
        if (same_triangle(r->triangle, tri)) return r;
    return last;
}

// Node p of a, its faces found: the records of the other bodies it met, in body order. An
// overlap met for the first time is taken here too (see below), and so is a node inside a
// deformable body (its own, with self-contact): one that started deeper behind a face than the
// pair was left, within half a contact length, and lies in a tet around that face's corners
// (not merely behind its plane, as above a thin part). It is taken when no face holds it, or
// when one holds it only by an edge it lies beyond while it is deeper than 1e-2 of an edge (a
// node resting at the seam of two bodies is inside by a hair: pushing it out through another
// face would fight the one that holds it). It is pushed out through that face (fallen in).
// Of the faces that hold a node, the best, and the best of those that form a valley with it
// (form_valley).
void keep_records(const NarrowInput& in, const ContactBody& a, uint32_t p, DetectionBlock& block) {
    const ContactCandidates& c = in.s.candidates;
    // An overlap met for the first time: accepted when nothing of the other body lies between
    // the node and the face (then the node is inside, and this face is its nearest way out);
    // otherwise the node is merely beyond a thin part.
    for (std::size_t k = 0; k < block.touched.size(); ++k) {
        if (block.deep_of[k] == UINT32_MAX) continue;
        const NodeCandidate& d = block.deep[block.deep_of[k]];
        if (!d.found || block.best[k].found) continue;
        const uint32_t bi = block.touched[k];
        const Vec3 x = position(a.x_start, p);
        if (!segment_crosses_body(x, x - d.start_gap * d.normal, d.triangle, in.bodies[bi],
                                  c.tree_of(in.bodies, bi), c.budget[bi])) {
            block.best[k] = d;
            block.best[k].fallen = !in.scan_overlaps;
        }
    }
    for (std::size_t k = 0; k < block.touched.size(); ++k) {
        const ContactBody& b = in.bodies[block.touched[k]];
        NodeCandidate& best = block.best[k];
        const NodeCandidate* inside = block.inside_of[k] == UINT32_MAX ? nullptr : &block.inside[block.inside_of[k]];
        if (inside && inside->found &&
            (!best.found || (best.lowest < 0.0 && inside->start_gap < -kFallenRecovery * contact_length(a, b))) &&
            inside_near(a, p, b, &b.triangles[3 * std::size_t(inside->triangle)], position(a.x_start, p))) {
            best = *inside;
            best.fallen = !in.scan_overlaps;
        }
        if (!best.found) continue;
        best.initial = in.scan_overlaps;
        block.records.push_back(make_record(a, p, b, best, same_face(in, b, block.last[k], best)));
        if (best.fallen) block.fallen.add(FallenIn{1, a.slot});
        if (in.any_shapes) block.record_gap.push_back(best.gap), block.record_fallen.push_back(best.fallen);
        if (best.shape != UINT32_MAX || best.slid || best.fallen) continue;
        const uint32_t begin = block.accepted_begin[k];
        const uint32_t end = k + 1 < block.touched.size() ? block.accepted_begin[k + 1] : uint32_t(block.accepted.size());
        const NodeCandidate* second = nullptr;
        for (uint32_t j = begin; j < end; ++j) {
            const NodeCandidate& e = block.accepted[j];
            if (e.triangle != best.triangle && form_valley(b, best, e) && (!second || e.gap > second->gap)) second = &e;
        }
        if (!second) continue;
        NodeCandidate other = *second;
        other.initial = in.scan_overlaps;
        block.records.push_back(make_record(a, p, b, other, same_face(in, b, block.last[k], other)));
        if (in.any_shapes) block.record_gap.push_back(other.gap), block.record_fallen.push_back(false);
    }
}

void test_node_triangles(const NarrowInput& in, uint32_t g, DetectionBlock& block, PreviousRecords& previous,
                         Vec3* slave_normals, uint8_t* ready) {
    const ContactCandidates& c = in.s.candidates;
    const uint32_t ai = c.body[g], p = c.node[g];
    const ContactBody& a = in.bodies[ai];
    const Aabb box = path_box(a, p);
    NodeTrack& track = in.node_tracks[g];
    const Vec3 start = position(a.x_start, p);
    track.odometer += (start - track.last_start).norm();
    track.last_start = start;
    const double node_path = (position(a.x, p) - start).norm();
    block.touched.clear();
    block.best.clear();
    block.inside.clear();
    block.inside_of.clear();
    block.deep.clear();
    block.deep_of.clear();
    block.last.clear();
    block.accepted.clear();
    block.accepted_begin.clear();
    double allowance = 0.0, grow = 0.0, l = 0.0, reach_near = 0.0, reach_deep = 0.0;
    bool first_touch = false, deep = false;
    uint32_t grow_body = UINT32_MAX;
    const ContactRecord* last = nullptr;  // the last step's record of (node, body), once looked up
    bool last_known = false;
    const uint32_t* held = nullptr;  // the triangle of the met body that held the node last step
    const NodeNormal normal = normal_of(in, g, slave_normals, ready);
    for (uint32_t k = c.triangle_begin[g]; k < c.triangle_begin[g + 1]; ++k) {
        const uint32_t bi = uint32_t(c.triangles[k] >> 32), t = uint32_t(c.triangles[k]);
        const ContactBody& b = in.bodies[bi];
        if (bi != grow_body) {  // the pair's lengths and rules, once per other body
            l = contact_length(a, b);
            deep = catches_deep_nodes(a, b, in.scan_overlaps);
            grow = triangle_growth(l, in.max_offset, deep);
            reach_near = far_reach(c, l, deep, node_path), reach_deep = far_reach(c, l, true, node_path);
            last_known = false;  // looked up when a moving face is skipped or the body is met
            grow_body = bi;
        }
        // A static triangle's box is the one the search kept; a moving one's is this sub-step's.
        const FaceStep* face = b.moves ? &in.s.faces[c.face_index[k]] : nullptr;
        const FaceTrack* face_track = b.moves ? &in.s.face_tracks[c.face_index[k]] : nullptr;
        PairSkip& skip = in.pair_skips[k];
        if (skip.margin > 0.0) {
            double reach_far = 0.0;  // how far from a moving face's plane the node may be met (its tilt)
            if (face_track) {
                if (!last_known) {
                    last = previous.find(a.slot, p, b.slot), last_known = true;
                    held = held_at_face(last) ? last->triangle : nullptr;
                }
                const bool next_to_held = held && shares_node(&b.triangles[3 * std::size_t(t)], held);
                reach_far = next_to_held ? reach_deep : reach_near;
            }
            if (still_outside(skip, in.scan_overlaps, track.odometer, node_path, face_track, face, reach_far)) continue;
            skip.margin = 0.0;
        }
        Aabb reach = face ? face->box : c.static_box[k];
        for (int d = 0; d < 3; ++d) reach.lo[d] -= grow, reach.hi[d] += grow;
        if (!overlaps(reach, box)) continue;
        if (block.touched.empty() || block.touched.back() != bi) {
            if (!last_known) {
                last = previous.find(a.slot, p, b.slot), last_known = true;
                held = held_at_face(last) ? last->triangle : nullptr;
            }
            block.touched.push_back(bi);
            block.best.emplace_back();
            const bool may_be_inside = b.inv_mass && b.node_elements;  // a deformable body
            block.inside_of.push_back(may_be_inside ? uint32_t(block.inside.size()) : UINT32_MAX);
            if (may_be_inside) block.inside.emplace_back();
            block.last.push_back(last);
            block.accepted_begin.push_back(uint32_t(block.accepted.size()));
            allowance = allowed_depth(kept_offset(last), l);
            first_touch = deep && last == nullptr;
            // A possible initial overlap is kept only where the pair is met for the first time.
            block.deep_of.push_back(first_touch ? uint32_t(block.deep.size()) : UINT32_MAX);
            if (first_touch) block.deep.emplace_back();
        }
        NodeSlots slots{block.best.back()};
        slots.deep = first_touch ? &block.deep.back() : nullptr;
        slots.inside = block.inside_of.back() == UINT32_MAX ? nullptr : &block.inside.back();
        slots.accepted = &block.accepted;
        const Outside out = test_node_triangle(a, p, normal, b, t, face, allowance, held, slots);
        if (out.margin > 0.0 && out.height > 0.0) {
            skip.margin = out.margin, skip.height = out.height;
            skip.node_mark = track.odometer - node_path;
            skip.face_mark = face_track ? face_track->odometer - face->motion : 0.0;
        }
    }
    keep_records(in, a, p, block);
}

// The candidate nodes of block b against their triangles; a node's unit normal, once needed,
// goes to slave_normals (3 per candidate node, `ready` set). When some node has shape
// candidates, where each node's records start and the gap of every record are kept for the
// shape pass.
void test_block_triangles(const NarrowInput& in, uint32_t b, DetectionBlock& block, Vec3* slave_normals,
                          uint8_t* ready) {
    const ContactCandidates& c = in.s.candidates;
    block.records.clear();
    block.record_begin.clear();
    block.record_gap.clear();
    block.record_fallen.clear();
    block.counts = ShapeQueryCounts{};
    block.fallen = FallenIn{};
    const uint32_t first = b * kSlaveBlock, end = std::min(uint32_t(c.body.size()), (b + 1) * kSlaveBlock);
    PreviousRecords previous(in.previous);
    previous.seek(in.bodies[c.body[first]].slot, c.node[first]);
    for (uint32_t g = first; g < end; ++g) {
        ready[g] = 0;
        if (in.any_shapes) block.record_begin.push_back(uint32_t(block.records.size()));
        test_node_triangles(in, g, block, previous, slave_normals, ready);
    }
    if (in.any_shapes) block.record_begin.push_back(uint32_t(block.records.size()));
}

// Rigid shapes: each candidate node of block b against its candidate shapes; a shape replaces
// the node's triangle of the same body when it is penetrated less. The block's records are
// rebuilt in the same order (body, node, other body).
void test_block_shapes(const NarrowInput& in, uint32_t b, DetectionBlock& block, Vec3* slave_normals,
                       uint8_t* ready) {
    const ContactCandidates& c = in.s.candidates;
    block.merged.clear();
    const std::vector<ContactRecord>& found = block.records;
    const uint32_t first = b * kSlaveBlock, end = std::min(uint32_t(c.body.size()), (b + 1) * kSlaveBlock);
    PreviousRecords previous(in.previous);
    previous.seek(in.bodies[c.body[first]].slot, c.node[first]);
    for (uint32_t g = first; g < end; ++g) {
        const ContactBody& a = in.bodies[c.body[g]];
        const uint32_t p = c.node[g];
        const Vec3 normal = c.shape_begin[g + 1] > c.shape_begin[g] ? normal_of(in, g, slave_normals, ready).get() : Vec3::Zero();
        const uint32_t begin = block.record_begin[g - first], stop = block.record_begin[g - first + 1];
        uint32_t next = begin;  // this node's records, ordered by body
        for (uint32_t k = c.shape_begin[g]; k < c.shape_begin[g + 1];) {
            const uint32_t oi = uint32_t(c.shapes[k] >> 32);
            const ContactBody& o = in.bodies[oi];
            while (next < stop && found[next].body_b < o.slot) block.merged.push_back(found[next++]);
            const bool has_triangle = next < stop && found[next].body_b == o.slot;
            NodeCandidate best;
            best.found = has_triangle;
            if (has_triangle) best.gap = block.record_gap[next];
            const ContactRecord* last = previous.find(a.slot, p, o.slot);
            const double allowance = allowed_depth(kept_offset(last), a.edge_length);
            for (; k < c.shape_begin[g + 1] && uint32_t(c.shapes[k] >> 32) == oi; ++k)
                test_node_shape(a, p, normal, o, uint32_t(c.shapes[k]), allowance, best, block.counts);
            if (in.scan_overlaps) best.fallen = false;  // an overlap of new bodies: let out gently
            if (best.found && best.shape != UINT32_MAX) {
                best.initial = in.scan_overlaps;
                block.merged.push_back(make_record(a, p, o, best, last));
                // The shape's fall replaces the triangle's, counted by the triangle pass.
                if (has_triangle && block.record_fallen[next]) block.fallen.nodes -= 1;
                if (best.fallen) block.fallen.add(FallenIn{1, a.slot});
                next += has_triangle;  // replaced by the shape
            } else if (has_triangle) {
                block.merged.push_back(found[next++]);
            }
        }
        while (next < stop) block.merged.push_back(found[next++]);
    }
    block.records.swap(block.merged);
}

// A moving face's odometer: the largest move of its vertices' step-start positions since the
// last sub-step.
void advance_face_track(const ContactBody& b, uint32_t t, FaceTrack& track) {
    double most = 0.0;
    for (int v = 0; v < 3; ++v) {
        const double* x = b.x_start + 3 * std::size_t(b.triangles[3 * t + v]);
        const Vec3 d(x[0] - track.last_start[3 * v], x[1] - track.last_start[3 * v + 1], x[2] - track.last_start[3 * v + 2]);
        most = std::max(most, d.squaredNorm());
        for (int k = 0; k < 3; ++k) track.last_start[3 * v + k] = x[k];
    }
    track.odometer += std::sqrt(most);
}

// After a search: every node and face starts its odometer at its step-start position, and every
// pair is tested.
void start_tracks(const std::vector<ContactBody>& bodies, DetectionScratch& s) {
    const ContactCandidates& c = s.candidates;
    s.node_tracks.resize(c.body.size());
    for (std::size_t g = 0; g < c.body.size(); ++g)
        s.node_tracks[g] = NodeTrack{position(bodies[c.body[g]].x_start, c.node[g]), 0.0};
    s.face_tracks.resize(c.faces.size());
    for (std::size_t k = 0; k < c.faces.size(); ++k) {
        advance_face_track(bodies[uint32_t(c.faces[k] >> 32)], uint32_t(c.faces[k]), s.face_tracks[k]);
        s.face_tracks[k].odometer = 0.0;  // from here
    }
    s.pair_skips.assign(c.triangles.size(), PairSkip{});
    s.tracks_ready = true;
}

// The blocks' records joined in block order, which is the list's order (each block copied on
// the pool to its place, its runs of one pair of bodies found by the same task while its
// records are in that core's cache); their counts added to the profile, and the runs joined
// (a run cut by a block's end made whole), in the same order.
FallenIn join_blocks(DetectionScratch& s, uint32_t blocks, std::vector<ContactRecord>& out,
                     std::vector<RecordRun>& runs, Profile& profile, ThreadPool* pool) {
    FallenIn fallen;
    s.block_begin.resize(blocks + 1);
    std::size_t total = 0;
    for (uint32_t b = 0; b < blocks; ++b) {
        const DetectionBlock& block = s.blocks[b];
        s.block_begin[b] = total;
        total += block.records.size();
        profile.shape_tests += block.counts.shape_tests;
        profile.ccd_queries += block.counts.ccd_queries;
        fallen.add(block.fallen);
    }
    s.block_begin[blocks] = total;
    out.resize(total);
    parallel_for(total >= 512 ? pool : nullptr, blocks, [&](uint32_t b) {
        DetectionBlock& block = s.blocks[b];
        std::copy(block.records.begin(), block.records.end(), out.begin() + std::ptrdiff_t(s.block_begin[b]));
        block.runs.clear();
        append_runs(block.records.data(), uint32_t(block.records.size()), block.runs);
    });
    runs.clear();
    for (uint32_t b = 0; b < blocks; ++b)
        for (const RecordRun& r : s.blocks[b].runs) {
            if (!runs.empty() && runs.back().body_a == r.body_a && runs.back().body_b == r.body_b) continue;
            runs.push_back(RecordRun{uint32_t(s.block_begin[b]) + r.first, r.body_a, r.body_b});
        }
    return fallen;
}

}  // namespace

double deepest_kept_offset(const std::vector<ContactRecord>& list) {
    double deepest = 0.0;
    for (const ContactRecord& r : list) deepest = std::max(deepest, r.kept_offset());
    return deepest;
}

FallenIn detect_node_triangle(const std::vector<ContactBody>& bodies, const std::vector<ContactRecord>& previous,
                          double max_offset, bool scan_overlaps, DetectionScratch& s, std::vector<ContactRecord>& out,
                          std::vector<RecordRun>& runs, Profile& profile, ThreadPool* pool) {
    // `out` keeps its old records until the join overwrites them: resized, not cleared, so that
    // only the records beyond its last length are constructed before being copied over.
    ContactCandidates& c = s.candidates;
    // The moving candidate faces' boxes and normals over this sub-step (each once, in blocks of
    // kFaceBlock), for the narrow phase.
    const auto step_faces = [&](uint32_t b) {
        const uint32_t faces = uint32_t(c.faces.size());
        for (uint32_t k = b * kFaceBlock; k < std::min(faces, (b + 1) * kFaceBlock); ++k) {
            const ContactBody& body = bodies[uint32_t(c.faces[k] >> 32)];
            s.faces[k] = face_step(body, uint32_t(c.faces[k]));
            advance_face_track(body, uint32_t(c.faces[k]), s.face_tracks[k]);
        }
    };
    const auto face_blocks = [&] { return (uint32_t(c.faces.size()) + kFaceBlock - 1) / kFaceBlock; };
    bool faces_stepped = false;
    {
        PhaseTimer timer(profile.broad_phase);
        bool hold = candidates_may_hold(bodies, max_offset, scan_overlaps, c);
        if (hold) {
            // One round for both: every body's move since the search, and the candidate faces'
            // steps, made now on the chance that the candidates hold (they nearly always do; if
            // not, the search below starts the faces' tracks again and they are stepped anew).
            const uint32_t nb = uint32_t(bodies.size()), fb = s.tracks_ready ? face_blocks() : 0;
            uint64_t work = c.faces.size();
            for (const ContactBody& b : bodies) work += b.surface_node_count;
            if (fb > 0) s.faces.resize(c.faces.size());
            parallel_for(work >= 1024 ? pool : nullptr, nb + fb,
                         [&](uint32_t k) { k < nb ? measure_move(bodies, k, c) : step_faces(k - nb); });
            faces_stepped = fb > 0 || c.faces.empty();
            hold = moves_within_budgets(c);
        }
        if (!hold) {
            search_candidates(bodies, max_offset, scan_overlaps, c, pool);
            profile.candidate_searches += 1;
            s.tracks_ready = false;  // new candidates: the tracks start again
            faces_stepped = false;
        }
    }
    const uint32_t nodes = uint32_t(c.body.size());
    if (nodes == 0) {
        out.clear();
        runs.clear();
        return FallenIn{};
    }
    const bool any_shapes = !c.shapes.empty();
    // Narrow phase: every candidate node against its candidate triangles, in blocks on the
    // pool, each block writing only its own records and scratch.
    if (!s.tracks_ready) start_tracks(bodies, s);
    const NarrowInput in{bodies, previous, s, scan_overlaps, max_offset, any_shapes, s.node_tracks.data(),
                         s.pair_skips.data()};
    const uint32_t blocks = (nodes + kSlaveBlock - 1) / kSlaveBlock;
    if (s.blocks.size() < blocks) s.blocks.resize(blocks);  // never shrinks: keeps capacity
    s.slave_normals.resize(nodes);
    s.normal_ready.resize(nodes);
    Vec3* normals = s.slave_normals.data();
    uint8_t* ready = s.normal_ready.data();
    {
        PhaseTimer timer(profile.narrow_phase);
        if (!faces_stepped) {
            s.faces.resize(c.faces.size());
            parallel_for(pool, face_blocks(), step_faces);
        }
        parallel_for(pool, blocks, [&](uint32_t b) { test_block_triangles(in, b, s.blocks[b], normals, ready); });
        if (!any_shapes) return join_blocks(s, blocks, out, runs, profile, pool);
    }
    PhaseTimer timer(profile.shape_queries);
    parallel_for(pool, blocks, [&](uint32_t b) { test_block_shapes(in, b, s.blocks[b], normals, ready); });
    return join_blocks(s, blocks, out, runs, profile, pool);
}

}  // namespace lfem
