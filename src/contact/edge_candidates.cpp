#include "contact/edge_candidates.h"

#include <algorithm>

#include "contact/detection_tolerances.h"
#include "contact/edge_edge.h"

namespace lfem {
namespace {

using EdgeBox = EdgeCandidates::EdgeBox;

// The box of edge e of body b at x*, grown by `grow`.
Aabb edge_box(const ContactBody& b, uint32_t e, double grow) {
    Aabb box = empty_box();
    for (int v = 0; v < 2; ++v) {
        const double* x = b.x + 3 * std::size_t(edge_of(b, e)[v]);
        for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], x[k]), box.hi[k] = std::max(box.hi[k], x[k]);
    }
    return grown(box, grow);
}

// How far apart a's and b's edges may come at the search and still be within the band of
// crossing, or as deep as a held pair may start (detect_features.cpp), once both have used up
// their budgets.
double search_reach(const std::vector<ContactBody>& bodies, const ContactCandidates& c, uint32_t ai, uint32_t bi) {
    const double l = contact_length(bodies[ai], bodies[bi]);
    return c.budget[ai] + c.budget[bi] + triangle_growth(l, c.offset_allowed, false) + kFallenRecovery * l;
}

bool by_lo(const EdgeBox& x, const EdgeBox& y) {
    return x.box.lo[0] != y.box.lo[0] ? x.box.lo[0] < y.box.lo[0] : x.edge < y.edge;
}

// A body with at most this many edges has them all boxed and sorted once per search (a cube of
// a pile meets several others); one with more (a floor, a terrain) is searched through its
// triangle tree for each body near it, so that its far edges are never visited.
constexpr uint32_t kListedEdges = 4096;
// Pairs of bodies per run of the candidates' making on the pool.
constexpr uint32_t kPairsPerChunk = 8;

using Chunk = EdgeCandidates::Chunk;

// Lists the edges of the bodies of the pairs with at most kListedEdges (e.listed_bodies, each
// once), on the pool: each body's edges with their boxes at x*, sorted by lo[0] (by_lo).
void list_edges(const std::vector<ContactBody>& bodies, EdgeCandidates& e, ThreadPool* pool) {
    e.listed_begin.assign(bodies.size(), UINT32_MAX);
    e.listed_bodies.clear();
    uint32_t total = 0;
    for (uint64_t key : e.body_pairs)
        for (uint32_t bi : {uint32_t(key >> 32), uint32_t(key)})
            if (e.listed_begin[bi] == UINT32_MAX && edge_count(bodies[bi]) <= kListedEdges)
                e.listed_begin[bi] = total, total += edge_count(bodies[bi]), e.listed_bodies.push_back(bi);
    e.listed.resize(total);
    parallel_for(pool, uint32_t(e.listed_bodies.size()), [&](uint32_t k) {
        const uint32_t bi = e.listed_bodies[k], first = e.listed_begin[bi], count = edge_count(bodies[bi]);
        for (uint32_t edge = 0; edge < count; ++edge) e.listed[first + edge] = {edge_box(bodies[bi], edge, 0.0), edge};
        std::sort(e.listed.begin() + first, e.listed.begin() + first + count, by_lo);
    });
}

// The edges of b whose boxes overlap `region`, with their boxes, sorted by lo[0] (by_lo): its
// sharp edges into `sharp`, its folds into `folds`. From its listed edges, or through its tree
// (b's triangles under the region) for a body with many.
void edges_in(const std::vector<ContactBody>& bodies, const ContactCandidates& c, uint32_t bi, const Aabb& region,
              const EdgeCandidates& e, Chunk& k, std::vector<EdgeBox>& sharp, std::vector<EdgeBox>& folds) {
    const ContactBody& b = bodies[bi];
    sharp.clear(), folds.clear();
    if (e.listed_begin[bi] != UINT32_MAX) {
        const uint32_t first = e.listed_begin[bi];
        for (uint32_t q = first; q < first + edge_count(b) && e.listed[q].box.lo[0] <= region.hi[0]; ++q)
            if (overlaps(e.listed[q].box, region)) (is_fold(b, e.listed[q].edge) ? folds : sharp).push_back(e.listed[q]);
        return;
    }
    k.triangles.clear();
    c.tree_of(bodies, bi).query(region, b.x, b.triangles, 0.0, [&](uint32_t t) { k.triangles.push_back(t); });
    edges_of(b, k.triangles, k.marks, k.edges);
    for (uint32_t eb : k.edges) {
        const Aabb box = edge_box(b, eb, 0.0);
        if (overlaps(box, region)) (is_fold(b, eb) ? folds : sharp).push_back({box, eb});
    }
    std::sort(sharp.begin(), sharp.end(), by_lo);
    std::sort(folds.begin(), folds.end(), by_lo);
}

