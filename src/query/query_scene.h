// Queries of the world's current geometry: rays cast against the deformed surfaces of every
// body and against the rigid shapes (closest hit, or all of them), and the bodies a box
// overlaps. Their cost follows what the ray or the box meets, not the size of the scene: a
// tree of the bodies' boxes finds the bodies met, and each body's tree of triangles the
// triangles (a static body's is the one contact built with its mesh; a moving body's is kept
// here and refitted only when a query reaches it after the body moved). The boxes and the
// tree of bodies are redone once per change of the world (the step does it, once queries are
// in use), never by the queries themselves unless something changed without a step.
//
// Nothing here is read by a step: the scene is a cache of the world's current state, so
// making queries or not leaves every result of the simulation bitwise the same.
#pragma once

#include <cstdint>
#include <vector>

#include "common/box_tree.h"
#include "common/math.h"
#include "common/thread_pool.h"
#include "contact/rigid_shape.h"
#include "contact/triangle_bvh.h"

namespace lfem {

// What the queries see of one body: arrays borrowed from the world, nothing owned.
struct QueryBody {
    uint64_t identity = 0;                  // changes whenever its geometry does
    bool moves = true;                      // false: a static body (x never changes)
    bool solid = false;                     // a tet mesh: its triangles close a volume
    uint32_t category = 1, mask = ~0u;      // its collision filter
    const double* x = nullptr;              // 3 per node: current positions
    const uint32_t* triangles = nullptr;    // boundary triangles, 3 node indices each
    uint32_t triangle_count = 0;
    const uint32_t* surface_nodes = nullptr;  // the nodes of the triangles
    uint32_t surface_node_count = 0;
    const TriangleBvh* static_tree = nullptr;  // a static body's tree (built with its mesh)
    const RigidShape* shapes = nullptr;
    uint32_t shape_count = 0;
    const double* shape_pose = nullptr;     // 7 per shape: current placement
};

// The world as the queries see it: numbered slots, each a body or nothing.
class QueryWorld {
public:
    virtual uint32_t slot_count() const = 0;
    // The body in a slot; false for a free slot or a body without geometry.
    virtual bool body(uint32_t slot, QueryBody& out) const = 0;

protected:
    ~QueryWorld() = default;
};

// A body is seen when each one's category is in the other's mask (as between bodies).
struct QueryFilter {
    uint32_t category = 1, mask = ~0u;
    bool sees(const QueryBody& b) const { return (b.category & mask) != 0 && (category & b.mask) != 0; }
};

// origin + t dir, dir a unit vector, t in [0, max_distance].
struct QueryRay {
    Vec3 origin = Vec3::Zero(), dir = Vec3::UnitX();
    double max_distance = 0;
};

// Where a ray crossed a surface: a boundary triangle of a body (its weights t1, t2 as in the
// contacts: the point is (1 - t1 - t2) a + t2 b + t1 c) or one of its shapes.
struct RayHit {
    uint32_t slot = 0;
    uint32_t triangle = UINT32_MAX, shape = UINT32_MAX;
    double t1 = 0, t2 = 0;
    Vec3 point = Vec3::Zero(), normal = Vec3::Zero();  // normal: unit, out of the surface
    double distance = 0;                                // m along the ray
};

// A sphere (a == b) or a capsule: the segment ab swept by radius.
struct QueryCapsule {
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
    double radius = 0;
};

// A body a sphere or capsule overlaps, and where: its boundary triangle or shape nearest the
// query's core (both UINT32_MAX for a body that holds the core inside, out of the query's
// reach of its surface), the point of it nearest the core (the core's first point for such a
// body) and the distance from the core (0 when the core is inside a shape).
struct Overlap {
    uint32_t slot = 0;
    uint32_t triangle = UINT32_MAX, shape = UINT32_MAX;
    Vec3 point = Vec3::Zero();
    double distance = 0;
};

// The order of hits: nearer first, then by slot, triangles before shapes, then by index, so
// that the answer depends on nothing but the geometry.
bool hit_before(const RayHit& a, const RayHit& b);

// What the queries did, for the profile (counts, repeatable).
struct QueryCounts {
    uint64_t queries = 0;     // rays and boxes answered
    uint64_t bodies = 0;      // bodies reached (box met, filter passed)
    uint64_t primitives = 0;  // triangles and shapes tested exactly
    uint64_t refits = 0;      // moving bodies' trees built or refitted
};

class QueryScene {
public:
    // Makes the boxes and the tree of bodies those of the world at `revision` (a counter the
    // world moves whenever positions or geometry may have changed); only bodies that moved or
    // changed are boxed again. Nothing to do when the revision is the scene's.
    void prepare(const QueryWorld& world, uint64_t revision, ThreadPool* pool);
    // Whether a query was ever made (until then nothing is kept current).
    bool in_use() const { return in_use_; }

