// A body as flat arrays. Split as in MuJoCo's model/data: BodyReference is fixed once the mesh
// is added (reference nodes, masses, element gradients), BodyState is everything a step
// changes (and so everything a rollback restores).
#pragma once

#include <cstdint>
#include <vector>

#include "contact/rigid_shape.h"
#include "fem/element_colouring.h"
#include "fem/material.h"
#include "mesh/node_ordering.h"
#include "lfem.h"

namespace lfem {

enum class NodeMode : uint8_t { free = 0, fixed = 1, prescribed = 2 };

struct BodyReference {
    std::vector<double> X;          // 3 per node: reference positions (m)
    std::vector<double> mass;       // lumped node masses, sum of rho V_e / 4 (kg)
    std::vector<uint32_t> tets;     // 4 node indices per tet
    std::vector<double> Dm_inv;     // 9 per tet: inverse reference edge matrix (column-major)
    std::vector<double> volume;     // reference volume per tet (m^3)
    std::vector<uint32_t> boundary; // 3 per outward boundary triangle
    std::vector<uint32_t> boundary_nodes; // nodes of the boundary, ascending (contact slaves)
    std::vector<uint32_t> feature_nodes;  // boundary nodes on edges and corners (15 degrees)
    double edge_length = 0;         // mean boundary edge length (m): contact tolerances
    double total_mass = 0;
    double com[3] = {0, 0, 0};      // reference centre of mass
    double stable_step = 0;         // 2/omega_max of this body alone (s); 0 = not deformable
    double inertia[9] = {0};        // rigid bodies: inertia about the COM, reference frame
    Numbering numbering;            // internal (locality) order <-> the caller's numbering
    ElementColouring colouring;     // blocks of tets for the parallel element loop (derived
                                    // from tets: rebuilt, not saved, by checkpoints)

    uint32_t node_count() const { return uint32_t(X.size() / 3); }
    uint32_t tet_count() const { return uint32_t(volume.size()); }
};

struct BodyState {
    std::vector<double> x;         // 3 per node: positions at the current time (m)
    std::vector<double> v_half;    // 3 per node: velocity of the last step, (x^n - x^n-1)/h;
                                   // the synchronized velocity itself when h_last == 0
    std::vector<double> elastic;   // 3 per node: elastic force -f_int at x (N)
    std::vector<float> tet_rotation; // 4 per tet (w,x,y,z): warm start of the corotational
                                     // rotations (float: a start, not a result); empty for
                                     // the other models
    std::vector<double> contact_force; // 3 per node: contact force of the last step (N);
                                       // empty while the body touches nothing
    double h_last = 0;             // size of the last step (s); 0 = no step since a reset
    double strain_energy = 0;      // J, at x
    double stiffening = 1;         // neo-Hookean: how much stiffer the stiffest tet is at x than
                                   // at rest (>= 1; neo_hookean_tangent.h); 1 for the others
    double rotation[4] = {1, 0, 0, 0}; // paper model: global rotation (quaternion w,x,y,z)
    double angular_momentum[3] = {0, 0, 0}; // paper model: L of eq. (2) about the COM
    double center[3] = {0, 0, 0};  // kinematic bodies: current centre; rigid: centre of mass
    double velocity[3] = {0, 0, 0}; // rigid bodies: velocity of the centre over the last step
    std::vector<double> shape_pose;  // 7 per rigid shape: its current placement
};

struct Body {
    uint32_t generation = 0;
    lfem_body_def def{};
    Lame lame;
    BodyReference ref;
    BodyState state;
    std::vector<NodeMode> node_mode;          // per node
    std::vector<double> prescribed_velocity;  // 3 per node, empty until first prescribed
    std::vector<double> node_force;           // 3 per node, empty until a force is set
    std::vector<RigidShape> shapes;           // rigid shapes (static and kinematic bodies)

    bool is_deformable() const { return def.type == LFEM_BODY_DEFORMABLE; }
    bool is_rigid() const { return def.type == LFEM_BODY_RIGID; }
    bool is_dynamic() const { return is_deformable() || is_rigid(); }  // moved by forces
    bool has_mesh() const { return !ref.X.empty(); }  // tets, or a static triangle surface
    bool has_geometry() const { return has_mesh() || !shapes.empty(); }
};

}  // namespace lfem
