// Broad phase of contact detection, at two levels. Bodies first: a body's slave nodes are
// tested only against bodies whose triangles their paths may reach (boxes overlap, filters
// allow). Then triangles: only the triangles near some such node path enter a spatial hash of
// their swept bounding boxes, which the narrow phase asks per node. Both cost O(triangles +
// nodes): counting sorts into tables of buckets, no pairs of everything, no tree.
#pragma once

#include <cstdint>
#include <vector>

#include "common/thread_pool.h"
#include "contact/contact_body.h"

namespace lfem {

struct Aabb {
    double lo[3], hi[3];
};

// Whether two boxes overlap (touching counts); a box with a NaN corner overlaps nothing.
inline bool overlaps(const Aabb& a, const Aabb& b) {
    for (int k = 0; k < 3; ++k)
        if (!(a.hi[k] >= b.lo[k] && b.hi[k] >= a.lo[k])) return false;
    return true;
}

// A spatial hash of boxes in a grid of cubic cells.
class SpatialHash {
public:
    // Index boxes (one per item, ids 0..n-1) in a grid of cubic cells of the given size.
    void build(const std::vector<Aabb>& boxes, double cell_size);
    // Ids of the items whose box overlaps `box`, appended to out (sorted, no repeats).
    void query(const Aabb& box, std::vector<uint32_t>& out) const;

private:
    struct Entry {
        uint64_t cell;
        uint32_t item;
    };
    uint64_t bucket_of(uint64_t cell) const;
    bool cell_range(const Aabb& b, int64_t lo[3], int64_t hi[3]) const;

    double cell_size_ = 1.0;
    const std::vector<Aabb>* boxes_ = nullptr;
    std::vector<uint32_t> bucket_start_;  // size buckets + 1
    std::vector<Entry> entries_;          // sorted by bucket
    std::vector<uint32_t> oversized_;     // items spanning too many cells: checked directly
};

// What the broad phase leaves for the narrow phase (kept between steps: the vectors are reused).
struct BroadPhase {
    // Per body: the joined boxes of its triangles over the step (body_box) and of its slave
    // nodes' paths (slave_box); the bodies whose triangles its slave nodes may reach
    // (partners[partner_begin[b] .. partner_begin[b+1])); whether its nodes are tested at all;
    // the bodies that have rigid shapes.
    std::vector<Aabb> body_box, slave_box;
    std::vector<uint32_t> partner_begin, partners, shape_bodies;
    std::vector<uint8_t> tested;
    // The hashed triangles: their boxes, and which body and triangle each box belongs to.
    std::vector<Aabb> boxes;
    std::vector<uint32_t> box_body, box_triangle;
    SpatialHash grid;
    // Scratch: every triangle's box (triangle_begin[b]: body b's first), the bodies' extents,
    // (reached body << 32 | reaching body) pairs, the body hash and its answers.
    std::vector<Aabb> triangle_box;
    std::vector<uint32_t> triangle_begin;
    std::vector<double> body_extent;
    std::vector<uint64_t> reached_by;
    SpatialHash body_grid;
    std::vector<uint32_t> candidates;
};

// Both levels for the bodies of a step. Triangle boxes cover the triangle's motion over the
// step, grown by the capture band and by max_offset (the deepest overlap being recovered),
// or half an edge with scan_overlaps (the first step after bodies were added). Exact: a
// triangle left out has a box that overlaps no node path that could test it; the cost follows
// the contact region, not the whole boundary (two long bars meeting end to end hash their end
// faces only; a body far from everything is not looked at). The boxes are made body by body
// on the pool; the result is the same for any thread count.
void run_broad_phase(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                     BroadPhase& out, ThreadPool* pool);

}  // namespace lfem
