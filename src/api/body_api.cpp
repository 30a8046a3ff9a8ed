// C shim of bodies: every pointer, number, index and handle is checked here before
// lfem::World sees it; nothing changes unless every check passed. Node and tet indices and
// per-node arrays cross in the caller's numbering and are translated here to the body's
// internal order (BodyReference::numbering, mesh/node_ordering.h).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "api/definitions.h"
#include "api/handles.h"
#include "api/node_lists.h"

using namespace lfem;
using namespace lfem::api;

namespace lfem::api {

void check_body_def(const lfem_body_def& d) {
    require(d.internal_value == body_def_cookie,
            "def was not initialised by lfem_body_def_default()");
    require(d.type == LFEM_BODY_DEFORMABLE || d.type == LFEM_BODY_STATIC ||
                d.type == LFEM_BODY_KINEMATIC || d.type == LFEM_BODY_RIGID,
            "def->type " + std::to_string(int(d.type)) + " is not a body type");
    require(d.model == LFEM_MODEL_PAPER || d.model == LFEM_MODEL_COROTATIONAL ||
                d.model == LFEM_MODEL_NEO_HOOKEAN || d.model == LFEM_MODEL_LINEAR,
            "def->model " + std::to_string(int(d.model)) + " is not a material model");
    require(std::isfinite(d.young_modulus) && d.young_modulus > 0.0,
            "def->young_modulus must be finite and > 0 Pa");
    require(std::isfinite(d.poisson_ratio) && d.poisson_ratio > -1.0 && d.poisson_ratio < 0.5,
            "def->poisson_ratio must lie in (-1, 0.5)");
    require(std::isfinite(d.density) && d.density > 0.0, "def->density must be finite and > 0 kg/m^3");
    require(std::isfinite(d.damping) && d.damping >= 0.0, "def->damping must be finite and >= 0 1/s");
    require(std::isfinite(d.friction) && d.friction >= 0.0, "def->friction must be finite and >= 0");
    require_finite(d.linear_velocity, 3, "def->linear_velocity");
    require_finite(d.angular_velocity, 3, "def->angular_velocity");
    require(d.self_contact <= 1, "def->self_contact must be 0 or 1, got " + std::to_string(int(d.self_contact)));
    require(d.enable_sleep <= 1, "def->enable_sleep must be 0 or 1, got " + std::to_string(int(d.enable_sleep)));
    require(d.report_contacts <= 1,
            "def->report_contacts must be 0 or 1, got " + std::to_string(int(d.report_contacts)));
    require(d.edge_contacts <= 1, "def->edge_contacts must be 0 or 1, got " + std::to_string(int(d.edge_contacts)));
    require(d.composite_tets <= 1, "def->composite_tets must be 0 or 1, got " + std::to_string(int(d.composite_tets)));
    require(d.self_contact == 0 || d.type == LFEM_BODY_DEFORMABLE,
            "def->self_contact needs a deformable body (the others keep their shape)");
}

}  // namespace lfem::api

namespace {

void require_capacity(uint32_t capacity, uint32_t needed, const char* what) {
    if (capacity < needed)
        throw Error(Status::buffer_too_small, std::string(what) + " capacity " + std::to_string(capacity) +
                                               " is below the " + std::to_string(needed) + " needed");
}

// A query of one value of a body: the handle, then the output pointer, then the value.
template <class T, class Read>
lfem_status read_body(const char* function, const lfem_world* world, lfem_body body, T* out, const Read& read) {
    return guard(function, [&] {
        const Body& b = world_of(world).body(from_c(body));
        require_pointer(out, "out");
        *out = read(b);
    });
}

// The arrays of a mesh as the caller gives them: positions (3 finite doubles per node, at least
// min_nodes nodes) and elements (at least one); the mesh itself is checked by the world.
void check_mesh_arrays(const double* positions, uint32_t node_count, uint32_t min_nodes, const uint32_t* elements,
                       const char* elements_name, uint32_t element_count, const char* count_name) {
    require_pointer(positions, "positions");
    require_pointer(elements, elements_name);
    require(node_count >= min_nodes, "node_count must be >= " + std::to_string(min_nodes));
    require(element_count >= 1, std::string(count_name) + " must be >= 1");
    require_finite(positions, 3 * std::size_t(node_count), "positions");
}

// A tet mesh of nodes_per_tet nodes a tet (4, or 10) for a body.
lfem_status add_tet_mesh(const char* function, lfem_world* world, lfem_body body, const double* positions,
                         uint32_t node_count, const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet) {
    return guard(function, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        check_mesh_arrays(positions, node_count, nodes_per_tet, tets, "tets", tet_count, "tet_count");
        w.add_mesh(from_c(body), positions, node_count, tets, tet_count, nodes_per_tet);
    });
}

