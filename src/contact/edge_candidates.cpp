#include "contact/edge_candidates.h"

#include <algorithm>

#include "contact/detection_tolerances.h"

namespace lfem {
namespace {

using EdgeBox = EdgeCandidates::EdgeBox;

// The box of sharp edge e of body b at x*, grown by `grow`.
Aabb edge_box(const ContactBody& b, uint32_t e, double grow) {
    Aabb box = empty_box();
    for (int v = 0; v < 2; ++v) {
        const double* x = b.x + 3 * std::size_t(b.sharp_edges[4 * std::size_t(e) + v]);
        for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], x[k]), box.hi[k] = std::max(box.hi[k], x[k]);
    }
    return grown(box, grow);
}

// Two sharp edges of one body (self-contact) are a pair once (the first of the two as a's) and
// only when they share no node: edges that meet at a node lie on each other there by
// construction, and a crossing near that node is its own to hold (node against face).
bool own_edges_may_cross(const ContactBody& b, uint32_t ea, uint32_t eb) {
    if (!(ea < eb)) return false;
    const uint32_t* p = &b.sharp_edges[4 * std::size_t(ea)];
    const uint32_t* q = &b.sharp_edges[4 * std::size_t(eb)];
    return p[0] != q[0] && p[0] != q[1] && p[1] != q[0] && p[1] != q[1];
}

// The pairs of a's and b's sharp edges whose boxes, a's grown by `reach`, overlap: a's edges near
// b's box, b's found through its tree under them (one query: a large floor's edges are not all
// visited), then swept along x (sort and sweep, O(n log n + pairs)). A self-contact body against
// itself (a == b) the same way, each pair of its edges once (own_edges_may_cross).
void pairs_of_bodies(const std::vector<ContactBody>& bodies, const ContactCandidates& c, uint32_t ai, uint32_t bi,
                     EdgeCandidates& e) {
    const ContactBody& a = bodies[ai];
    const ContactBody& b = bodies[bi];
    // Within the band of crossing, or as deep as a held pair may start (detect_features.cpp),
    // after both have used up their budgets.
    const double l = contact_length(a, b);
    const double reach =
        c.budget[ai] + c.budget[bi] + triangle_growth(l, c.offset_allowed, false) + kFallenRecovery * l;
    e.boxes_a.clear();
    Aabb near = empty_box();
    for (uint32_t ea = 0; ea < a.sharp_edge_count; ++ea) {
        const Aabb box = edge_box(a, ea, reach);
        if (!overlaps(box, c.body_box[bi])) continue;
        e.boxes_a.push_back({box, ea});
        join(near, box);
    }
    if (e.boxes_a.empty()) return;
    e.triangles.clear();
    c.tree_of(bodies, bi).query(near, b.x, b.triangles, 0.0, [&](uint32_t t) { e.triangles.push_back(t); });
    sharp_edges_of(b, e.triangles, e.edges);
    e.boxes_b.clear();
    for (uint32_t eb : e.edges) {
        const Aabb box = edge_box(b, eb, 0.0);
        if (overlaps(box, near)) e.boxes_b.push_back({box, eb});
    }
    const auto by_lo = [](const EdgeBox& x, const EdgeBox& y) {
        return x.box.lo[0] != y.box.lo[0] ? x.box.lo[0] < y.box.lo[0] : x.edge < y.edge;
    };
    std::sort(e.boxes_a.begin(), e.boxes_a.end(), by_lo);
    std::sort(e.boxes_b.begin(), e.boxes_b.end(), by_lo);
    const std::size_t first = e.pairs.size();
    // Each box meets those of the other list that start within its x-extent, once: the one of
    // the two that starts first finds the other.
    std::size_t i = 0, j = 0;
    while (i < e.boxes_a.size() && j < e.boxes_b.size()) {
        const bool a_first = e.boxes_a[i].box.lo[0] <= e.boxes_b[j].box.lo[0];
        const EdgeBox& x = a_first ? e.boxes_a[i] : e.boxes_b[j];
        const std::vector<EdgeBox>& others = a_first ? e.boxes_b : e.boxes_a;
        for (std::size_t k = a_first ? j : i; k < others.size() && others[k].box.lo[0] <= x.box.hi[0]; ++k) {
            if (!overlaps(x.box, others[k].box)) continue;
            const EdgePair p = a_first ? EdgePair{ai, bi, x.edge, others[k].edge, 0, 0}
                                       : EdgePair{ai, bi, others[k].edge, x.edge, 0, 0};
            if (ai != bi || own_edges_may_cross(a, p.edge_a, p.edge_b)) e.pairs.push_back(p);
        }
        a_first ? ++i : ++j;
    }
    std::sort(e.pairs.begin() + first, e.pairs.end(), [](const EdgePair& x, const EdgePair& y) {
        return x.edge_a != y.edge_a ? x.edge_a < y.edge_a : x.edge_b < y.edge_b;
    });
}

}  // namespace

