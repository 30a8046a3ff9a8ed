#include "contact/contact_bodies.h"

namespace lfem {

void ContactBodies::clear(uint32_t slot_count) {
    bodies_.clear();
    body_of_slot_.assign(slot_count, UINT32_MAX);
    movable_ = 0;
    self_contact_ = 0;
    asleep_ = 0;
}

void ContactBodies::add(const ContactBodyInput& in) {
    const bool dynamic = in.type == BodyKind::deformable || in.type == BodyKind::rigid;
    ContactBody cb;
    cb.slot = in.slot;
    cb.identity = in.identity;
    cb.moves = in.type != BodyKind::static_body;
    cb.asleep = in.asleep;
    cb.surface_nodes = in.surface->nodes.data();
    cb.surface_node_count = uint32_t(in.surface->nodes.size());
    cb.node_triangle_begin = in.surface->node_triangle_begin.data();
    cb.node_triangles = in.surface->node_triangles.data();
    cb.sharp_edges = in.surface->sharp_edges.data();
    cb.sharp_edge_count = in.edge_contacts ? uint32_t(in.surface->sharp_edges.size() / 4) : 0;
    cb.fold_edges = in.surface->fold_edges.data();
    cb.triangle_edges = in.surface->triangle_edges.data();
    cb.fold_edge_count = in.edge_contacts ? uint32_t(in.surface->fold_edges.size() / 4) : 0;
    const bool has_elements = in.elements && in.surface->triangle_element.size() == in.surface->triangle_count();
    cb.elements = has_elements ? in.elements : nullptr;
    cb.element_stride = in.nodes_per_tet;
    cb.triangle_element = has_elements ? in.surface->triangle_element.data() : nullptr;
    const bool has_node_elements = has_elements && in.surface->node_element_begin.size() == std::size_t(in.node_count) + 1;
    cb.node_element_begin = has_node_elements ? in.surface->node_element_begin.data() : nullptr;
    cb.node_elements = has_node_elements ? in.surface->node_elements.data() : nullptr;
    cb.static_bvh = in.type == BodyKind::static_body ? in.static_bvh : nullptr;
    cb.face_normals = in.type == BodyKind::static_body ? in.face_normals : nullptr;
    cb.triangles = in.surface->triangles.data();
    cb.triangle_count = in.surface->triangle_count();
    const std::vector<uint32_t>& slaves = in.type == BodyKind::deformable ? *in.every_node
                                          : dynamic                      ? in.surface->nodes
                                                                         : in.surface->feature_nodes;
    cb.nodes = slaves.data();
    cb.node_count = uint32_t(slaves.size());
    cb.total_nodes = in.node_count;
    cb.x = in.x;
    cb.x_start = in.type == BodyKind::static_body ? in.x : in.x_start;
    cb.v_last = in.type == BodyKind::deformable ? in.v_last : nullptr;
    cb.inv_mass = in.type == BodyKind::deformable ? in.inv_mass : nullptr;
    cb.rigid = in.type == BodyKind::rigid ? in.rigid : nullptr;
    cb.friction = in.friction;
    cb.category = in.category;
    cb.mask = in.mask;
    cb.self_contact = in.self_contact && in.type == BodyKind::deformable && cb.triangle_count > 0;
    cb.edge_length = in.surface->edge_length;
    cb.load_motion = in.load_motion;
    cb.shapes = in.shapes;
    cb.shape_count = in.shape_count;
    cb.shape_pose = in.shape_pose;
    cb.shape_pose_start = in.type == BodyKind::kinematic ? in.shape_pose_start : in.shape_pose;
    body_of_slot_[in.slot] = uint32_t(bodies_.size());
    bodies_.push_back(cb);
    movable_ += dynamic;
    asleep_ += in.asleep;
    self_contact_ += cb.self_contact;
}

}  // namespace lfem