void require_deformable(const Body& b, const char* what) {
    require(b.is_deformable(), std::string(what) + " needs a deformable body");
}

// Fixing, prescribing (at `velocity`) or releasing nodes of a deformable body.
lfem_status set_node_mode(const char* function, lfem_world* world, lfem_body body, const uint32_t* nodes,
                          uint32_t count, NodeMode mode, const char* what, const double* velocity = nullptr) {
    return guard(function, [&] {
        World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_deformable(b, what);
        const std::vector<uint32_t> internal = internal_nodes(b, nodes, count);
        if (mode == NodeMode::prescribed) {
            require_pointer(velocity, "velocity");
            require_finite(velocity, 3, "velocity");
        }
        w.set_node_mode(from_c(body), internal.data(), count, mode, velocity);
    });
}

}  // namespace

extern "C" {

LFEM_API lfem_body_def lfem_body_def_default(void) {
    lfem_body_def d{};
    d.type = LFEM_BODY_DEFORMABLE;
    d.model = LFEM_MODEL_PAPER;
    d.young_modulus = 1e6;
    d.poisson_ratio = 0.3;
    d.density = 1000.0;
    d.damping = 0.0;
    d.friction = 0.5;
    d.category_bits = 1u;
    d.mask_bits = 0xFFFFFFFFu;
    d.user_data = nullptr;
    d.enable_sleep = 1;
    d.edge_contacts = 1;
    d.internal_value = body_def_cookie;
    return d;
}

LFEM_API lfem_status lfem_body_create(lfem_world* world, const lfem_body_def* def, lfem_body* out) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        require_pointer(def, "def");
        require_pointer(out, "out");
        check_body_def(*def);
        *out = to_c(w.create_body(to_body_def(*def)));
    });
}

LFEM_API lfem_status lfem_body_destroy(lfem_world* world, lfem_body body) {
    return guard(__func__, [&] { world_of(world).destroy_body(from_c(body)); });
}

LFEM_API int lfem_body_is_valid(const lfem_world* world, lfem_body body) {
    return world != nullptr && world->world.is_valid(from_c(body)) ? 1 : 0;
}

LFEM_API lfem_status lfem_body_add_mesh(lfem_world* world, lfem_body body, const double* positions,
                                        uint32_t node_count, const uint32_t* tets, uint32_t tet_count) {
    return add_tet_mesh(__func__, world, body, positions, node_count, tets, tet_count, 4);
}

LFEM_API lfem_status lfem_body_add_quadratic_mesh(lfem_world* world, lfem_body body, const double* positions,
                                                  uint32_t node_count, const uint32_t* tets, uint32_t tet_count) {
    return add_tet_mesh(__func__, world, body, positions, node_count, tets, tet_count, 10);
}

LFEM_API lfem_status lfem_body_add_triangle_mesh(lfem_world* world, lfem_body body, const double* positions,
                                                 uint32_t node_count, const uint32_t* triangles,
                                                 uint32_t triangle_count) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        check_mesh_arrays(positions, node_count, 3, triangles, "triangles", triangle_count, "triangle_count");
        w.add_triangle_mesh(from_c(body), positions, node_count, triangles, triangle_count);
    });
}

LFEM_API lfem_status lfem_body_get_node_count(const lfem_world* world, lfem_body body, uint32_t* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return b.node_count(); });
}

LFEM_API lfem_status lfem_body_get_tet_count(const lfem_world* world, lfem_body body, uint32_t* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return b.tet_count(); });
}

LFEM_API lfem_status lfem_body_get_nodes_per_tet(const lfem_world* world, lfem_body body, uint32_t* out) {
    return read_body(__func__, world, body, out,
                     [](const Body& b) { return b.tet_count() ? b.nodes_per_tet() : uint32_t(0); });
}

LFEM_API lfem_status lfem_body_get_user_data(const lfem_world* world, lfem_body body, void** out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return b.user_data(); });
}

LFEM_API lfem_status lfem_body_get_mass(const lfem_world* world, lfem_body body, double* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return b.mass(); });
}

LFEM_API lfem_status lfem_body_get_added_mass(const lfem_world* world, lfem_body body, double* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return b.added_mass(); });
}

LFEM_API lfem_status lfem_body_get_inversion(const lfem_world* world, lfem_body body, uint32_t* inverted_tets,
                                             double* min_jacobian, double* inverted_for) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Inversion inv = w.inversion(w.body(from_c(body)));
        if (inverted_tets) *inverted_tets = inv.inverted_tets;
        if (min_jacobian) *min_jacobian = inv.min_jacobian;
        if (inverted_for) *inverted_for = inv.inverted_for;
    });
}