// Each pair of boxes of xs and ys that overlap, as emit(x's edge, y's edge): both sorted by
// lo[0] (by_lo), swept along x (O(n + pairs)): each box meets those of the other list that
// start within its x-extent, once (the one of the two that starts first finds the other).
template <class Emit>
void overlapping_boxes(const std::vector<EdgeBox>& xs, const std::vector<EdgeBox>& ys, Emit&& emit) {
    std::size_t i = 0, j = 0;
    while (i < xs.size() && j < ys.size()) {
        const bool x_first = xs[i].box.lo[0] <= ys[j].box.lo[0];
        const EdgeBox& first = x_first ? xs[i] : ys[j];
        const std::vector<EdgeBox>& others = x_first ? ys : xs;
        for (std::size_t k = x_first ? j : i; k < others.size() && others[k].box.lo[0] <= first.box.hi[0]; ++k) {
            if (!overlaps(first.box, others[k].box)) continue;
            x_first ? emit(first.edge, others[k].edge) : emit(others[k].edge, first.edge);
        }
        x_first ? ++i : ++j;
    }
}

// Boxes grown by `reach`.
void grow_all(const std::vector<EdgeBox>& from, double reach, std::vector<EdgeBox>& to) {
    to.clear();
    for (const EdgeBox& x : from) to.push_back({grown(x.box, reach), x.edge});
}

// The folds of body fi under sharp edges of body si (boxes grown by the reach) whose boxes meet
// theirs: a group of the edge pass's watched folds (each once), with all of those sharp edges.
// Most lie flat under a resting face and are passed over each sub-step by one test of their
// bend; pairs with the group's sharp edges are made only for those bent outward.
void watch_folds(uint32_t si, const std::vector<EdgeBox>& sharp, uint32_t fi, const ContactBody& b,
                 const std::vector<EdgeBox>& folds, Chunk& k) {
    if (sharp.empty() || folds.empty()) return;
    const std::size_t first = k.watched.size();
    const uint32_t group = uint32_t(k.fold_groups.size());
    if (++k.marks.generation == 0) std::fill(k.marks.mark.begin(), k.marks.mark.end(), 0), k.marks.generation = 1;
    overlapping_boxes(sharp, folds, [&](uint32_t, uint32_t fold) {
        if (k.marks.mark[fold] == k.marks.generation) return;
        k.marks.mark[fold] = k.marks.generation;
        EdgeCandidates::WatchedFold w{group, fold, {0, 0, 0, 0}};
        fold_corners(b, fold, w.corners);
        // A static body's folds bend as they did when it was added: a flat one never holds (a
        // terrain's folds under a cube are not tested again each sub-step).
        if (b.moves || fold_bends(b.x, w.corners)) k.watched.push_back(w);
    });
    if (k.watched.size() == first) return;
    k.fold_groups.push_back({si, fi, uint32_t(k.group_sharp.size()), uint32_t(k.group_sharp.size() + sharp.size())});
    for (const EdgeBox& x : sharp) k.group_sharp.push_back(x.edge);
}

