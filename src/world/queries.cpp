// The queries of the world's current geometry (query/query_scene.h) on the bodies as they are:
// the world lends each body's arrays, the scene keeps its boxes and trees current through the
// world's revision, which moves with every change of positions or geometry.
#include "common/closest_point.h"
#include "common/error.h"
#include "world/world.h"

namespace lfem {
namespace {

class BodiesForQueries final : public QueryWorld {
public:
    explicit BodiesForQueries(const BodyRegistry& bodies) : bodies_(bodies) {}
    uint32_t slot_count() const override { return bodies_.slot_count(); }
    bool body(uint32_t slot, QueryBody& out) const override {
        if (!bodies_.live(slot)) return false;
        const Body& b = bodies_.slot(slot);
        if (!b.has_geometry()) return false;
        out.identity = b.geometry_identity();
        out.moves = b.def.type != BodyKind::static_body;
        out.solid = b.ref.tet_count() > 0;
        out.category = b.def.category_bits, out.mask = b.def.mask_bits;
        out.x = b.state.x.data();
        out.triangles = b.ref.surface.triangles.data();
        out.triangle_count = b.ref.surface.triangle_count();
        out.surface_nodes = b.ref.surface.nodes.data();
        out.surface_node_count = uint32_t(b.ref.surface.nodes.size());
        out.static_tree = b.def.type == BodyKind::static_body ? &b.ref.bvh : nullptr;
        out.shapes = b.shapes.data();
        out.shape_count = uint32_t(b.shapes.size());
        out.shape_pose = b.state.shape_pose.data();
        return true;
    }

private:
    const BodyRegistry& bodies_;
};

}  // namespace

void World::moved(ThreadPool* pool) {
    queries_.revision += 1;
    if (!pool || !queries_.scene.in_use()) return;
    try {
        queries_.scene.prepare(BodiesForQueries(bodies_), queries_.revision, pool);
    } catch (...) {
        // Out of memory: the step rolls back, so the boxes made of its positions must not
        // count for any revision: the next query prepares everything again.
        queries_.revision += 1;
        throw;
    }
}

bool World::cast_ray(const QueryRay& ray, const QueryFilter& filter, RayHit& out) const {
    const BodiesForQueries view(bodies_);
    queries_.scene.prepare(view, queries_.revision, nullptr);
    return queries_.scene.cast_ray(view, ray, filter, out);
}

void World::cast_ray_all(const QueryRay& ray, const QueryFilter& filter, std::vector<RayHit>& out) const {
    const BodiesForQueries view(bodies_);
    queries_.scene.prepare(view, queries_.revision, nullptr);
    queries_.scene.cast_ray_all(view, ray, filter, out);
}

void World::overlap_box(const Aabb& box, const QueryFilter& filter, std::vector<uint32_t>& slots) const {
    const BodiesForQueries view(bodies_);
    queries_.scene.prepare(view, queries_.revision, nullptr);
    queries_.scene.overlap_box(view, box, filter, slots);
}

bool World::cast_sphere(const QueryRay& ray, double radius, const QueryFilter& filter, RayHit& out) const {
    const BodiesForQueries view(bodies_);
    queries_.scene.prepare(view, queries_.revision, nullptr);
    return queries_.scene.cast_sphere(view, ray, radius, filter, out);
}

void World::overlap_capsule(const QueryCapsule& capsule, const QueryFilter& filter, std::vector<Overlap>& out) const {
    const BodiesForQueries view(bodies_);
    queries_.scene.prepare(view, queries_.revision, nullptr);
    queries_.scene.overlap_capsule(view, capsule, filter, out);
}

// Every boundary triangle where the nodes are now: O(T) for T triangles, one body. The first
// triangle (in the body's order) among equally near ones.
SurfacePoint World::closest_surface_point(const Body& b, const double point[3]) const {
    const std::vector<uint32_t>& t = b.boundary_triangles();
    if (t.empty()) throw Error(Status::invalid_argument, "the body has no boundary triangles (shapes are not searched)");
    const Vec3 p(point);
    const double* x = b.state.x.data();
    SurfacePoint best;
    // Squared distances, unless a body far out (beyond 1e154 m) overflows them all: then the
    // distances themselves, scaled (stableNorm), so that the answer stays a point and a finite
    // distance.
    for (const bool scaled : {false, true}) {
        double nearest = HUGE_VAL;
        for (std::size_t k = 0; k < t.size(); k += 3) {
            double w[3];
            const Vec3 q = closest_on_triangle(p, Vec3(x + 3 * std::size_t(t[k])), Vec3(x + 3 * std::size_t(t[k + 1])),
                                               Vec3(x + 3 * std::size_t(t[k + 2])), w);
            const double d = scaled ? (q - p).stableNorm() : (q - p).squaredNorm();
            if (d < nearest) nearest = d, best.point = q, best.triangle = uint32_t(k / 3);
        }
        best.distance = scaled ? nearest : std::sqrt(nearest);
        if (nearest < HUGE_VAL) break;
    }
    return best;
}

}  // namespace lfem