    // The nearest crossing of the ray with a surface the filter sees; false when none.
    bool cast_ray(const QueryWorld& world, const QueryRay& ray, const QueryFilter& filter, RayHit& out);
    // Every crossing, in hit_before order.
    void cast_ray_all(const QueryWorld& world, const QueryRay& ray, const QueryFilter& filter,
                      std::vector<RayHit>& out);
    // A sphere of `radius` swept along the ray: the first place it touches a surface the filter
    // sees (its distance along the ray, the point touched, the normal there out of the surface
    // towards the sphere's centre); false when none within max_distance.
    bool cast_sphere(const QueryWorld& world, const QueryRay& ray, double radius, const QueryFilter& filter,
                     RayHit& out);
    // The slots of the bodies the filter sees whose geometry overlaps the box (touching
    // counts): a boundary triangle or a shape that meets it, or a body of tets around it; in
    // slot order.
    void overlap_box(const QueryWorld& world, const Aabb& box, const QueryFilter& filter, std::vector<uint32_t>& out);
    // The bodies the filter sees that the sphere or capsule overlaps (touching counts), in slot
    // order, each with its nearest triangle or shape and point.
    void overlap_capsule(const QueryWorld& world, const QueryCapsule& capsule, const QueryFilter& filter,
                         std::vector<Overlap>& out);

    const QueryCounts& counts() const { return counts_; }
    void reset_counts() { counts_ = QueryCounts{}; }

private:
    struct Slot {
        bool present = false;    // a body with geometry
        bool unbounded = false;  // it has a plane: no box holds it
        uint64_t identity = 0, revision = 0;  // of the box
        Aabb box = empty_box();
        TriangleBvh tree;        // a moving body's triangles (a static body brings its own)
        uint64_t tree_identity = 0, tree_revision = 0;
    };
    void box_body(uint32_t slot, const QueryBody& b);
    // The body's tree of triangles at its current positions (refitted when it moved).
    const TriangleBvh& tree_of(uint32_t slot, const QueryBody& b);
    // visit(slot, t_max) -> t_max for the bodies whose box the ray meets, nearest first
    // (bodies with a plane first of all).
    template <class Visit>
    void for_bodies_on_ray(const QueryRay& ray, const Visit& visit, double grow = 0.0);
    // Every crossing of the ray with body b's triangles and shapes before t_max, to add(hit)
    // which returns the new t_max.
    template <class Add>
    double body_crossings(uint32_t slot, const QueryBody& b, const QueryRay& ray, double t_max, const Add& add);
    bool body_overlaps(uint32_t slot, const QueryBody& b, const Aabb& box);
    bool contains(uint32_t slot, const QueryBody& b, const Vec3& p);

    std::vector<Slot> slots_;
    BoxTree tree_;                             // of the bounded bodies' boxes
    std::vector<uint32_t> bounded_, unbounded_;  // slots, ascending
    uint64_t revision_ = 0;
    bool prepared_ = false, in_use_ = false;
    QueryCounts counts_;
};

}  // namespace lfem
