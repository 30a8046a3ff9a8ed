#include "contact/contact_candidates.h"

#include <algorithm>
#include <cmath>

#include "contact/detection_tolerances.h"
#include "contact/rigid_shape.h"

namespace lfem {
namespace {

// A moving body's budget: 8 times its fastest surface node's motion over the searching
// sub-step (so that a body moving steadily is searched again every 8 or so sub-steps), and at
// least 0.1 of its boundary edge (so that a resting body's jitter never runs it out). The
// candidates' growth allows the recovered overlaps to double and the band to widen by 0.05 of
// an edge before a search is due again.
constexpr double kBudgetSteps = 8.0;
constexpr double kBudgetEdges = 0.1;
constexpr double kGrowthSlack = 0.05;
// Slave nodes per block of the parallel search (fixed: the same blocks for any thread count).
constexpr uint32_t kSearchBlock = 256;

Aabb point_box(const double* x, double r) {
    Aabb b;
    for (int k = 0; k < 3; ++k) b.lo[k] = x[k] - r, b.hi[k] = x[k] + r;
    return b;
}

// The largest per-axis distance of a body's surface nodes, at the start and at the end of the
// step, from `reference` (3 per surface node).
double largest_move(const ContactBody& b, const double* reference) {
    double most = 0.0;
    for (uint32_t j = 0; j < b.surface_node_count; ++j) {
        const uint32_t i = b.surface_nodes[j];
        for (int k = 0; k < 3; ++k)
            most = std::max({most, std::fabs(b.x[3 * i + k] - reference[3 * j + k]),
                             std::fabs(b.x_start[3 * i + k] - reference[3 * j + k])});
    }
    return most;
}

// Runs task(i) for i < count on the pool when the work (about `work` node visits, a few
// nanoseconds each) is worth a round of it (about a microsecond), else here: either way the
// same result.
template <class Task>
void for_bodies(ThreadPool* pool, uint32_t count, uint64_t work, const Task& task) {
    parallel_for(work >= 1024 ? pool : nullptr, count, task);
}

// Body by body: positions, budget, growth, tree and boxes of the new search.
void prepare_bodies(const std::vector<ContactBody>& bodies, double max_offset, bool scan, ContactCandidates& c,
                    ThreadPool* pool) {
    const uint32_t nb = uint32_t(bodies.size());
    std::vector<uint64_t> old_identity = c.identity;
    c.identity.resize(nb);
    c.budget.assign(nb, 0.0);
    // The overlaps being recovered may double, and grow by kGrowthSlack of the finest edge,
    // before a search is due again.
    double finest = HUGE_VAL;
    for (const ContactBody& b : bodies)
        if (b.triangle_count > 0) finest = std::min(finest, b.edge_length);
    c.offset_allowed = 2.0 * max_offset + kGrowthSlack * (std::isfinite(finest) ? finest : 0.0);
    c.scanned = scan;
    c.moved.assign(nb, 0.0);
    c.surface_begin.assign(1, 0);
    uint64_t work = 0;
    for (const ContactBody& b : bodies) {
        c.surface_begin.push_back(c.surface_begin.back() + b.surface_node_count);
        work += b.surface_node_count + b.triangle_count;
    }
    c.x_search.resize(3 * std::size_t(c.surface_begin.back()));
    c.bvh.resize(nb);
    c.body_box.resize(nb);
    c.slave_box.resize(nb);
    for_bodies(pool, nb, work, [&](uint32_t bi) {
        const ContactBody& b = bodies[bi];
        double* xs = &c.x_search[3 * std::size_t(c.surface_begin[bi])];
        for (uint32_t j = 0; j < b.surface_node_count; ++j)
            for (int k = 0; k < 3; ++k) xs[3 * j + k] = b.x[3 * b.surface_nodes[j] + k];
        if (b.moves) c.budget[bi] = std::max(kBudgetEdges * b.edge_length, kBudgetSteps * largest_move(b, xs));
        if (!b.static_bvh && b.triangle_count > 0) {
            TriangleBvh& tree = c.bvh[bi];
            if (bi < old_identity.size() && old_identity[bi] == b.identity && !tree.empty()) tree.refit(b.x, b.triangles);
            else tree.build(b.x, b.triangles, b.triangle_count);
        }
        c.identity[bi] = b.identity;
        Aabb& slaves = c.slave_box[bi];
        slaves = empty_box();
        for (uint32_t j = 0; j < b.node_count; ++j)
            for (int k = 0; k < 3; ++k) {
                slaves.lo[k] = std::min(slaves.lo[k], b.x[3 * b.nodes[j] + k]);
                slaves.hi[k] = std::max(slaves.hi[k], b.x[3 * b.nodes[j] + k]);
            }
        slaves = grown(slaves, c.budget[bi]);
        // Grown for the coarsest partner (contact lengths are at most the body's own).
        const double grow = triangle_growth(b.edge_length, c.offset_allowed, catches_deep_nodes(b, c.scanned));
        c.body_box[bi] = b.triangle_count > 0 ? grown(c.tree_of(bodies, bi).bounds(), c.budget[bi] + grow)
                                              : empty_box();
    });
}

// Pairs of bodies through a hash of their boxes (cells of the mean body size; a floor much
// larger than the bodies on it is kept aside and tested directly): the bodies whose triangles
// each body's slave nodes may reach, and the bodies with rigid shapes.
void find_partners(const std::vector<ContactBody>& bodies, ContactCandidates& c) {
    const uint32_t nb = uint32_t(bodies.size());
    double extent_sum = 0.0;
    uint32_t extent_count = 0;
    for (uint32_t bi = 0; bi < nb; ++bi) {
        const Aabb& box = c.body_box[bi];
        const double extent = std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
        if (bodies[bi].triangle_count > 0 && std::isfinite(extent)) extent_sum += extent, ++extent_count;
    }
    c.body_grid.build(c.body_box, extent_count > 0 && extent_sum > 0.0 ? extent_sum / extent_count : 1.0);
    c.partner_begin.assign(1, 0);
    c.partners.clear();
    c.shape_bodies.clear();
    for (uint32_t bi = 0; bi < nb; ++bi)
        if (bodies[bi].shape_count > 0) c.shape_bodies.push_back(bi);
    for (uint32_t ai = 0; ai < nb; ++ai) {
        const ContactBody& a = bodies[ai];
        if (a.node_count > 0) {
            c.found.clear();
            c.body_grid.query(c.slave_box[ai], c.found);
            // Itself too when it has self-contact (whatever its filter says of bodies like it).
            for (uint32_t bi : c.found)
                if (bi == ai ? a.self_contact : bodies[bi].triangle_count > 0 && bodies_may_touch(a, bodies[bi]))
                    c.partners.push_back(bi);
        }
        c.partner_begin.push_back(uint32_t(c.partners.size()));
    }
}

// Could static shape k of body o touch node p of body a (at x_search) before the budget runs
// out? Its distance can shrink by at most sqrt(3) B_a (a per-axis bound): look within twice B_a
// beyond the capture band.
bool shape_in_reach(const ContactBody& a, const double* x, double budget, const ContactBody& o, uint32_t k) {
    if (o.moves) return true;  // a kinematic shape: tested at every sub-step
    const RigidShape& shape = o.shapes[k];
    const ShapePose pose = ShapePose::load(o.shape_pose + 7 * std::size_t(k));
    const double reach = kCaptureBand * a.edge_length + 2.0 * budget;
    const Vec3 p(x[0], x[1], x[2]);
    if ((p - pose.center).norm() > shape_bounding_radius(shape) + reach) return false;
    double distance;
    Vec3 normal;
    return shape_signed_distance(shape, pose, p, reach, distance, normal);
}

// The candidates of the slave nodes [first, last) of the sequence of all bodies' slave nodes
// (slave_begin: where each body's start), into block `block`.
void search_block(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& slave_begin, uint32_t first,
                  uint32_t last, uint32_t block, ContactCandidates& c) {
    std::vector<uint32_t>& out_body = c.block_body[block];
    std::vector<uint32_t>& out_node = c.block_node[block];
    std::vector<uint32_t>& triangle_count = c.block_triangle_count[block];
    std::vector<uint32_t>& shape_count = c.block_shape_count[block];
    std::vector<uint64_t>& triangles = c.block_triangles[block];
    std::vector<uint64_t>& shapes = c.block_shapes[block];
    std::vector<Aabb>& static_box = c.block_static_box[block];
    out_body.clear(), out_node.clear(), triangle_count.clear(), shape_count.clear(), triangles.clear(), shapes.clear();
    static_box.clear();
    uint32_t ai = uint32_t(std::upper_bound(slave_begin.begin(), slave_begin.end(), first) - slave_begin.begin()) - 1;
    for (uint32_t g = first; g < last; ++g) {
        while (slave_begin[ai + 1] <= g) ++ai;
        const ContactBody& a = bodies[ai];
        const uint32_t p = a.nodes[g - slave_begin[ai]];
        const double* x = a.x + 3 * std::size_t(p);
        const std::size_t triangles_before = triangles.size(), shapes_before = shapes.size();
        for (uint32_t q = c.partner_begin[ai]; q < c.partner_begin[ai + 1]; ++q) {
            const uint32_t bi = c.partners[q];
            const std::size_t from = triangles.size();
            const ContactBody& b = bodies[bi];
            const bool self = bi == ai;
            if (self && a.node_triangle_begin[p + 1] == a.node_triangle_begin[p]) continue;  // interior
            const double grow = triangle_growth(contact_length(a, b), c.offset_allowed, catches_deep_nodes(a, b, c.scanned));
            c.tree_of(bodies, bi).query(point_box(x, c.budget[ai] + c.budget[bi] + grow), b.x, b.triangles, 0.0,
                                        [&](uint32_t t) {
                                            if (!self || own_triangle_in_reach(a, p, b.triangles + 3 * std::size_t(t)))
                                                triangles.push_back(uint64_t(bi) << 32 | t);
                                        });
            std::sort(triangles.begin() + from, triangles.end());  // partners ascend, so does the list
            for (std::size_t k = from; k < triangles.size(); ++k)
                static_box.push_back(bodies[bi].moves ? empty_box() : triangle_step_box(bodies[bi], uint32_t(triangles[k]), 0.0));
        }
        for (uint32_t o : c.shape_bodies) {
            if (o == ai || !bodies_may_touch(a, bodies[o])) continue;
            for (uint32_t k = 0; k < bodies[o].shape_count; ++k)
                if (shape_in_reach(a, x, c.budget[ai], bodies[o], k)) shapes.push_back(uint64_t(o) << 32 | k);
        }
        if (triangles.size() == triangles_before && shapes.size() == shapes_before) continue;
        out_body.push_back(ai);
        out_node.push_back(p);
        triangle_count.push_back(uint32_t(triangles.size() - triangles_before));
        shape_count.push_back(uint32_t(shapes.size() - shapes_before));
    }
}

}  // namespace

Aabb triangle_step_box(const ContactBody& b, uint32_t t, double grow) {
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
    return box;
}

bool candidates_may_hold(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                         const ContactCandidates& c) {
    if (!c.valid || c.identity.size() != bodies.size()) return false;
    // A search for initial overlaps looked half an edge deep; after that step a narrower one
    // takes over.
    if (max_offset > c.offset_allowed || scan_overlaps != c.scanned) return false;
    for (uint32_t bi = 0; bi < bodies.size(); ++bi)
        if (c.identity[bi] != bodies[bi].identity) return false;
    return true;
}

void measure_move(const std::vector<ContactBody>& bodies, uint32_t bi, ContactCandidates& c) {
    const ContactBody& b = bodies[bi];
    c.moved[bi] = b.moves ? largest_move(b, &c.x_search[3 * std::size_t(c.surface_begin[bi])]) : 0.0;
}

bool moves_within_budgets(const ContactCandidates& c) {
    for (uint32_t bi = 0; bi < c.moved.size(); ++bi)
        if (!(c.moved[bi] <= c.budget[bi])) return false;  // also a NaN position
    return true;
}

void search_candidates(const std::vector<ContactBody>& bodies, double max_offset, bool scan_overlaps,
                       ContactCandidates& c, ThreadPool* pool) {
    c.valid = false;
    c.searches += 1;
    prepare_bodies(bodies, max_offset, scan_overlaps, c, pool);
    find_partners(bodies, c);
    std::vector<uint32_t> slave_begin(1, 0);
    uint64_t work = 0;
    for (uint32_t ai = 0; ai < bodies.size(); ++ai) {
        const bool partners = c.partner_begin[ai + 1] > c.partner_begin[ai];
        const bool tested = partners || !c.shape_bodies.empty();
        slave_begin.push_back(slave_begin.back() + (tested ? bodies[ai].node_count : 0));
    }
    work = slave_begin.back();
    const uint32_t blocks = (slave_begin.back() + kSearchBlock - 1) / kSearchBlock;
    for (auto* v : {&c.block_body, &c.block_node, &c.block_triangle_count, &c.block_shape_count})
        if (v->size() < blocks) v->resize(blocks);
    for (auto* v : {&c.block_triangles, &c.block_shapes})
        if (v->size() < blocks) v->resize(blocks);
    if (c.block_static_box.size() < blocks) c.block_static_box.resize(blocks);
    parallel_for(work >= kSearchBlock ? pool : nullptr, blocks, [&](uint32_t b) {
        search_block(bodies, slave_begin, b * kSearchBlock, std::min(slave_begin.back(), (b + 1) * kSearchBlock), b, c);
    });
    // The blocks joined in block order: the nodes in body and node order.
    c.body.clear(), c.node.clear(), c.triangles.clear(), c.shapes.clear(), c.static_box.clear();
    c.triangle_begin.assign(1, 0);
    c.shape_begin.assign(1, 0);
    for (uint32_t b = 0; b < blocks; ++b) {
        c.body.insert(c.body.end(), c.block_body[b].begin(), c.block_body[b].end());
        c.node.insert(c.node.end(), c.block_node[b].begin(), c.block_node[b].end());
        c.triangles.insert(c.triangles.end(), c.block_triangles[b].begin(), c.block_triangles[b].end());
        c.static_box.insert(c.static_box.end(), c.block_static_box[b].begin(), c.block_static_box[b].end());
        c.shapes.insert(c.shapes.end(), c.block_shapes[b].begin(), c.block_shapes[b].end());
        for (uint32_t n : c.block_triangle_count[b]) c.triangle_begin.push_back(c.triangle_begin.back() + n);
        for (uint32_t n : c.block_shape_count[b]) c.shape_begin.push_back(c.shape_begin.back() + n);
    }
    c.faces.clear();
    for (uint64_t key : c.triangles)
        if (bodies[uint32_t(key >> 32)].moves) c.faces.push_back(key);
    std::sort(c.faces.begin(), c.faces.end());
    c.faces.erase(std::unique(c.faces.begin(), c.faces.end()), c.faces.end());
    c.face_index.resize(c.triangles.size());
    for (std::size_t k = 0; k < c.triangles.size(); ++k)
        c.face_index[k] = bodies[uint32_t(c.triangles[k] >> 32)].moves
                              ? uint32_t(std::lower_bound(c.faces.begin(), c.faces.end(), c.triangles[k]) - c.faces.begin())
                              : UINT32_MAX;
    c.valid = true;
}

}  // namespace lfem
