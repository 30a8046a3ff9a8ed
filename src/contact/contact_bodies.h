// The bodies of one contact stage: the world hands over each body's arrays and type, and this
// decides what contact makes of them (which nodes are slaves, which points can move), and maps
// the world's slots to them.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_body.h"
#include "contact/triangle_bvh.h"
#include "common/body_kind.h"
#include "mesh/surface.h"

namespace lfem {

// One body as the world has it during a sub-step, after the predictor.
struct ContactBodyInput {
    uint32_t slot = 0;                   // the body's slot in the world
    uint64_t identity = 0;               // changes whenever the body's geometry does
    const TriangleBvh* static_bvh = nullptr;  // static bodies: the tree of their triangles
    const double* face_normals = nullptr;     // static bodies: their unit face normals
    BodyKind type = BodyKind::static_body;  // a sleeping body's: static
    bool asleep = false;
    const Surface* surface = nullptr;    // its boundary (triangles, slave candidates)
    const uint32_t* elements = nullptr;  // the tets (nodes_per_tet each), nullptr without
    uint32_t nodes_per_tet = 4;
    const std::vector<uint32_t>* every_node = nullptr;  // 0 .. node_count - 1 (deformable bodies)
    uint32_t node_count = 0;
    double* x = nullptr;                 // 3 per node: predicted x* (the current x when static)
    const double* x_start = nullptr;     // 3 per node: x^n (unused for a static body)
    const double* v_last = nullptr;      // 3 per node: deformable bodies' v^{n-1/2}
    const double* inv_mass = nullptr;    // per node: deformable bodies' 1/mhat
    RigidResponse* rigid = nullptr;      // rigid bodies' response
    double friction = 0;
    uint32_t category = 1, mask = ~0u;
    bool self_contact = false;           // deformable bodies: the surface collides with itself
    bool edge_contacts = true;           // its sharp edges meet other bodies' (edge_edge.h)
    double load_motion = 0;              // m, see ContactBody::load_motion
    const RigidShape* shapes = nullptr;  // static and kinematic bodies
    uint32_t shape_count = 0;
    const double* shape_pose = nullptr;        // 7 per shape, end of the step
    const double* shape_pose_start = nullptr;  // 7 per shape, start (kinematic bodies)
};

class ContactBodies {
public:
    // Starts a new list for a world of slot_count slots.
    void clear(uint32_t slot_count);
    // Adds a body. Slave nodes: every node of a deformable body, its interior ones too (a body
    // folded or crushed through itself must not pass through another body with them), every
    // boundary node of a rigid one; only the edge and corner nodes of a static or kinematic
    // one, whose flat faces the other pass enforces. Only a deformable body's free nodes move alone; a rigid body's
    // move through its response; a static body's start is where it is.
    void add(const ContactBodyInput& input);

    const std::vector<ContactBody>& bodies() const { return bodies_; }
    // Index in bodies() of the body in a world slot (UINT32_MAX: not in contact).
    const std::vector<uint32_t>& body_of_slot() const { return body_of_slot_; }
    const ContactBody& of_slot(uint32_t slot) const { return bodies_[body_of_slot_[slot]]; }
    // Contact has work to do: two bodies, one of them moved by forces, or a body that meets
    // itself.
    bool may_touch() const { return movable_ > 0 && (bodies_.size() > 1 || self_contact_ > 0); }
    bool any_asleep() const { return asleep_ > 0; }

private:
    std::vector<ContactBody> bodies_;
    std::vector<uint32_t> body_of_slot_;
    uint32_t movable_ = 0, self_contact_ = 0, asleep_ = 0;
};

}  // namespace lfem