// The candidates of bodies lo <= hi: each one's edges near the other's box grown by the search's
// reach (edges_in); the pairs of their sharp edges whose boxes, one's grown by the reach,
// overlap (swept: overlapping_boxes), of the one with fewer sharp edges as a (a self-contact
// body against itself the same way, each pair of its edges once: own_edges_may_cross); and
// each one's folds under the other's sharp edges (watch_folds).
void edges_of_bodies(const std::vector<ContactBody>& bodies, const ContactCandidates& c, uint32_t lo, uint32_t hi,
                     const EdgeCandidates& e, Chunk& k) {
    const double reach = search_reach(bodies, c, lo, hi);
    edges_in(bodies, c, lo, grown(c.body_box[hi], reach), e, k, k.sharp_lo, k.folds_lo);
    if (lo == hi) {
        k.sharp_hi = k.sharp_lo;
    } else {
        edges_in(bodies, c, hi, grown(c.body_box[lo], reach), e, k, k.sharp_hi, k.folds_hi);
    }
    const bool swap = bodies[hi].sharp_edge_count < bodies[lo].sharp_edge_count;
    const uint32_t ai = swap ? hi : lo, bi = swap ? lo : hi;
    const ContactBody& a = bodies[ai];
    grow_all(swap ? k.sharp_hi : k.sharp_lo, reach, k.grown);
    const std::size_t first = k.pairs.size();
    overlapping_boxes(k.grown, swap ? k.sharp_lo : k.sharp_hi, [&](uint32_t ea, uint32_t eb) {
        if (ai != bi || own_edges_may_cross(a, ea, eb)) k.pairs.push_back({ai, bi, ea, eb, 0, 0});
    });
    std::sort(k.pairs.begin() + first, k.pairs.end(), [](const EdgePair& x, const EdgePair& y) {
        return x.edge_a != y.edge_a ? x.edge_a < y.edge_a : x.edge_b < y.edge_b;
    });
    const std::size_t marks = std::max(edge_count(bodies[lo]), edge_count(bodies[hi]));
    if (k.marks.mark.size() < marks) k.marks.mark.resize(marks, 0);  // watch_folds marks folds
    grow_all(k.sharp_lo, reach, k.grown);
    watch_folds(lo, k.grown, hi, bodies[hi], lo == hi ? k.folds_lo : k.folds_hi, k);
    if (lo == hi) return;
    grow_all(k.sharp_hi, reach, k.grown);
    watch_folds(hi, k.grown, lo, bodies[lo], k.folds_lo, k);
}

}  // namespace

// Two edges of one body (self-contact) are a pair once (the first of the two as a's) and
// only when they share no node: edges that meet at a node lie on each other there by
// construction, and a crossing near that node is its own to hold (node against face).
bool own_edges_may_cross(const ContactBody& b, uint32_t ea, uint32_t eb) {
    if (!(ea < eb)) return false;
    const uint32_t* p = edge_of(b, ea);
    const uint32_t* q = edge_of(b, eb);
    return p[0] != q[0] && p[0] != q[1] && p[1] != q[0] && p[1] != q[1];
}

void edges_of(const ContactBody& b, const std::vector<uint32_t>& triangles, EdgeMarks& marks, std::vector<uint32_t>& out) {
    out.clear();
    const uint32_t count = edge_count(b);
    if (count == 0) return;  // the body's edge pass is off
    if (marks.mark.size() < count) marks.mark.resize(count, 0);
    if (++marks.generation == 0) std::fill(marks.mark.begin(), marks.mark.end(), 0), marks.generation = 1;
    for (uint32_t t : triangles)
        for (int v = 0; v < 3; ++v) {
            const uint32_t e = b.triangle_edges[3 * std::size_t(t) + v];
            if (e == UINT32_MAX || marks.mark[e] == marks.generation) continue;
            marks.mark[e] = marks.generation;
            out.push_back(e);
        }
}

