// Contact candidates: which triangles and rigid shapes each slave node could meet, searched for
// only now and then, as the explicit crash codes do (the bucket sort every N cycles of LS-DYNA
// and OpenRadioss, with a margin for the motion in between). A search gives every moving body a
// budget B of motion and takes as candidates of a node every triangle whose box, grown by the
// bodies' budgets and by the detection's own growth, reaches the node. While no body has moved
// further than its budget from where the search saw it (checked every sub-step over its surface
// nodes) the candidates hold every triangle the exact test of a sub-step could accept, so the
// sub-step tests only them, in the order a full search would give: the contact list is bitwise
// what a search at every sub-step would find. When a budget runs out, or a body's geometry
// changes, the next sub-step searches again.
#pragma once

#include <cstdint>
#include <vector>

#include "common/thread_pool.h"
#include "contact/broad_phase.h"
#include "contact/contact_body.h"
#include "contact/triangle_bvh.h"

namespace lfem {

struct ContactCandidates {
    bool valid = false;
    uint64_t searches = 0;      // how often a search ran
    double offset_allowed = 0;  // the deepest recovered overlap the search allowed for (m)
    bool scanned = false;       // the search allowed for initial overlaps
    // Per body of the contact list the search saw (ContactBodies order):
    std::vector<uint64_t> identity;
    std::vector<double> budget;          // B (m, per axis): how far its nodes may move
    std::vector<double> moved;           // scratch: how far it has moved since (per sub-step)
    std::vector<uint32_t> surface_begin; // where its surface nodes start in x_search (+1 at the end)
    std::vector<double> x_search;        // 3 per surface node: where the search saw them
    std::vector<TriangleBvh> bvh;        // moving bodies' trees (a static body brings its own)
    // The slave nodes with candidates, in body and node order: node `node[i]` of body
    // `body[i]`, its triangles (other body << 32 | triangle, ascending) and rigid shapes
    // (shape body << 32 | shape, ascending).
    std::vector<uint32_t> body, node;
    std::vector<uint32_t> triangle_begin, shape_begin;  // +1 at the end
    std::vector<uint64_t> triangles, shapes;
    std::vector<Aabb> static_box;  // per candidate triangle of a static body: its box (it never moves)
    // The moving bodies' candidate triangles, each once (body << 32 | triangle, ascending):
    // the narrow phase makes each one's box and normals once per sub-step (node_face.h,
    // FaceStep), not once per node that may meet it. face_index: per candidate triangle, its
    // place in `faces` (UINT32_MAX for a static body's).
    std::vector<uint64_t> faces;
    std::vector<uint32_t> face_index;
    // Scratch of the search: body boxes, the body hash, pairs.
    std::vector<Aabb> body_box, slave_box;
    std::vector<uint32_t> partner_begin, partners, shape_bodies, found;
    SpatialHash body_grid;
    std::vector<std::vector<uint32_t>> block_body, block_node, block_triangle_count, block_shape_count;
    std::vector<std::vector<uint64_t>> block_triangles, block_shapes;
    std::vector<std::vector<Aabb>> block_static_box;

    const TriangleBvh& tree_of(const std::vector<ContactBody>& bodies, uint32_t b) const {
        return bodies[b].static_bvh ? *bodies[b].static_bvh : bvh[b];
    }
};

// The box of triangle t of body b over the step (its nodes at x_start and x*), grown by `grow`.
Aabb triangle_step_box(const ContactBody& b, uint32_t t, double grow);

// Whether the candidates still hold for the bodies at this sub-step: the same bodies, the same
// growth (candidates_may_hold), and each within its budget: measure_move of every body (each
// writes only its own c.moved, so the bodies can be measured side by side on the pool, with
// other work of the sub-step in the same round), then moves_within_budgets.
bool candidates_may_hold(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                         const ContactCandidates& c);
void measure_move(const std::vector<ContactBody>& bodies, uint32_t bi, ContactCandidates& c);
bool moves_within_budgets(const ContactCandidates& c);

// A new search from the bodies as they are (x_start to x* of this sub-step).
void search_candidates(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                       ContactCandidates& c, ThreadPool* pool);

}  // namespace lfem
