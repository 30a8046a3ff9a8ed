// Contact detection between the step-start configuration x^n and the predicted one x*: a node
// of one body against the boundary triangles of another (eqs. 5 and 6), both passes (nodes of A
// into B and nodes of B into A) in one list.
#pragma once

#include <vector>

#include "common/thread_pool.h"
#include "contact/broad_phase.h"
#include "contact/contact_body.h"
#include "contact/contact_record.h"
#include "fem/tet_element.h"
#include "lfem.h"

namespace lfem {

// The best face (or rigid shape) of another body found so far for one slave node.
struct NodeCandidate {
    bool found = false;
    uint32_t triangle = 0;
    uint32_t shape = UINT32_MAX;  // a rigid shape instead of a triangle
    Vec3 point_start = Vec3::Zero(), point_end = Vec3::Zero();
    double gap = 0;        // g* at the end of the step (m)
    double start_gap = 0;  // g^n
    double w[3] = {0, 0, 0};
    Vec3 normal = Vec3::Zero();
};

// One block of consecutive slave nodes (the tested bodies' slave nodes in body order, cut into
// blocks of a fixed size): its own records and scratch, so that blocks run in parallel on the
// pool and their records are joined in block order, the list's order (body, node, other body).
// Kept between steps, so the vectors are reused and not allocated again.
struct DetectionBlock {
    std::vector<ContactRecord> records, merged;  // merged: rebuilt with the shape contacts
    // Shape pass: where each of the block's nodes' records start (+1 at the end) and the gap
    // of each record.
    std::vector<uint32_t> record_begin;
    std::vector<double> record_gap;
    std::vector<uint32_t> touched;            // bodies with a candidate for the current node
    std::vector<NodeCandidate> best, deep;    // per touched body
    std::vector<const ContactRecord*> last;   // per touched body: the pair's last record
    std::vector<uint32_t> candidates, crossing;  // hash answers: the node's path, a segment
    uint64_t shape_tests = 0, ccd_queries = 0;   // the profile's counts, added in block order
};

struct DetectionScratch {
    BroadPhase broad;
    // Narrow phase: per body where its slave nodes start in the sequence of all tested bodies'
    // slave nodes and where its nodes start in node_normals (+1 at the end, both), 3 per node
    // of the tested bodies (sums of the triangle normals around it; only the boundary nodes'
    // are set), 3 per slave node of the sequence (outward unit normals at x*), and the blocks
    // (only the first ones may be in use: the vector never shrinks, so a block's vectors keep
    // their capacity).
    std::vector<uint32_t> slave_begin, node_begin;
    std::vector<double> node_normals, slave_normals;
    std::vector<DetectionBlock> blocks;
};

// Fills `out` with one constraint per (node, other body): the boundary triangle the node
// crossed or lies against, with its normal at x*, the barycentric weights of the contact point
// and the target gap (a kept overlap). `previous` is the last step's list (same order: body,
// node, other body), which says which overlaps are being recovered, and whose multipliers
// warm-start the pairs found again (the same node and body: a resting contact starts solved). With scan_overlaps (the
// first step after bodies were added) nodes found up to half an edge inside another body are
// taken as overlaps to be removed gradually. Time and counts of the broad phase, the
// node-triangle tests and the rigid-shape queries are added to `profile`. The node tests run
// in blocks on the pool when one is given; the list and the counts are bitwise the same for
// any number of threads.
void detect_node_triangle(const std::vector<ContactBody>& bodies,
                          const std::vector<ContactRecord>& previous, bool scan_overlaps,
                          DetectionScratch& scratch, std::vector<ContactRecord>& out,
                          lfem_profile& profile, ThreadPool* pool = nullptr);

}  // namespace lfem
