// Which sharp edges of two bodies may cross (contact/edge_edge.h), and which folds may bend
// under another's sharp edges, before the candidates of the
// node pass run out (contact_candidates.h): made after each of its searches, from the bodies
// where the search saw them, and held while its budgets hold. Two edges are a candidate pair
// when their boxes, grown by both bodies' budgets and the detection's band, overlap: an edge
// stays within its box grown by its body's budget (its nodes move at most that far per axis),
// so no pair left out can come within the band of crossing before the next search. The pairs
// of bodies are the search's (the bodies whose faces each body's nodes may reach), a
// self-contact body with itself among them (each pair of its edges once, none that share a
// node).
#pragma once

#include <cstdint>
#include <vector>

#include "common/box.h"
#include "common/thread_pool.h"
#include "contact/contact_body.h"
#include "contact/contact_candidates.h"

namespace lfem {

// Sharp edge `edge_a` of body `a` against sharp edge `edge_b` of body `b` (indices into the
// contact list's bodies and their edges, contact_body.h edge_of).
struct EdgePair {
    uint32_t a = 0, b = 0;
    uint32_t edge_a = 0, edge_b = 0;
    uint32_t line_a = 0, line_b = 0;  // the edges' places in EdgeCandidates::edges_used
};

// A mark per edge of a body, reset by counting: which edges edges_of has put out this time.
struct EdgeMarks {
    std::vector<uint32_t> mark;
    uint32_t generation = 0;
};

struct EdgeCandidates {
    uint64_t search = 0;           // the search (ContactCandidates::searches) they were made after
    std::vector<EdgePair> pairs;   // by body pair, then a's edge, then b's
    // The edges the pairs name, each once (body << 32 | edge, as the pairs first name them),
    // and per sub-step their lines at x* side by side (6 each: first node, second less first),
    // which the pairs read instead of the bodies' scattered nodes.
    std::vector<uint64_t> edges_used;
    std::vector<double> lines;
    // The folds watched against sharp edges: group g's are those of body fold_body near the
    // sharp edges group_sharp[sharp_begin .. sharp_end) of body sharp_body (bodies of the
    // contact list). Each sub-step a fold bent outward (fold_bends_out) is tested against its
    // group's sharp edges, the rest (most: faces lying flat on each other) are passed over.
    struct FoldGroup {
        uint32_t sharp_body, fold_body, sharp_begin, sharp_end;
    };
    struct WatchedFold {
        uint32_t group, fold;
        uint32_t corners[4];  // fold_corners, gathered once
    };
    std::vector<FoldGroup> fold_groups;
    std::vector<uint32_t> group_sharp;
    std::vector<WatchedFold> watched;  // by fold body, fold, group
    // Scratch.
    struct EdgeBox {
        Aabb box;
        uint32_t edge;
    };
    std::vector<uint64_t> body_pairs;
    std::vector<uint32_t> listed_bodies;  // the bodies with few edges, boxed and sorted once per
    std::vector<EdgeBox> listed;          //   search: their edges, each body's from listed_begin
    std::vector<uint32_t> listed_begin;   //   (UINT32_MAX: a body searched through its tree)
    std::vector<uint32_t> edge_base, edge_line;  // an edge's line: edge_line[edge_base[body] + edge]
    EdgeMarks marks;
    // The candidates of a run of body pairs, made on one thread (fixed runs: the same result on
    // any number of threads), then joined in order.
    struct Chunk {
        std::vector<EdgePair> pairs;
        std::vector<FoldGroup> fold_groups;
        std::vector<uint32_t> group_sharp;
        std::vector<WatchedFold> watched;
        EdgeMarks marks;
        std::vector<uint32_t> triangles, edges;
        std::vector<EdgeBox> sharp_lo, folds_lo, sharp_hi, folds_hi, grown;
    };
    std::vector<Chunk> chunks;
};

// The pairs and the watched folds again when the candidates were searched since they were
// made (else nothing to do), on the pool.
void update_edge_pairs(const std::vector<ContactBody>& bodies, const ContactCandidates& c, EdgeCandidates& e,
                       ThreadPool* pool);

// The edges (sharp and folds) of b's triangles `triangles`, each once, in the order the
// triangles name them, into out (EdgeMarks: scratch).
void edges_of(const ContactBody& b, const std::vector<uint32_t>& triangles, EdgeMarks& marks, std::vector<uint32_t>& out);

// Whether edges ea and eb of one body (self-contact) are tested: once (the first as a's), and
// only when they share no node.
bool own_edges_may_cross(const ContactBody& b, uint32_t ea, uint32_t eb);

// The used edges' lines at this sub-step's x* (EdgeCandidates::lines).
void update_edge_lines(const std::vector<ContactBody>& bodies, EdgeCandidates& e);

}  // namespace lfem