void update_edge_pairs(const std::vector<ContactBody>& bodies, const ContactCandidates& c, EdgeCandidates& e,
                       ThreadPool* pool) {
    if (e.search == c.searches) return;
    e.search = c.searches;
    e.pairs.clear();
    e.fold_groups.clear(), e.group_sharp.clear(), e.watched.clear();
    // The pairs of bodies the search put within reach (each once; a self-contact body with
    // itself), with a sharp edge between them (folds meet sharp edges only).
    e.body_pairs.clear();
    for (uint32_t ai = 0; ai + 1 < c.partner_begin.size(); ++ai)
        for (uint32_t q = c.partner_begin[ai]; q < c.partner_begin[ai + 1]; ++q) {
            const uint32_t bi = c.partners[q];
            if (bodies[ai].sharp_edge_count == 0 && bodies[bi].sharp_edge_count == 0) continue;
            if (bi == ai ? !bodies[ai].self_contact : !bodies_may_touch(bodies[ai], bodies[bi])) continue;
            e.body_pairs.push_back(ai < bi ? uint64_t(ai) << 32 | bi : uint64_t(bi) << 32 | ai);
        }
    std::sort(e.body_pairs.begin(), e.body_pairs.end());
    e.body_pairs.erase(std::unique(e.body_pairs.begin(), e.body_pairs.end()), e.body_pairs.end());
    list_edges(bodies, e, pool);
    // In fixed runs of body pairs on the pool, joined in order.
    const uint32_t count = uint32_t(e.body_pairs.size()), chunks = (count + kPairsPerChunk - 1) / kPairsPerChunk;
    if (e.chunks.size() < chunks) e.chunks.resize(chunks);
    parallel_for(pool, chunks, [&](uint32_t q) {
        Chunk& k = e.chunks[q];
        k.pairs.clear(), k.fold_groups.clear(), k.group_sharp.clear(), k.watched.clear();
        for (uint32_t i = q * kPairsPerChunk; i < std::min(count, (q + 1) * kPairsPerChunk); ++i)
            edges_of_bodies(bodies, c, uint32_t(e.body_pairs[i] >> 32), uint32_t(e.body_pairs[i]), e, k);
    });
    for (uint32_t q = 0; q < chunks; ++q) {
        const Chunk& k = e.chunks[q];
        const uint32_t groups = uint32_t(e.fold_groups.size()), sharp = uint32_t(e.group_sharp.size());
        e.pairs.insert(e.pairs.end(), k.pairs.begin(), k.pairs.end());
        for (EdgeCandidates::FoldGroup g : k.fold_groups)
            g.sharp_begin += sharp, g.sharp_end += sharp, e.fold_groups.push_back(g);
        e.group_sharp.insert(e.group_sharp.end(), k.group_sharp.begin(), k.group_sharp.end());
        for (EdgeCandidates::WatchedFold w : k.watched) w.group += groups, e.watched.push_back(w);
    }
    // A fold near the sharp edges of several bodies is watched once per group, side by side, so
    // that its bend is tested once per sub-step.
    std::sort(e.watched.begin(), e.watched.end(), [&](const EdgeCandidates::WatchedFold& x, const EdgeCandidates::WatchedFold& y) {
        const uint32_t bx = e.fold_groups[x.group].fold_body, by = e.fold_groups[y.group].fold_body;
        return bx != by ? bx < by : x.fold != y.fold ? x.fold < y.fold : x.group < y.group;
    });
    // Each edge the pairs name gets a line, in the order the pairs first name it: through a
    // slot per edge of each body the pairs name (edge_base: where its slots begin).
    e.edges_used.clear();
    e.edge_base.assign(bodies.size(), UINT32_MAX);
    uint32_t slots = 0;
    for (const EdgePair& p : e.pairs)
        for (uint32_t body : {p.a, p.b})
            if (e.edge_base[body] == UINT32_MAX) e.edge_base[body] = slots, slots += edge_count(bodies[body]);
    e.edge_line.assign(slots, UINT32_MAX);
    const auto place = [&](uint32_t body, uint32_t edge) {
        uint32_t& line = e.edge_line[e.edge_base[body] + edge];
        if (line == UINT32_MAX) line = uint32_t(e.edges_used.size()), e.edges_used.push_back(uint64_t(body) << 32 | edge);
        return line;
    };
    for (EdgePair& p : e.pairs) p.line_a = place(p.a, p.edge_a), p.line_b = place(p.b, p.edge_b);
}


void update_edge_lines(const std::vector<ContactBody>& bodies, EdgeCandidates& e) {
    e.lines.resize(6 * e.edges_used.size());
    for (std::size_t k = 0; k < e.edges_used.size(); ++k) {
        const ContactBody& b = bodies[uint32_t(e.edges_used[k] >> 32)];
        const uint32_t* edge = edge_of(b, uint32_t(e.edges_used[k]));
        const double* x0 = b.x + 3 * std::size_t(edge[0]);
        const double* x1 = b.x + 3 * std::size_t(edge[1]);
        double* line = &e.lines[6 * k];
        for (int d = 0; d < 3; ++d) line[d] = x0[d], line[3 + d] = x1[d] - x0[d];
    }
}

}  // namespace lfem
