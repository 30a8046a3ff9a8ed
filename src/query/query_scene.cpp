// The queries' cache: a box per body at its current positions, the tree of those boxes, and
// the moving bodies' trees of triangles, each redone only when its body moved or changed.
#include "query/query_scene.h"

#include <algorithm>
#include <cmath>

namespace lfem {
namespace {

// The box of a posed shape (a hull's by its bounding sphere: it is only a first test).
Aabb shape_box(const RigidShape& s, const ShapePose& pose) {
    Aabb b;
    Vec3 reach;
    switch (s.type) {
        case ShapeType::box: {
            const Mat3 R = pose.rotation.toRotationMatrix();
            reach = R.cwiseAbs() * Vec3(s.half_extents);
            break;
        }
        case ShapeType::capsule:
            reach = (pose.rotation * Vec3(0, 0, s.half_length)).cwiseAbs() + Vec3::Constant(s.radius);
            break;
        default: reach = Vec3::Constant(shape_bounding_radius(s)); break;
    }
    for (int k = 0; k < 3; ++k) b.lo[k] = pose.center[k] - reach[k], b.hi[k] = pose.center[k] + reach[k];
    return b;
}

}  // namespace

bool hit_before(const RayHit& a, const RayHit& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.slot != b.slot) return a.slot < b.slot;
    const bool a_shape = a.shape != UINT32_MAX, b_shape = b.shape != UINT32_MAX;
    if (a_shape != b_shape) return !a_shape;
    return a_shape ? a.shape < b.shape : a.triangle < b.triangle;
}

void QueryScene::box_body(uint32_t slot, const QueryBody& b) {
    Slot& s = slots_[slot];
    s.box = empty_box();
    s.unbounded = false;
    for (uint32_t j = 0; j < b.surface_node_count; ++j) {
        const double* p = &b.x[3 * std::size_t(b.surface_nodes[j])];
        for (int k = 0; k < 3; ++k) s.box.lo[k] = std::min(s.box.lo[k], p[k]), s.box.hi[k] = std::max(s.box.hi[k], p[k]);
    }
    for (uint32_t j = 0; j < b.shape_count; ++j) {
        const RigidShape& shape = b.shapes[j];
        if (shape.type == ShapeType::plane) {
            s.unbounded = true;
            continue;
        }
        join(s.box, shape_box(shape, ShapePose::load(b.shape_pose + 7 * std::size_t(j))));
    }
}

void QueryScene::prepare(const QueryWorld& world, uint64_t revision, ThreadPool* pool) {
    const uint32_t n = world.slot_count();
    if (prepared_ && revision == revision_ && slots_.size() == n) return;
    slots_.resize(n);
    parallel_for(pool, n, [&](uint32_t i) {
        Slot& s = slots_[i];
        QueryBody b;
        s.present = world.body(i, b);
        if (!s.present) return;
        // A static body's box holds for as long as its geometry; a moving one's for a revision.
        if (s.identity == b.identity && (!b.moves || s.revision == revision)) return;
        box_body(i, b);
        s.identity = b.identity, s.revision = revision;
    });
    bounded_.clear();
    unbounded_.clear();
    for (uint32_t i = 0; i < n; ++i)
        if (slots_[i].present) (slots_[i].unbounded ? unbounded_ : bounded_).push_back(i);
    std::vector<double> centre(3 * bounded_.size());
    for (std::size_t j = 0; j < bounded_.size(); ++j)
        for (int k = 0; k < 3; ++k) {
            const Aabb& box = slots_[bounded_[j]].box;
            centre[3 * j + k] = 0.5 * (box.lo[k] + box.hi[k]);
        }
    tree_.build(centre.data(), uint32_t(bounded_.size()));
    tree_.refit([&](uint32_t j) { return slots_[bounded_[j]].box; });
    revision_ = revision;
    prepared_ = true;
}

const TriangleBvh& QueryScene::tree_of(uint32_t slot, const QueryBody& b) {
    if (b.static_tree) return *b.static_tree;
    Slot& s = slots_[slot];
    if (s.tree_identity != b.identity || s.tree.empty()) {
        s.tree.build(b.x, b.triangles, b.triangle_count);
    } else if (s.tree_revision != revision_) {
        s.tree.refit(b.x, b.triangles);
    } else {
        return s.tree;
    }
    s.tree_identity = b.identity, s.tree_revision = revision_;
    counts_.refits += 1;
    return s.tree;
}

}  // namespace lfem
