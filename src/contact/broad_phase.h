// The broad phase of contact detection: a spatial hash of axis-aligned boxes (common/box.h)
// that finds the pairs of bodies whose boxes overlap in O(bodies) (a counting sort into a
// table of buckets, no pairs of everything). Within a pair of bodies, the triangles come from
// each body's tree (triangle_bvh.h).
#pragma once

#include <cstdint>
#include <vector>

#include "common/box.h"

namespace lfem {

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

}  // namespace lfem