void sharp_edges_of(const ContactBody& b, const std::vector<uint32_t>& triangles, std::vector<uint32_t>& out) {
    out.clear();
    for (uint32_t t : triangles)
        for (int v = 0; v < 3; ++v) {
            const uint32_t* tri = &b.triangles[3 * std::size_t(t)];
            const uint32_t e = sharp_edge_between(b, tri[v], tri[(v + 1) % 3]);
            if (e != UINT32_MAX) out.push_back(e);
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

uint32_t sharp_edge_between(const ContactBody& b, uint32_t i, uint32_t j) {
    const uint32_t u = std::min(i, j), v = std::max(i, j);
    uint32_t lo = 0, hi = b.sharp_edge_count;
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        const uint32_t* e = &b.sharp_edges[4 * std::size_t(mid)];
        if (e[0] < u || (e[0] == u && e[1] < v)) lo = mid + 1;
        else hi = mid;
    }
    const uint32_t* e = &b.sharp_edges[4 * std::size_t(lo)];
    return lo < b.sharp_edge_count && e[0] == u && e[1] == v ? lo : UINT32_MAX;
}

void update_edge_pairs(const std::vector<ContactBody>& bodies, const ContactCandidates& c, EdgeCandidates& e) {
    if (e.search == c.searches) return;
    e.search = c.searches;
    e.pairs.clear();
    // The pairs of different bodies the search put within reach (each once).
    e.body_pairs.clear();
    for (uint32_t ai = 0; ai + 1 < c.partner_begin.size(); ++ai)
        for (uint32_t q = c.partner_begin[ai]; q < c.partner_begin[ai + 1]; ++q) {
            const uint32_t bi = c.partners[q];
            if (bodies[ai].sharp_edge_count == 0 || bodies[bi].sharp_edge_count == 0) continue;
            if (bi == ai && !bodies[ai].self_contact) continue;
            e.body_pairs.push_back(ai < bi ? uint64_t(ai) << 32 | bi : uint64_t(bi) << 32 | ai);
        }
    std::sort(e.body_pairs.begin(), e.body_pairs.end());
    e.body_pairs.erase(std::unique(e.body_pairs.begin(), e.body_pairs.end()), e.body_pairs.end());
    for (uint64_t key : e.body_pairs) {
        const uint32_t lo = uint32_t(key >> 32), hi = uint32_t(key);
        if (lo != hi && !bodies_may_touch(bodies[lo], bodies[hi])) continue;
        const bool swap = bodies[hi].sharp_edge_count < bodies[lo].sharp_edge_count;
        pairs_of_bodies(bodies, c, swap ? hi : lo, swap ? lo : hi, e);
    }
    e.edges_used.clear();
    for (const EdgePair& p : e.pairs) {
        e.edges_used.push_back(uint64_t(p.a) << 32 | p.edge_a);
        e.edges_used.push_back(uint64_t(p.b) << 32 | p.edge_b);
    }
    std::sort(e.edges_used.begin(), e.edges_used.end());
    e.edges_used.erase(std::unique(e.edges_used.begin(), e.edges_used.end()), e.edges_used.end());
    const auto place = [&](uint32_t body, uint32_t edge) {
        const uint64_t key = uint64_t(body) << 32 | edge;
        return uint32_t(std::lower_bound(e.edges_used.begin(), e.edges_used.end(), key) - e.edges_used.begin());
    };
    for (EdgePair& p : e.pairs) p.line_a = place(p.a, p.edge_a), p.line_b = place(p.b, p.edge_b);
}


void update_edge_lines(const std::vector<ContactBody>& bodies, EdgeCandidates& e) {
    e.lines.resize(6 * e.edges_used.size());
    for (std::size_t k = 0; k < e.edges_used.size(); ++k) {
        const ContactBody& b = bodies[uint32_t(e.edges_used[k] >> 32)];
        const uint32_t* edge = &b.sharp_edges[4 * std::size_t(uint32_t(e.edges_used[k]))];
        const double* x0 = b.x + 3 * std::size_t(edge[0]);
        const double* x1 = b.x + 3 * std::size_t(edge[1]);
        double* line = &e.lines[6 * k];
        for (int d = 0; d < 3; ++d) line[d] = x0[d], line[3 + d] = x1[d] - x0[d];
    }
}

}  // namespace lfem
