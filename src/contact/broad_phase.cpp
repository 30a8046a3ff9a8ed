#include "contact/broad_phase.h"

#include <algorithm>
#include <cmath>


namespace lfem {
namespace {

// An item covering more cells than this (a huge static triangle under small bodies) is kept
// in a short list and tested against every query instead of filling the grid.
constexpr int64_t kMaxCellsPerItem = 64;

uint64_t pack_cell(int64_t i, int64_t j, int64_t k) {
    // 21 bits per axis (two's complement wraps): cells far apart may share a key, which only
    // adds candidates that the box test then rejects.
    const uint64_t m = (1ull << 21) - 1;
    return (uint64_t(i) & m) | ((uint64_t(j) & m) << 21) | ((uint64_t(k) & m) << 42);
}

}  // namespace

uint64_t SpatialHash::bucket_of(uint64_t cell) const {
    uint64_t h = cell * 0x9E3779B97F4A7C15ull;  // Fibonacci hashing
    h ^= h >> 29;
    return h & (uint64_t(bucket_start_.size()) - 2);  // buckets: a power of two
}

bool SpatialHash::cell_range(const Aabb& b, int64_t lo[3], int64_t hi[3]) const {
    // Cell coordinates are formed in double and checked before conversion: a box with NaN,
    // inverted or astronomically far corners (a state about to be caught as a blow-up) is
    // handled as oversized instead of overflowing the integer cell range.
    constexpr double kMaxCoordinate = 1e15;  // far inside int64_t, products included
    int64_t cells = 1;
    for (int k = 0; k < 3; ++k) {
        const double l = std::floor(b.lo[k] / cell_size_), h = std::floor(b.hi[k] / cell_size_);
        if (!(l <= h) || !(-kMaxCoordinate < l) || !(h < kMaxCoordinate)) return false;
        lo[k] = int64_t(l);
        hi[k] = int64_t(h);
        cells *= hi[k] - lo[k] + 1;
        if (cells > kMaxCellsPerItem) return false;
    }
    return true;
}

void SpatialHash::build(const std::vector<Aabb>& boxes, double cell_size) {
    boxes_ = &boxes;
    cell_size_ = cell_size;
    oversized_.clear();
    // First pass: how many cell entries.
    std::size_t count = 0;
    int64_t lo[3], hi[3];
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        if (cell_range(boxes[i], lo, hi))
            count += std::size_t((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1));
        else
            oversized_.push_back(i);
    }
    std::size_t buckets = 1;
    while (buckets < 2 * count + 1) buckets *= 2;
    bucket_start_.assign(buckets + 1, 0);
    std::vector<Entry> unsorted;
    unsorted.reserve(count);
    for (uint32_t i = 0; i < boxes.size(); ++i) {
        if (!cell_range(boxes[i], lo, hi)) continue;
        for (int64_t a = lo[0]; a <= hi[0]; ++a)
            for (int64_t b = lo[1]; b <= hi[1]; ++b)
                for (int64_t c = lo[2]; c <= hi[2]; ++c) {
                    const uint64_t cell = pack_cell(a, b, c);
                    unsorted.push_back({cell, i});
                    ++bucket_start_[bucket_of(cell) + 1];
                }
    }
    // Counting sort by bucket (stable: items stay in id order within a bucket).
    for (std::size_t b = 0; b < buckets; ++b) bucket_start_[b + 1] += bucket_start_[b];
    entries_.resize(unsorted.size());
    std::vector<uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
    for (const Entry& e : unsorted) entries_[fill[bucket_of(e.cell)]++] = e;
}

void SpatialHash::query(const Aabb& box, std::vector<uint32_t>& out) const {
    const std::size_t first = out.size();
    int64_t lo[3], hi[3];
    const bool small = cell_range(box, lo, hi);
    if (small && !entries_.empty()) {
        for (int64_t a = lo[0]; a <= hi[0]; ++a)
            for (int64_t b = lo[1]; b <= hi[1]; ++b)
                for (int64_t c = lo[2]; c <= hi[2]; ++c) {
                    const uint64_t cell = pack_cell(a, b, c);
                    const uint64_t bucket = bucket_of(cell);
                    for (uint32_t e = bucket_start_[bucket]; e < bucket_start_[bucket + 1]; ++e)
                        if (entries_[e].cell == cell && overlaps(box, (*boxes_)[entries_[e].item]))
                            out.push_back(entries_[e].item);
                }
    } else if (!small) {
        // A query box larger than the grid allows (a very fast node): test every item. Rare,
        // and bounded by the item count.
        for (uint32_t i = 0; i < boxes_->size(); ++i)
            if (overlaps(box, (*boxes_)[i])) out.push_back(i);
    }
    if (small)
        for (uint32_t i : oversized_)
            if (overlaps(box, (*boxes_)[i])) out.push_back(i);
    std::sort(out.begin() + first, out.end());
    out.erase(std::unique(out.begin() + first, out.end()), out.end());
}


}  // namespace lfem
