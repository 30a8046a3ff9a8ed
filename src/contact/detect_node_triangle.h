// Contact detection between the step-start configuration x^n and the predicted one x*: a node
// of one body against the boundary triangles of another (eqs. 5 and 6), both passes (nodes of A
// into B and nodes of B into A) in one list.
#pragma once

#include <vector>

#include "contact/broad_phase.h"
#include "contact/contact_body.h"
#include "contact/contact_record.h"
#include "lfem.h"

namespace lfem {

struct DetectionScratch {
    // Body level, to leave out what cannot touch: per body the joined boxes of its triangles
    // and of its slave nodes' paths, the bodies whose triangles each body's slave nodes may
    // reach (partner_begin: where each body's list starts, +1 at the end), and per body whether
    // its nodes are tested at all; reached_by: (reached body << 32 | reaching body).
    std::vector<Aabb> triangle_box, body_box, slave_box;
    std::vector<uint32_t> partner_begin, partners, shape_bodies;
    std::vector<uint64_t> reached_by;
    std::vector<uint8_t> tested;
    BroadPhase body_grid;
    std::vector<uint32_t> touched;  // bodies with a candidate for the current node
    std::vector<Aabb> boxes;
    std::vector<uint32_t> box_body, box_triangle;  // which body and triangle a box belongs to
    std::vector<uint32_t> candidates;
    std::vector<double> node_normals;  // 3 per node of the body being tested
    // Shape pass, used only when some body has rigid shapes: 3 per slave node (all bodies),
    // where each slave node's records start (+1 at the end), the gap of each record, and the
    // records rebuilt with the shape contacts.
    std::vector<double> slave_normals;
    std::vector<uint32_t> record_begin;
    std::vector<double> record_gap;
    std::vector<ContactRecord> merged;
    BroadPhase grid;
};

// Fills `out` with one constraint per (node, other body): the boundary triangle the node
// crossed or lies against, with its normal at x*, the barycentric weights of the contact point
// and the target gap (a kept overlap). `previous` is the last step's list (same order: body,
// node, other body), which says which overlaps are being recovered. With scan_overlaps (the
// first step after bodies were added) nodes found up to half an edge inside another body are
// taken as overlaps to be removed gradually. Time and counts of the broad phase, the
// node-triangle tests and the rigid-shape queries are added to `profile`.
void detect_node_triangle(const std::vector<ContactBody>& bodies,
                          const std::vector<ContactRecord>& previous, bool scan_overlaps,
                          DetectionScratch& scratch, std::vector<ContactRecord>& out,
                          lfem_profile& profile);

}  // namespace lfem
