// A body as flat arrays. Split as in MuJoCo's model/data: BodyReference is fixed once the mesh
// is added (reference nodes, masses, element gradients, surface), BodyState is everything a
// step changes (and so everything a rollback restores). The views at the end hand the kernels
// of fem/, rigid/ and contact/ what they compute on, without those folders knowing a Body.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/rigid_shape.h"
#include "contact/triangle_bvh.h"
#include "fem/central_difference.h"
#include "fem/element_colouring.h"
#include "fem/element_mesh.h"
#include "fem/internal_forces.h"
#include "fem/material.h"
#include "mesh/node_ordering.h"
#include "mesh/surface.h"
#include "rigid/global_rotation.h"
#include "rigid/rigid_body.h"
#include "skin/skin.h"
#include "world/definitions.h"

namespace lfem {

struct BodyReference {
    std::vector<double> X;          // 3 per node: reference positions (m)
    std::vector<double> mass;       // lumped node masses (kg, fem/lumped_mass.h)
    std::vector<uint32_t> tets;     // nodes_per_tet node indices per tet
    std::vector<double> Dm_inv;     // 9 per tet (linear) or per quadrature point (quadratic):
                                    // inverse reference edge matrix or Jacobian (column-major)
    std::vector<double> volume;     // reference volume per tet (m^3)
    std::vector<double> qp_volume;  // quadratic: 4 per tet, each quadrature point's volume
    uint32_t nodes_per_tet = 4;     // 4, or 10 for a body of quadratic tets (fixed by its
                                    // first mesh)
    bool composite = false;         // 10-node tets as the composite element (the body def's
                                    // composite_tets; fem/composite_tet.h)
    Surface surface;                // boundary triangles, slave and feature nodes, edge length
    double total_mass = 0;          // the sum of `mass`, added mass included
    double added_mass = 0;          // kg, added by mass scaling (lfem_world_def.mass_scaling_step)
    double com[3] = {0, 0, 0};      // reference centre of mass
    double stable_step = 0;         // 2/omega_max of this body alone (s); 0 = not deformable
    double inertia[9] = {0};        // rigid bodies: inertia about the COM, reference frame
    Numbering numbering;            // internal (locality) order <-> the caller's numbering
    ElementColouring colouring;     // blocks of tets for the parallel element loop (derived
                                    // from tets: rebuilt, not saved, by checkpoints)
    std::vector<uint32_t> every_node;  // deformable bodies: 0 .. node_count - 1, the contact slaves
    std::vector<double> face_normals; // static bodies: each boundary triangle's unit outward
                                      // normal (3 each; zero for a collapsed one), derived
    TriangleBvh bvh;                // static bodies: the tree of the boundary triangles, built
                                    // when the mesh is added (derived, like the colouring)

