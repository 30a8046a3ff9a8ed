// What contact detection and the multiplier solve see of one body during a sub-step: flat
// arrays borrowed from the body and the step's scratch, nothing owned.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/math.h"
#include "contact/rigid_shape.h"

namespace lfem {

// What the solve needs of a rigid body in this step: its predicted centre, and how a force
// lambda (N) at a point moves it, as for a node: dx = lambda / mhat with
// 1/mhat = h h_mid (1/M + r x I^-1 (r x .)); and the corrections the solve accumulates, which
// the rigid body's commit applies.
struct RigidResponse {
    Vec3 center = Vec3::Zero();     // c* (predicted)
    double inv_mass = 0;            // h h_mid / M
    Mat3 inv_inertia = Mat3::Zero();  // h h_mid I_world^-1 at x*
    Vec3 dc = Vec3::Zero();         // correction of the centre accumulated by the solve
    Vec3 dtheta = Vec3::Zero();     // correction of the rotation (rotation vector)
};

class TriangleBvh;

struct ContactBody {
    uint32_t slot = 0;                 // the body's slot in the world (for handles)
    uint64_t identity = 0;             // changes whenever the body's geometry does (cached
                                       // contact candidates are kept only while it holds)
    bool moves = true;                 // false for a static body: x never changes
    bool asleep = false;               // a sleeping body, taking part as a static one
    const uint32_t* triangles = nullptr; // boundary triangles, 3 node indices each
    uint32_t triangle_count = 0;
    const uint32_t* nodes = nullptr;   // boundary nodes (the candidate slave nodes)
    uint32_t node_count = 0;
    uint32_t total_nodes = 0;          // all nodes of the body (x has 3 per node)
    const uint32_t* surface_nodes = nullptr;  // every node of the triangles, ascending
    uint32_t surface_node_count = 0;
    const uint32_t* node_triangle_begin = nullptr;  // per node: where its triangles start
    const uint32_t* node_triangles = nullptr;       // (+1 at the end), ascending
    const uint32_t* sharp_edges = nullptr;      // the surface's sharp edges at rest, 4 each
    uint32_t sharp_edge_count = 0;              //   (mesh/surface.h, Surface::sharp_edges); 0
                                                //   when the body's edge pass is off
    const uint32_t* fold_edges = nullptr;       // its folds (Surface::fold_edges), 4 each; 0
    uint32_t fold_edge_count = 0;               //   when the body's edge pass is off
    const uint32_t* triangle_edges = nullptr;   // per triangle, its 3 edges (Surface::triangle_edges)
    const uint32_t* elements = nullptr;         // the tets, element_stride nodes each (corners first)
    uint32_t element_stride = 4;
    const uint32_t* triangle_element = nullptr; // per triangle: the tet it bounds (UINT32_MAX: none)
    const uint32_t* node_element_begin = nullptr;  // per node: where its tets start (+1 at the end;
    const uint32_t* node_elements = nullptr;       // surface nodes only), nullptr without
    const TriangleBvh* static_bvh = nullptr;  // a static body's tree, built when its mesh was added
    const double* face_normals = nullptr;     // a static body's unit face normals (3 per triangle,
                                              // zero: collapsed), made when its mesh was added
    const double* x_start = nullptr;   // 3 per node: positions at the start of the step, x^n
    const double* v_last = nullptr;    // 3 per node: velocity over the last step (deformable
                                       // bodies); nullptr = (x - x_start) / h, this step's
                                       // rigid motion (zero for a static body)
    double* x = nullptr;               // 3 per node: predicted x*, corrected in place to x^{n+1}
    const double* inv_mass = nullptr;  // per node: 1/mhat (m per N); nullptr = no node moves alone
    RigidResponse* rigid = nullptr;    // a rigid body: its nodes move together (x holds x*)
    double friction = 0;               // Coulomb coefficient of the body's surface
    uint32_t category = 1, mask = ~0u; // collision filter
    bool self_contact = false;         // its boundary nodes meet its own triangles too
    double edge_length = 0;            // mean boundary edge length (m): sets the tolerances
    double load_motion = 0;            // m: how far gravity and the node forces move a free node of
                                       // the body in one sub-step (h h_mid a); 0 if it is not stepped
    const RigidShape* shapes = nullptr; // rigid shapes (static and kinematic bodies)
    uint32_t shape_count = 0;
    const double* shape_pose = nullptr;       // 7 per shape, end of the step
    const double* shape_pose_start = nullptr; // 7 per shape, start of the step
};

// Edge e of body b for the edge pass: its sharp edges are 0 .. sharp_edge_count - 1, its folds
// follow (4 entries each: the nodes u < v, the triangles they join).
inline uint32_t edge_count(const ContactBody& b) { return b.sharp_edge_count + b.fold_edge_count; }
inline bool is_fold(const ContactBody& b, uint32_t e) { return e >= b.sharp_edge_count; }
inline const uint32_t* edge_of(const ContactBody& b, uint32_t e) {
    return is_fold(b, e) ? b.fold_edges + 4 * std::size_t(e - b.sharp_edge_count) : b.sharp_edges + 4 * std::size_t(e);
}

// A body whose points contact can move: a deformable one (its free nodes) or a rigid one.
// Static and kinematic bodies follow their own motion whatever the contacts do.
inline bool is_movable(const ContactBody& b) { return b.inv_mass != nullptr || b.rigid != nullptr; }

// Whether nodes found deep inside body b count (pushed out) at every step, not only when new
// bodies are checked for initial overlaps: static, kinematic and rigid bodies are solid
// volumes that nothing may pass through.
inline bool catches_deep_nodes(const ContactBody& b, bool scan_overlaps) {
    return scan_overlaps || b.inv_mass == nullptr;
}

// The same for a node of `a` against `b`: a body's own nodes lie behind its own faces, so a
// body never finds them deep inside itself.
inline bool catches_deep_nodes(const ContactBody& a, const ContactBody& b, bool scan_overlaps) {
    return &a != &b && catches_deep_nodes(b, scan_overlaps);
}

// Node p of a self-contact body against one of its own triangles: only a boundary node, and
// never a triangle around it, which it touches by construction. The triangles next to those
// are candidates: a crease folds them onto the node. (node_face.cpp)
bool own_triangle_in_reach(const ContactBody& a, uint32_t p, const uint32_t* triangle);

// Two bodies are checked against each other only if each one's category is in the other's
// mask, and at least one of them can move.
inline bool bodies_may_touch(const ContactBody& a, const ContactBody& b) {
    return (a.category & b.mask) != 0 && (b.category & a.mask) != 0 && (is_movable(a) || is_movable(b));
}

// The length that scales the tolerances of a node of `a` against a triangle of `b`: the finer of
// the two surfaces' mean edges, so that a coarse floor's large triangles do not widen the bands
// (and the work) of a fine body resting on it.
inline double contact_length(const ContactBody& a, const ContactBody& b) {
    return a.edge_length < b.edge_length ? a.edge_length : b.edge_length;
}

// Friction of a pair: the geometric mean, so a frictionless surface (mu = 0) makes every
// contact it takes part in frictionless, and equal surfaces keep their own coefficient.
inline double pair_friction(double mu_a, double mu_b) {
    return mu_a * mu_b > 0.0 ? __builtin_sqrt(mu_a * mu_b) : 0.0;
}

}  // namespace lfem
