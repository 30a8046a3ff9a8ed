#include "contact/broad_phase.h"

#include <algorithm>
#include <cmath>

#include "contact/detection_tolerances.h"

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


namespace {

Aabb empty_box() {
    Aabb box;
    for (int k = 0; k < 3; ++k) box.lo[k] = HUGE_VAL, box.hi[k] = -HUGE_VAL;
    return box;
}

void join(Aabb& box, const Aabb& other) {
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], other.lo[k]), box.hi[k] = std::max(box.hi[k], other.hi[k]);
}

// Triangle boxes over the whole step, grown by the capture band and the deepest overlap being
// recovered; the node paths' boxes. Body by body on the pool, each body writing its own range
// of triangle_box (from the prefix sums of the triangle counts) and its own entries.
void compute_boxes(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                   BroadPhase& s, ThreadPool* pool) {
    const uint32_t nb = uint32_t(bodies.size());
    s.body_box.resize(nb);
    s.slave_box.resize(nb);
    s.triangle_begin.resize(nb + 1);
    s.triangle_begin[0] = 0;
    for (uint32_t bi = 0; bi < nb; ++bi) s.triangle_begin[bi + 1] = s.triangle_begin[bi] + bodies[bi].triangle_count;
    s.triangle_box.resize(s.triangle_begin[nb]);
    s.body_extent.assign(nb, -1.0);
    parallel_for(pool, nb, [&](uint32_t bi) {
        const ContactBody& b = bodies[bi];
        const double grow = std::max(kCaptureBand * b.edge_length + max_offset,
                                     scan_overlaps ? kInitialDepth * b.edge_length : 0.0);
        s.body_box[bi] = empty_box();
        for (uint32_t t = 0; t < b.triangle_count; ++t) {
            Aabb box = empty_box();
            for (int v = 0; v < 3; ++v) {
                const uint32_t i = b.triangles[3 * t + v];
                for (int k = 0; k < 3; ++k) {
                    const double x0 = b.x_start[3 * i + k], x1 = b.x[3 * i + k];
                    box.lo[k] = std::min({box.lo[k], x0, x1});
                    box.hi[k] = std::max({box.hi[k], x0, x1});
                }
            }
            for (int k = 0; k < 3; ++k) box.lo[k] -= grow, box.hi[k] += grow;
            s.triangle_box[s.triangle_begin[bi] + t] = box;
            join(s.body_box[bi], box);
        }
        s.slave_box[bi] = empty_box();
        for (uint32_t j = 0; j < b.node_count; ++j) {
            const uint32_t p = b.nodes[j];
            for (int k = 0; k < 3; ++k) {
                const double x0 = b.x_start[3 * p + k], x1 = b.x[3 * p + k];
                s.slave_box[bi].lo[k] = std::min({s.slave_box[bi].lo[k], x0, x1});
                s.slave_box[bi].hi[k] = std::max({s.slave_box[bi].hi[k], x0, x1});
            }
        }
        if (b.triangle_count > 0) {
            const Aabb& box = s.body_box[bi];
            const double extent = std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
            if (std::isfinite(extent)) s.body_extent[bi] = extent;
        }
    });
}

// Pairs of bodies through a hash of the body boxes (cells of the mean body size; a floor much
// larger than the bodies on it is kept aside and tested directly): each body's partners, and
// whether its nodes are tested at all.
void find_partners(const std::vector<ContactBody>& bodies, BroadPhase& s) {
    const uint32_t nb = uint32_t(bodies.size());
    double extent_sum = 0.0;
    uint32_t extent_count = 0;
    for (uint32_t bi = 0; bi < nb; ++bi)
        if (s.body_extent[bi] >= 0.0) extent_sum += s.body_extent[bi], ++extent_count;
    s.body_grid.build(s.body_box, extent_count > 0 && extent_sum > 0.0 ? extent_sum / extent_count : 1.0);
    s.partner_begin.assign(1, 0);
    s.partners.clear();
    s.reached_by.clear();
    s.shape_bodies.clear();
    s.tested.assign(nb, 0);
    for (uint32_t bi = 0; bi < nb; ++bi)
        if (bodies[bi].shape_count > 0) s.shape_bodies.push_back(bi);
    for (uint32_t ai = 0; ai < nb; ++ai) {
        const ContactBody& a = bodies[ai];
        if (a.node_count > 0) {
            s.candidates.clear();
            s.body_grid.query(s.slave_box[ai], s.candidates);
            for (uint32_t bi : s.candidates)
                if (bi != ai && bodies[bi].triangle_count > 0 && bodies_may_touch(a, bodies[bi])) {
                    s.partners.push_back(bi);
                    s.reached_by.push_back(uint64_t(bi) << 32 | ai);
                }
            bool shape_partner = false;
            for (uint32_t bi : s.shape_bodies)
                shape_partner = shape_partner || (bi != ai && bodies_may_touch(a, bodies[bi]));
            s.tested[ai] = s.partners.size() > s.partner_begin.back() || shape_partner;
        }
        s.partner_begin.push_back(uint32_t(s.partners.size()));
    }
}

// Which triangles enter the hash: those of a reached body whose box overlaps the path box of a
// body reaching it (or, when many bodies reach it, of all of them joined).
void hash_reachable_triangles(const std::vector<ContactBody>& bodies, BroadPhase& s) {
    std::sort(s.reached_by.begin(), s.reached_by.end());  // by reached body, then reaching
    const std::vector<uint64_t>& reached = s.reached_by;
    const auto reaching = [&](std::size_t q) { return uint32_t(reached[q]); };
    s.boxes.clear();
    s.box_body.clear();
    s.box_triangle.clear();
    double cell = 0.0;
    std::size_t first_triangle = 0;  // of body bi in triangle_box
    std::size_t r = 0;
    for (uint32_t bi = 0; bi < bodies.size(); ++bi) {
        const ContactBody& b = bodies[bi];
        const std::size_t r_begin = r;
        while (r < reached.size() && uint32_t(reached[r] >> 32) == bi) ++r;
        if (r > r_begin) {
            constexpr std::size_t kMaxSeparateBoxes = 8;
            Aabb joined = empty_box();
            for (std::size_t q = r_begin; q < r; ++q) join(joined, s.slave_box[reaching(q)]);
            for (uint32_t t = 0; t < b.triangle_count; ++t) {
                const Aabb& box = s.triangle_box[first_triangle + t];
                bool near = false;
                if (r - r_begin > kMaxSeparateBoxes) near = overlaps(box, joined);
                else
                    for (std::size_t q = r_begin; q < r && !near; ++q) near = overlaps(box, s.slave_box[reaching(q)]);
                if (!near) continue;
                s.boxes.push_back(box);
                s.box_body.push_back(bi);
                s.box_triangle.push_back(t);
                cell = std::max(cell, b.edge_length);
            }
        }
        first_triangle += b.triangle_count;
    }
    if (!s.boxes.empty()) s.grid.build(s.boxes, 2.0 * cell);
}

}  // namespace

void run_broad_phase(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                     BroadPhase& out, ThreadPool* pool) {
    compute_boxes(bodies, max_offset, scan_overlaps, out, pool);
    find_partners(bodies, out);
    hash_reachable_triangles(bodies, out);
}

}  // namespace lfem