    uint32_t node_count() const { return uint32_t(X.size() / 3); }
    uint32_t tet_count() const { return uint32_t(volume.size()); }
    // Corotational warm-start rotations per tet: one, or one per quadrature point.
    uint32_t rotations_per_tet() const { return nodes_per_tet == 10 ? 4 : 1; }
};

struct BodyState {
    std::vector<double> x;         // 3 per node: positions at the current time (m)
    std::vector<double> v_half;    // 3 per node: velocity of the last step, (x^n - x^n-1)/h;
                                   // the synchronized velocity itself when h_last == 0
    std::vector<double> elastic;   // 3 per node: elastic force -f_int at x (N)
    std::vector<float> tet_rotation; // 4 per tet (w,x,y,z; quadratic tets: 4 per quadrature
                                     // point): warm start of the corotational rotations
                                     // (float: a start, not a result); empty for the other
                                     // models
    std::vector<double> contact_force; // 3 per node: contact force of the last step (N);
                                       // empty while the body touches nothing
    double h_last = 0;             // size of the last step (s); 0 = no step since a reset
    double strain_energy = 0;      // J, at x
    uint32_t inverted_tets = 0;    // tets turned inside out at x (J <= 0)
    double min_jacobian = 1;       // the smallest volume ratio J of the tets at x
    double inverted_since = -1;    // s: when the body's tets last began to be inverted (-1: none are)
    double stiffening = 1;         // neo-Hookean: how much stiffer the stiffest tet is at x than
                                   // at rest (>= 1; neo_hookean_tangent.h); 1 for the others
    double sleep_timer = 0;        // s: how long the body has moved slower than sleep_velocity (sleep.cpp)
    uint32_t asleep = 0;           // 1: not stepped until it wakes (lfem_world_def.enable_sleep)
    GlobalMotion global;           // paper model: frame rotation and L of eq. (2); rigid: the
                                   // whole motion; kinematic: the pivot (center)
    std::vector<double> shape_pose;  // 7 per rigid shape: its current placement
};

struct Body {
    uint32_t generation = 0;
    uint32_t geometry_revision = 0;           // counts the meshes and shapes added (contact's
                                              // cached candidates hold while it does not change)
    BodyDef def{};
    BodyReference ref;
    BodyState state;
    std::vector<NodeMode> node_mode;          // per node
    std::vector<double> prescribed_velocity;  // 3 per node, empty until first prescribed
    std::vector<double> node_force;           // 3 per node, empty until a force is set
    std::vector<double> call_force;           // 3 per node: forces for the next call only
                                              // (lfem_body_apply_force), empty when none
    std::vector<double> applied_force;        // node_force + call_force while call_force is set
                                              // (the first sub-step of a call scales call_force,
                                              // World::plan_stages)
    std::vector<RigidShape> shapes;           // rigid shapes (static and kinematic bodies)
    std::vector<Skin> skins;                  // render meshes bound to the tets (skin/skin.h);
                                              // never read by a step

    // The Lame parameters of the def's Young's modulus and Poisson's ratio (derived, never
    // stored: a change of the def changes them).
    Lame lame() const { return lame_from_young_poisson(def.young_modulus, def.poisson_ratio); }
    // The node forces a step applies: the caller's lasting ones, plus the next call's when set.
    Span<const double> loads() const { return call_force.empty() ? Span<const double>(node_force) : applied_force; }
    // applied_force = call_scale * call_force + node_force again after either changed (the
    // caller has sized applied_force as call_force: nothing here allocates or fails).
    void refresh_loads(double call_scale = 1.0) {
        for (std::size_t k = 0; k < applied_force.size(); ++k)
            applied_force[k] = call_scale * call_force[k] + (node_force.empty() ? 0.0 : node_force[k]);
    }
    bool is_deformable() const { return def.type == BodyKind::deformable; }
    bool is_rigid() const { return def.type == BodyKind::rigid; }
    bool is_kinematic() const { return def.type == BodyKind::kinematic; }
    bool is_dynamic() const { return is_deformable() || is_rigid(); }  // moved by forces
    bool is_static() const { return def.type == BodyKind::static_body; }
    bool moves_kinematically() const {
        const double* v = def.linear_velocity;
        const double* w = def.angular_velocity;
        return is_kinematic() && (v[0] != 0 || v[1] != 0 || v[2] != 0 || w[0] != 0 || w[1] != 0 || w[2] != 0);
    }
    bool is_paper() const { return is_deformable() && def.model == Model::paper; }
    bool has_mesh() const { return !ref.X.empty(); }  // tets, or a static triangle surface
    bool has_geometry() const { return has_mesh() || !shapes.empty(); }
    // Changes whenever the geometry does: a new generation, a mesh or a shape added.
    uint64_t geometry_identity() const { return uint64_t(generation) << 32 | geometry_revision; }