LFEM_API lfem_status lfem_body_get_momentum(const lfem_world* world, lfem_body body, double linear[3],
                                            double angular[3]) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        Vec3 P, L;
        w.body_momentum(w.body(from_c(body)), P, L);
        for (int k = 0; k < 3; ++k) {
            if (linear) linear[k] = P[k];
            if (angular) angular[k] = L[k];
        }
    });
}

LFEM_API lfem_status lfem_body_get_positions(const lfem_world* world, lfem_body body, double* out,
                                             uint32_t node_capacity) {
    return guard(__func__, [&] {
        const Body& b = world_of(world).body(from_c(body));
        require_pointer(out, "out");
        require_capacity(node_capacity, b.node_count(), "node");
        b.numbering().nodes_to_api(b.positions(), b.node_count(), out);
    });
}

LFEM_API lfem_status lfem_body_get_velocities(const lfem_world* world, lfem_body body, double* out,
                                              uint32_t node_capacity) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(out, "out");
        require_capacity(node_capacity, b.node_count(), "node");
        std::vector<double> v(3 * std::size_t(b.node_count()));  // internal order
        w.synchronized_velocities(b, v.data());
        b.numbering().nodes_to_api(v.data(), b.node_count(), out);
    });
}

LFEM_API lfem_status lfem_body_set_velocities(lfem_world* world, lfem_body body, const double* velocities,
                                              uint32_t node_count) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require(b.is_deformable() || (b.is_rigid() && b.has_mesh()),
                "setting node velocities needs a deformable body or a rigid body with a mesh");
        require_pointer(velocities, "velocities");
        require(node_count == b.node_count(),
                "node_count " + std::to_string(node_count) + " differs from the body's " +
                    std::to_string(b.node_count()));
        require_finite(velocities, 3 * std::size_t(node_count), "velocities");
        std::vector<double> v(3 * std::size_t(b.node_count()));  // internal order
        b.numbering().nodes_from_api(velocities, node_count, v.data());
        w.set_velocities(from_c(body), v.data());
    });
}

LFEM_API lfem_status lfem_body_set_positions(lfem_world* world, lfem_body body, const double* positions,
                                             uint32_t node_count) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_deformable(b, "setting node positions");
        require_pointer(positions, "positions");
        require(node_count == b.node_count(),
                "node_count " + std::to_string(node_count) + " differs from the body's " +
                    std::to_string(b.node_count()));
        require_finite(positions, 3 * std::size_t(node_count), "positions");
        std::vector<double> x(3 * std::size_t(b.node_count()));  // internal order
        b.numbering().nodes_from_api(positions, node_count, x.data());
        w.set_positions(from_c(body), x.data());
    });
}

LFEM_API lfem_status lfem_body_set_transform(lfem_world* world, lfem_body body, const double transform[7]) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        require_pose(transform, "transform");
        w.set_transform(from_c(body), transform);
    });
}

LFEM_API lfem_status lfem_body_apply_impulse(lfem_world* world, lfem_body body, const double point[3],
                                             const double impulse[3]) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        require_pointer(point, "point");
        require_pointer(impulse, "impulse");
        require_finite(point, 3, "point");
        require_finite(impulse, 3, "impulse");
        w.apply_impulse(from_c(body), point, impulse);
    });
}

LFEM_API lfem_status lfem_body_apply_force(lfem_world* world, lfem_body body, const double point[3],
                                           const double force[3]) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        require_pointer(point, "point");
        require_pointer(force, "force");
        require_finite(point, 3, "point");
        require_finite(force, 3, "force");
        w.apply_force(from_c(body), point, force);
    });
}

LFEM_API lfem_status lfem_body_get_user_id(const lfem_world* world, lfem_body body, uint64_t* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return b.user_id(); });
}

LFEM_API lfem_status lfem_body_get_transform(const lfem_world* world, lfem_body body, double out[7]) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(out, "out");
        w.body_transform(b, out);
    });
}

LFEM_API lfem_status lfem_body_get_center_of_mass(const lfem_world* world, lfem_body body, double out[3]) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(out, "out");
        const Vec3 c = w.body_center_of_mass(b);
        for (int k = 0; k < 3; ++k) out[k] = c[k];
    });
}

LFEM_API lfem_status lfem_body_get_boundary_triangle_count(const lfem_world* world, lfem_body body,
                                                           uint32_t* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return uint32_t(b.boundary_triangles().size() / 3); });
}

