// An active constraint of the forward increment Lagrange multiplier method: a point of body
// `body_a` against a point of body `body_b`, each a weighted sum of a few nodes (eq. 6's
// barycentric weights), with the multiplier (the contact force, newtons). Three kinds:
//  - node_face: node `node` of body_a against triangle `triangle` of body_b, or against rigid
//    shape `shape` of body_b (the paper's node-to-triangle constraint);
//  - face_shape: the point of body_a's boundary triangle nodes_a (weights weights_a) against
//    the point of rigid shape `shape` of body_b nearest to it: a shape poking between the
//    nodes (face_shape.h);
//  - edge_edge: the point of body_a's boundary edge nodes_a[0..1] (weights weights_a) against
//    the point of body_b's edge triangle[0..1] (weights 1 - t2, t2; t1 = 0): crossed edges
//    (edge_edge.h); or against an edge of body_b's box or hull shape `shape` (a box's by
//    `end`, of twelve; a hull's by its points triangle[0..1]), its point point_start and
//    point_end as a shape's.
// The last two are features: their `node` is kFeatureNode, so they sort after every node of
// body_a and never meet a node's lookups (warm_start.h).
#pragma once

#include <algorithm>

#include <cstdint>
#include <vector>

namespace lfem {

enum class ContactKind : uint8_t { node_face = 0, face_shape = 1, edge_edge = 2 };

// The `node` of a feature record (face_shape, edge_edge).
constexpr uint32_t kFeatureNode = UINT32_MAX;

struct ContactRecord {
    uint32_t body_a = 0, node = 0;       // slot index of the node's body, node index
    uint32_t body_b = 0;                 // slot index of the triangle's body
    uint32_t triangle[3] = {0, 0, 0};    // node indices a, b, c in body_b (unused for a shape)
    uint32_t shape = UINT32_MAX;         // index of body_b's rigid shape, or UINT32_MAX
    double point_start[3] = {0, 0, 0};   // shape contacts: the touched material point of the
    double point_end[3] = {0, 0, 0};     //   shape at the start and at the end of the step
    double t1 = 0, t2 = 0;               // barycentric: point = (1-t1-t2) a + t2 b + t1 c
    double normal[3] = {0, 0, 0};        // unit, out of body_b
    double lambda_n = 0;                 // N, normal multiplier (>= 0: tension release)
    double lambda_t[3] = {0, 0, 0};      // N, friction multiplier (tangential)
    double offset = 0;                   // m, overlap being recovered: target gap is -offset
    double gap_after = 0;                // m, gap left by the solve along `normal` (negative:
                                         //   penetration)
    double plane_gap = 0;                // m, the node's distance from the triangle's plane
                                         //   after the solve: the depth the next step finds
    uint32_t nodes_a[3] = {0, 0, 0};     // features: body_a's nodes (a face's three, an edge's two)
    double weights_a[3] = {0, 0, 0};     //   and their weights (summing to 1)
    ContactKind kind = ContactKind::node_face;
    uint8_t end = 0;                     // face_shape: which of the shape's points under the face
                                         //   (face_shape.h, points_under); edge_edge against a
                                         //   box: which of its edges (0 against a hull)
    bool sliding = false;
    bool gentle = false;                 // the offset is an overlap of bodies as they were
                                         //   added: let out at 1e-3 of an edge a step

    bool active() const { return lambda_n > 0.0; }  // carries force
    bool feature() const { return kind != ContactKind::node_face; }
    // How many nodes a weighted point of a side sums: two on an edge, three on a triangle.
    int side_nodes() const { return kind == ContactKind::edge_edge ? 2 : 3; }
    // How deep the solve left the pair (m, >= 0): a kept overlap or the solver's residual,
    // along the normal or from the triangle's plane, whichever is deeper (plane_gap).
    double kept_offset() const { return std::max(0.0, -std::min(gap_after, plane_gap)); }
};

// The key of an unordered pair of bodies (world slots): the lower slot << 32 | the higher.
inline uint64_t body_pair_key(uint32_t a, uint32_t b) { return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a; }

// A run of a contact list's records of one pair of bodies: from records[first] to the next
// run's first (or the list's end), nodes of body_a (a slot) against body_b. A list ordered by
// node, then by the other body, comes in such runs: the solve's grouping works on them.
struct RecordRun {
    uint32_t first = 0, body_a = 0, body_b = 0;
};

// The contact list's order: body_a, node, body_b (a feature's node, kFeatureNode, after all).
inline bool list_order(const ContactRecord& x, const ContactRecord& y) {
    return x.body_a != y.body_a ? x.body_a < y.body_a : x.node != y.node ? x.node < y.node : x.body_b < y.body_b;
}

// The runs of records[0 .. count), appended to runs (first: the index within records).
inline void append_runs(const ContactRecord* records, uint32_t count, std::vector<RecordRun>& runs) {
    const std::size_t start = runs.size();
    for (uint32_t j = 0; j < count; ++j)
        if (runs.size() == start || runs.back().body_a != records[j].body_a || runs.back().body_b != records[j].body_b)
            runs.push_back(RecordRun{j, records[j].body_a, records[j].body_b});
}

}  // namespace lfem