    // ---- what the shim reads of a body: plain values, in the body's internal numbering, which
    // numbering() translates (anything computed is a World read, body_reads.cpp)
    uint32_t node_count() const { return ref.node_count(); }
    uint32_t tet_count() const { return ref.tet_count(); }
    uint32_t nodes_per_tet() const { return ref.nodes_per_tet; }  // 4 or 10 (4 before any tet)
    const Numbering& numbering() const { return ref.numbering; }
    const double* positions() const { return state.x.data(); }  // 3 per node
    const std::vector<uint32_t>& tets() const { return ref.tets; }
    const std::vector<uint32_t>& boundary_triangles() const { return ref.surface.triangles; }
    // The boundary as faces: the 6-node triangles of a body of 10-node tets, else the triangles.
    const std::vector<uint32_t>& boundary_faces() const {
        return ref.nodes_per_tet == 10 ? ref.surface.quadratic_faces : ref.surface.triangles;
    }
    uint32_t nodes_per_face() const { return ref.nodes_per_tet == 10 ? 6 : 3; }
    double mass() const { return ref.total_mass; }
    double added_mass() const { return ref.added_mass; }
    void* user_data() const { return def.user_data; }
    uint64_t user_id() const { return def.user_id; }
};

// The blocks of the parallel element loop of a body's tets (element_colouring.h): blocks of
// about the same work, a 10-node tet costing several linear ones. Derived from the tets alone,
// so a checkpoint rebuilds it.
inline ElementColouring colour_tets(const BodyReference& ref) {
    const uint32_t block = ref.nodes_per_tet == 10 ? kElementBlockSize / 4 : kElementBlockSize;
    return colour_element_blocks(ref.tets.data(), ref.tet_count(), ref.node_count(), block, ref.nodes_per_tet);
}

// The data derived from a body's reference (not saved in checkpoints): the element colouring,
// the surface's node-triangle lists and, for a static body, the tree of its triangles.
void derive_reference_data(const Body& body, BodyReference& ref);
// The stable step, the masses (fitted to it under mass scaling), the total mass and the
// reference centre of mass of a body's tets (add_mesh.cpp).
void fit_step_and_masses(const Body& body, const WorldDef& def, BodyReference& ref, ThreadPool* pool);

// ---- views for the kernels ---------------------------------------------------------------

inline ElementMesh element_mesh(const BodyReference& ref) {
    ElementMesh m;
    m.X = ref.X, m.tets = ref.tets, m.Dm_inv = ref.Dm_inv, m.volume = ref.volume, m.mass = ref.mass;
    m.qp_volume = ref.qp_volume, m.nodes_per_tet = ref.nodes_per_tet, m.composite = ref.composite;
    m.colouring = &ref.colouring;
    return m;
}

inline Material material_of(const Body& b) { return Material{b.def.model, b.lame()}; }

// The elastic state at b.state.x, written into `elastic` (b.state.elastic for the step).
inline ElasticState elastic_state(const BodyState& s, std::vector<double>& elastic, std::vector<float>& tet_rotation) {
    ElasticState e;
    e.x = s.x, e.force = elastic, e.tet_rotation = tet_rotation, e.frame = s.global.rotation;
    return e;
}

// Forces at the body's current positions into its state: elastic forces, strain energy and
// stiffening.
inline void update_elastic_forces(const Body& b, BodyState& s, ThreadPool* pool) {
    const ElasticResult r =
        compute_elastic_forces(element_mesh(b.ref), material_of(b), elastic_state(s, s.elastic, s.tet_rotation), pool);
    s.strain_energy = r.strain_energy;
    s.stiffening = r.stiffening;
    s.inverted_tets = r.inverted_tets;
    s.min_jacobian = r.min_jacobian;
}

inline NodeLoads node_loads(const Body& b, const double gravity[3]) {
    NodeLoads l;
    l.mass = b.ref.mass, l.mode = b.node_mode, l.prescribed_velocity = b.prescribed_velocity;
    l.node_force = b.loads(), l.elastic = b.state.elastic, l.damping = b.def.damping, l.gravity = gravity;
    return l;
}

inline RigidBodyView rigid_view(const Body& b) {
    RigidBodyView v;
    v.mass = b.ref.total_mass, v.com = Vec3(b.ref.com), v.inertia = load_row_major(b.ref.inertia);
    v.X = b.ref.X, v.node_force = b.loads();
    return v;
}

}  // namespace lfem