LFEM_API lfem_status lfem_body_get_boundary_triangles(const lfem_world* world, lfem_body body,
                                                      uint32_t* out, uint32_t triangle_capacity) {
    return guard(__func__, [&] {
        const Body& b = world_of(world).body(from_c(body));
        require_pointer(out, "out");
        const std::vector<uint32_t>& triangles = b.boundary_triangles();
        require_capacity(triangle_capacity, uint32_t(b.boundary_triangles().size() / 3), "triangle");
        for (std::size_t j = 0; j < triangles.size(); ++j) out[j] = b.numbering().api_node(triangles[j]);
    });
}

LFEM_API lfem_status lfem_body_get_boundary_face_count(const lfem_world* world, lfem_body body, uint32_t* out) {
    return read_body(__func__, world, body, out, [](const Body& b) { return uint32_t(b.boundary_faces().size() / b.nodes_per_face()); });
}

LFEM_API lfem_status lfem_body_get_boundary_faces(const lfem_world* world, lfem_body body, uint32_t* out,
                                                  uint32_t face_capacity) {
    return guard(__func__, [&] {
        const Body& b = world_of(world).body(from_c(body));
        require_pointer(out, "out");
        const std::vector<uint32_t>& faces = b.boundary_faces();
        require_capacity(face_capacity, uint32_t(faces.size() / b.nodes_per_face()), "face");
        for (std::size_t j = 0; j < faces.size(); ++j) out[j] = b.numbering().api_node(faces[j]);
    });
}

LFEM_API lfem_status lfem_body_get_von_mises_stress(const lfem_world* world, lfem_body body,
                                                    double* out, uint32_t tet_capacity) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(out, "out");
        require_capacity(tet_capacity, b.tet_count(), "tet");
        std::vector<double> stress(b.tet_count());  // all or nothing for out
        w.von_mises_stress(b, stress.data());
        b.numbering().tets_to_api(stress.data(), b.tet_count(), out);
    });
}

LFEM_API lfem_status lfem_body_get_rotation(const lfem_world* world, lfem_body body, double out[9]) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(out, "out");
        w.rotation_matrix(b, out);
    });
}

LFEM_API lfem_status lfem_body_find_nodes_in_box(const lfem_world* world, lfem_body body, const double lo[3],
                                                 const double hi[3], uint32_t* out, uint32_t capacity,
                                                 uint32_t* count) {
    return guard(__func__, [&] {
        const World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_pointer(lo, "lo");
        require_pointer(hi, "hi");
        require_pointer(count, "count");
        require(capacity == 0 || out != nullptr, "out is NULL with a non-zero capacity");
        require_finite(lo, 3, "lo");
        require_finite(hi, 3, "hi");
        const std::vector<uint32_t> found = w.nodes_in_box(b, lo, hi);
        *count = uint32_t(found.size());
        require_capacity(capacity, *count, "node");
        std::copy(found.begin(), found.end(), out);
    });
}

LFEM_API lfem_status lfem_body_fix_nodes(lfem_world* world, lfem_body body, const uint32_t* nodes,
                                         uint32_t count) {
    return set_node_mode(__func__, world, body, nodes, count, NodeMode::fixed, "fixing nodes");
}

LFEM_API lfem_status lfem_body_prescribe_node_velocity(lfem_world* world, lfem_body body,
                                                       const uint32_t* nodes, uint32_t count,
                                                       const double velocity[3]) {
    return set_node_mode(__func__, world, body, nodes, count, NodeMode::prescribed, "prescribing node velocities",
                         velocity);
}

LFEM_API lfem_status lfem_body_release_nodes(lfem_world* world, lfem_body body, const uint32_t* nodes,
                                             uint32_t count) {
    return set_node_mode(__func__, world, body, nodes, count, NodeMode::free, "releasing nodes");
}

LFEM_API lfem_status lfem_body_set_node_forces(lfem_world* world, lfem_body body, const uint32_t* nodes,
                                               uint32_t count, const double* forces) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        const Body& b = w.body(from_c(body));
        require_deformable(b, "node forces");
        const std::vector<uint32_t> internal = internal_nodes(b, nodes, count);
        require(count == 0 || forces != nullptr, "forces is NULL");
        require_finite(forces, 3 * std::size_t(count), "forces");
        w.set_node_forces(from_c(body), internal.data(), count, forces);
    });
}

LFEM_API lfem_status lfem_body_clear_node_forces(lfem_world* world, lfem_body body) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));
        w.clear_node_forces(from_c(body));
    });
}

LFEM_API lfem_status lfem_body_set_kinematic_velocity(lfem_world* world, lfem_body body,
                                                      const double linear[3], const double angular[3]) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        require(w.body(from_c(body)).is_kinematic(), "the body is not kinematic");
        require_pointer(linear, "linear");
        require_pointer(angular, "angular");
        require_finite(linear, 3, "linear");
        require_finite(angular, 3, "angular");
        w.set_kinematic_velocity(from_c(body), linear, angular);
    });
}

}  // extern "C"
