// Contact detection between the step-start configuration x^n and the predicted one x*: a node
// of one body against the boundary triangles of another (eqs. 5 and 6) and against rigid
// shapes, both passes (nodes of A into B and nodes of B into A) in one list. The candidates of
// each node come from contact_candidates.h (searched for only now and then); every sub-step
// tests them exactly.
#pragma once

#include <vector>

#include "common/thread_pool.h"
#include "contact/contact_body.h"
#include "contact/contact_candidates.h"
#include "contact/contact_record.h"
#include "contact/node_face.h"
#include "common/profile.h"

namespace lfem {

// Nodes found inside another body (or a shape), or with self-contact their own, during the
// run, to be pushed out: how many, and the slot of the body of the last one (in list order).
struct FallenIn {
    uint64_t nodes = 0;
    uint32_t last_slot = UINT32_MAX;
    void add(const FallenIn& o) {
        nodes += o.nodes;
        if (o.nodes) last_slot = o.last_slot;
    }
};

// One block of consecutive candidate nodes (cut into blocks of a fixed size): its own records
// and scratch, so that blocks run in parallel on the pool and their records are joined in block
// order, the list's order (body, node, other body). Kept between steps, so the vectors are
// reused and not allocated again.
struct DetectionBlock {
    std::vector<ContactRecord> records, merged;  // merged: rebuilt with the shape contacts
    // Shape pass: where each of the block's nodes' records start (+1 at the end) and the gap
    // of each record.
    std::vector<uint32_t> record_begin;
    std::vector<double> record_gap;
    std::vector<uint8_t> record_fallen;       // shape pass: the record is of a node fallen in
    std::vector<uint32_t> touched;            // bodies with a candidate for the current node
    std::vector<NodeCandidate> best;          // per touched body
    std::vector<NodeCandidate> inside;        // per touched deformable body: the face of a node
                                              //   that may be inside it
    std::vector<uint32_t> inside_of;          // per touched body: its entry of inside, or none
    std::vector<NodeCandidate> deep;          // per touched body met for the first time
    std::vector<uint32_t> deep_of;            // per touched body: its entry of deep, or none
    std::vector<const ContactRecord*> last;   // per touched body: the pair's last record
    std::vector<NodeCandidate> accepted;      // faces that would take the node, no better than the
                                              //   best, turned from it (NodeSlots), and the bests
                                              //   they were found beside
    std::vector<uint32_t> accepted_begin;     // per touched body: its first in accepted
    std::vector<RecordRun> runs;              // of its records (first: within the block), made by the join
    ShapeQueryCounts counts;                  // the profile's counts, added in block order
    FallenIn fallen;                          // of the block's records
};

// Skipping faces a node cannot meet yet (detect_node_triangle.cpp): how far each candidate node
// and each moving candidate face has moved since the search (its odometer: the sum of the
// moves of its step-start positions, a face's the largest of its vertices'), and for each
// candidate pair turned away as lying outside the face, by how much and since when.
struct NodeTrack {
    Vec3 last_start = Vec3::Zero();  // x^n at the last sub-step
    double odometer = 0;             // m
};
struct FaceTrack {
    double last_start[9] = {};  // its vertices' x^n at the last sub-step
    double odometer = 0;        // m
};
struct PairSkip {
    double margin = 0;     // barycentric weight short of the face's edge tolerance; 0: test
    double height = 0;     // smallest height of the triangle tested (m)
    double node_mark = 0;  // the node's odometer then, less its move in that sub-step
    double face_mark = 0;  // the face's, alike
};

struct DetectionScratch {
    ContactCandidates candidates;
    std::vector<NodeTrack> node_tracks;  // per candidate node
    std::vector<FaceTrack> face_tracks;  // per moving candidate face
    std::vector<PairSkip> pair_skips;    // per candidate pair (candidates.triangles)
    bool tracks_ready = false;           // the three above belong to the candidates (false
                                         // while they are being made: an allocation may fail)
    std::vector<Vec3> slave_normals;    // per candidate node: outward unit normal at x*
    std::vector<uint8_t> normal_ready;  // per candidate node: its normal is computed
    std::vector<FaceStep> faces;        // per moving candidate face (candidates.faces): this sub-step's
    std::vector<DetectionBlock> blocks; // only the first ones may be in use (never shrinks)
    std::vector<std::size_t> block_begin;  // where each block's records go in the joined list
};

// Fills `out` with one constraint per (node, other body): the boundary triangle the node
// crossed or lies against, with its normal at x*, the barycentric weights of the contact point
// and the target gap (a kept overlap). `previous` is the last step's list (same order: body,
// node, other body), which says which overlaps are being recovered, and whose multipliers
// warm-start the pairs found again (the same node and body: a resting contact starts solved);
// max_offset is its deepest_kept_offset.
// With scan_overlaps (the first step after bodies were added) nodes found up to half an edge
// inside another body are taken as overlaps to be removed gradually. Time and counts of the
// candidate search (broad phase), the node-triangle tests (narrow phase) and the rigid-shape
// queries are added to `profile`. The tests run in blocks on the pool when one is given; the
// list and the counts are bitwise the same for any number of threads, and whether or not the
// candidates were searched for again. `runs` gets the list's runs of one pair of bodies (found
// by the threads that copy the blocks' records into the list). Returns the nodes found fallen
// in (a warning).
FallenIn detect_node_triangle(const std::vector<ContactBody>& bodies,
                          const std::vector<ContactRecord>& previous, double max_offset, bool scan_overlaps,
                          DetectionScratch& scratch, std::vector<ContactRecord>& out, std::vector<RecordRun>& runs,
                          Profile& profile, ThreadPool* pool = nullptr);

// The deepest overlap a list leaves to be recovered (the largest ContactRecord::kept_offset, 0
// for none): how much deeper than the capture band the next detection must look.
double deepest_kept_offset(const std::vector<ContactRecord>& list);

}  // namespace lfem
