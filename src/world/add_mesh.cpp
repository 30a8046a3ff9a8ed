// Mesh ingestion: a body receives tets (or, static and kinematic bodies, a triangle surface or
// rigid shapes). Each call builds the new reference and state beside the old ones and swaps
// them in only at the end, so any failure (a bad mesh, out of memory) leaves the body
// untouched.
#include <algorithm>
#include <cmath>
#include <string>

#include "common/error.h"
#include "common/format.h"
#include "common/quadratic_tet_nodes.h"
#include "contact/hull_edges.h"
#include "fem/lumped_mass.h"
#include "fem/quadratic_tet.h"
#include "fem/stable_step.h"
#include "mesh/boundary.h"
#include "mesh/mesh_check.h"
#include "mesh/tet_geometry.h"
#include "rigid/global_rotation.h"
#include "world/world.h"

namespace lfem {
namespace {

// The body's mass and its first moments must be finite numbers.
void require_finite_mass(const std::vector<double>& mass, const std::vector<double>& X) {
    double total = 0.0, moment = 0.0;
    for (std::size_t i = 0; i < mass.size(); ++i) {
        total += mass[i];
        moment += mass[i] * (std::fabs(X[3 * i]) + std::fabs(X[3 * i + 1]) + std::fabs(X[3 * i + 2]));
    }
    if (!std::isfinite(total) || !std::isfinite(moment))
        throw Error(Status::invalid_mesh, "the body's mass overflows a double (density times volume, or "
                                              "times the distance from the origin)");
}

std::string number(double v) { return format_number(v, 3); }

// A curved 10-node tet must not fold over: det J > 0, and not flat (the linear tets' test,
// tet_geometry.h, with det J for 6 V), at each quadrature point and corner. The caller's
// numbering, as the other mesh checks.
void check_quadratic_jacobians(const double* positions, const uint32_t* tets, uint32_t tet_count) {
    for (uint32_t t = 0; t < tet_count; ++t) {
        const uint32_t* tet = tets + kQuadraticTetNodes * std::size_t(t);
        const double* x[4];
        for (int i = 0; i < 4; ++i) x[i] = positions + 3 * std::size_t(tet[i]);
        const double longest = tet_geometry::longest_edge(x[0], x[1], x[2], x[3]);
        const double smallest = smallest_jacobian(positions, tet);
        if (tet_geometry::is_flat(smallest, longest) || smallest < 0.0)
            throw Error(Status::invalid_mesh, "tet " + std::to_string(t) + " is curved so far that its map folds over "
                                           "(smallest det J of its quadrature points and corners " + number(smallest) +
                                           ", 6 V of its corners " +
                                           number(tet_geometry::six_volume(x[0], x[1], x[2], x[3])) +
                                           "): move its mid-edge nodes towards the middles of their edges");
    }
}

// The boundary of the new tets into the surface: their triangles, or for 10-node tets their
// 6-node faces and the 4 flat triangles of each (mesh/surface.h).
void append_boundary(BodyReference& ref, const uint32_t* new_tets, uint32_t tet_count) {
    Surface& surface = ref.surface;
    if (ref.nodes_per_tet == kQuadraticTetNodes) {
        const std::vector<uint32_t> faces = extract_quadratic_boundary(new_tets, tet_count);
        const std::vector<uint32_t> flat = split_quadratic_faces(faces);
        surface.quadratic_faces.insert(surface.quadratic_faces.end(), faces.begin(), faces.end());
        surface.triangles.insert(surface.triangles.end(), flat.begin(), flat.end());
    } else {
        const std::vector<uint32_t> boundary = extract_boundary_triangles(new_tets, tet_count);
        surface.triangles.insert(surface.triangles.end(), boundary.begin(), boundary.end());
    }
    compute_surface_data(ref.X.data(), ref.node_count(), surface);
}

// The reference data of the tets appended after the first old_tets (ref.tets holds them
// already; the per-tet arrays grow to match).
void append_reference_tets(BodyReference& ref, uint32_t old_tets, bool composite) {
    const uint32_t total = uint32_t(ref.tets.size() / ref.nodes_per_tet);
    if (ref.nodes_per_tet == kQuadraticTetNodes) {
        ref.Dm_inv.resize(9 * std::size_t(kQuadraturePoints) * total);
        ref.qp_volume.resize(std::size_t(kQuadraturePoints) * total);
        ref.volume.resize(total);
        add_quadratic_reference_tets(ref.X.data(), ref.tets.data(), old_tets, total, composite, ref.Dm_inv.data(),
                                     ref.qp_volume.data(), ref.volume.data());
    } else {
        ref.Dm_inv.resize(9 * std::size_t(total));
        ref.volume.resize(total);
        add_reference_tets(ref.X.data(), ref.tets.data(), old_tets, total, ref.Dm_inv.data(), ref.volume.data());
    }
}

}  // namespace

// A deformable body's stable step and, under mass scaling, the mass that the tets which would
// need a shorter step than the requested one get (all the body's, from their physical masses
// again: the stable limit is then at least mass_scaling_step / step_safety); then the total
// mass and the reference centre of mass. For a new mesh and a new material alike.
void fit_step_and_masses(const Body& body, const WorldDef& def, BodyReference& ref, ThreadPool* pool) {
    const uint32_t n = ref.node_count();
    if (body.is_deformable() && def.mass_scaling_step > 0.0) {
        std::vector<double> physical(n, 0.0);
        add_lumped_mass(ref.tets.data(), ref.volume.data(), 0, ref.tet_count(), body.def.density, physical.data(),
                        ref.nodes_per_tet);
        ElementMesh mesh = element_mesh(ref);
        mesh.mass = physical;
        const double omega_target = 2.0 * def.step_safety / def.mass_scaling_step;
        ref.stable_step =
            2.0 / scale_masses_for_step(mesh, body.lame(), body.def.density, omega_target, ref.mass.data(), pool).omega_max;
        ref.added_mass = 0.0;
        for (uint32_t i = 0; i < n; ++i) ref.added_mass += ref.mass[i] - physical[i];
        // A step far below the body's own stable step asks for masses beyond a double (found by
        // fuzz_api: the body then reported an infinite mass).
        if (!std::isfinite(ref.added_mass) || !std::isfinite(ref.stable_step))
            throw Error(Status::invalid_argument, "mass scaling to the world's step of " + number(def.mass_scaling_step) +
                                                      " s would add more mass to the body than a double holds");
        require_finite_mass(ref.mass, ref.X);
    } else if (body.is_deformable()) {
        ref.stable_step = 2.0 / estimate_stable_step(element_mesh(ref), body.lame(), pool).omega_max;
    }
    ref.total_mass = 0.0;
    for (double m : ref.mass) ref.total_mass += m;
    const Vec3 C = center_of_mass(ref.mass.data(), ref.X.data(), n);
    for (int k = 0; k < 3; ++k) ref.com[k] = C[k];
}

namespace {

// The body's reference with the new mesh appended, in the order of node_ordering.h (locality
// of the element loop): everything from here on sees the reordered mesh, the caller its own
// numbering. The reordered copies go as soon as they are appended (peak memory).
BodyReference append_reference(const Body& body, const double* positions, uint32_t node_count,
                               const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet,
                               const WorldDef& def, ThreadPool* pool) {
    BodyReference ref = body.ref;
    ref.nodes_per_tet = nodes_per_tet;
    const uint32_t old_nodes = ref.node_count(), old_tets = ref.tet_count();
    {
        LocalityOrder order = order_for_locality(positions, node_count, tets, tet_count, nodes_per_tet);
        ref.numbering.append(order, old_nodes, old_tets);
        ref.X.insert(ref.X.end(), order.positions.begin(), order.positions.end());
        ref.tets.reserve(ref.tets.size() + order.tets.size());
        for (uint32_t v : order.tets) ref.tets.push_back(v + old_nodes);
    }
    ref.mass.resize(ref.X.size() / 3, 0.0);
    append_boundary(ref, &ref.tets[std::size_t(nodes_per_tet) * old_tets], tet_count);
    append_reference_tets(ref, old_tets, body.def.composite_tets != 0);
    add_lumped_mass(ref.tets.data(), ref.volume.data(), old_tets, old_tets + tet_count, body.def.density,
                    ref.mass.data(), nodes_per_tet);
    const uint32_t n = ref.node_count();
    // Each tet's volume is finite (mesh_check), but density times a volume near the largest
    // double, summed, or its moments about the origin, may not be (found by fuzz_api).
    require_finite_mass(ref.mass, ref.X);
    derive_reference_data(body, ref);
    fit_step_and_masses(body, def, ref, pool);
    const Vec3 C(ref.com);
    if (body.is_rigid()) {
        // The inertia of the lumped masses about the centre of mass, in the reference frame.
        const Mat3 I = inertia_tensor(ref.mass.data(), ref.X.data(), n, C);
        if (!I.allFinite()) throw Error(Status::invalid_mesh, "the body's inertia overflows a double (mass times size squared)");
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) ref.inertia[3 * r + c] = I(r, c);
    }
    return ref;
}

// The body's state with the new nodes appended: existing nodes continue from their
// synchronized velocities, new ones get the def's; the kinetic energy they bring is added to
// *added_kinetic.
BodyState append_state(const World& world, const Body& body, const BodyReference& ref,
                       uint32_t old_nodes, const double* new_positions, double* added_kinetic) {
    const uint32_t n = ref.node_count();
    BodyState state = body.state;
    std::vector<double> v(3 * std::size_t(n), 0.0);
    if (old_nodes) world.synchronized_velocities(body, v.data());
    state.x.insert(state.x.end(), new_positions, new_positions + 3 * std::size_t(n - old_nodes));
    const Vec3 c = center_of_mass(ref.mass.data(), state.x.data(), n);
    const Vec3 lin(body.def.linear_velocity), ang(body.def.angular_velocity);
    for (uint32_t i = old_nodes; i < n; ++i) {
        const Vec3 r = Vec3(&state.x[3 * i]) - c;
        const Vec3 vi = lin + ang.cross(r);
        for (int k = 0; k < 3; ++k) v[3 * i + k] = vi[k];
        *added_kinetic += 0.5 * ref.mass[i] * vi.squaredNorm();
    }
    state.v_half = std::move(v);
    state.h_last = 0.0;
    state.elastic.assign(3 * std::size_t(n), 0.0);
    if (body.is_deformable() && body.def.model == Model::corotational) {
        const std::size_t per_tet = ref.rotations_per_tet();
        state.tet_rotation.resize(4 * per_tet * ref.tet_count(), 0.0f);
        for (std::size_t k = per_tet * body.ref.tet_count(); k < per_tet * ref.tet_count(); ++k)
            state.tet_rotation[4 * k] = 1.0f;
    }
    for (int k = 0; k < 3; ++k) state.global.center[k] = c[k];
    return state;
}

// The global motion of a new mesh, and its first elastic forces.
void start_motion(Body& candidate, BodyState& state, ThreadPool* pool) {
    const BodyReference& ref = candidate.ref;
    const uint32_t n = ref.node_count();
    const Vec3 c(state.global.center), C(ref.com);
    const Vec3 lin(candidate.def.linear_velocity), ang(candidate.def.angular_velocity);
    if (candidate.is_paper()) {
        // Frame: fit to the current nodes (identity for an undeformed new body); L of eq. (2)
        // from the nodes' velocities.
        Quat q = load_quaternion(state.global.rotation);
        fit_global_rotation(ref.mass.data(), state.x.data(), ref.X.data(), n, c, C, q);
        store_quaternion(q, state.global.rotation);
        const Vec3 L = angular_momentum(ref.mass.data(), state.x.data(), state.v_half.data(), n, c);
        for (int k = 0; k < 3; ++k) state.global.angular_momentum[k] = L[k];
    }
    if (candidate.is_deformable()) update_elastic_forces(candidate, state, pool);
    if (candidate.is_rigid()) {
        // The paper's global motion alone: centre of mass, rotation (identity: the reference
        // is the mesh as given) and angular momentum L = I omega of the def's spin.
        const Vec3 L = load_row_major(ref.inertia) * ang;
        for (int k = 0; k < 3; ++k) {
            state.global.center[k] = C[k];
            state.global.velocity[k] = lin[k];
            state.global.angular_momentum[k] = L[k];
        }
        store_quaternion(Quat::Identity(), state.global.rotation);
    }
}

}  // namespace

void derive_reference_data(const Body& body, BodyReference& ref) {
    ref.composite = body.def.composite_tets != 0;
    ref.colouring = colour_tets(ref);
    compute_node_triangles(ref.node_count(), ref.surface);
    compute_sharp_edges(ref.X.data(), ref.surface);
    compute_triangle_elements(ref.tets.data(), ref.tet_count(), ref.nodes_per_tet, ref.surface);
    if (body.is_deformable())
        compute_node_elements(ref.tets.data(), ref.tet_count(), ref.nodes_per_tet, ref.node_count(), ref.surface);
    ref.every_node.clear();
    if (body.is_deformable())
        for (uint32_t i = 0; i < ref.node_count(); ++i) ref.every_node.push_back(i);
    ref.bvh = TriangleBvh{};
    ref.face_normals.clear();
    if (body.def.type != BodyKind::static_body) return;
    // Never moves: its tree and its faces' normals are made once, here (as contact would make
    // them at every sub-step: the same bits).
    ref.bvh.build(ref.X.data(), ref.surface.triangles.data(), ref.surface.triangle_count());
    ref.face_normals.assign(3 * std::size_t(ref.surface.triangle_count()), 0.0);
    for (uint32_t t = 0; t < ref.surface.triangle_count(); ++t) {
        const Vec3 n = unit_triangle_normal(ref.X.data(), &ref.surface.triangles[3 * std::size_t(t)]);
        for (int k = 0; k < 3; ++k) ref.face_normals[3 * std::size_t(t) + k] = n[k];
    }
}

void World::add_mesh(BodyHandle handle, const double* positions, uint32_t node_count, const uint32_t* tets,
                     uint32_t tet_count, uint32_t nodes_per_tet) {
    Body& body = bodies_.get(handle);
    check_tet_mesh(positions, node_count, tets, tet_count, nodes_per_tet);
    if (nodes_per_tet == kQuadraticTetNodes) check_quadratic_jacobians(positions, tets, tet_count);
    if (body.is_rigid() && body.has_mesh())
        throw Error(Status::invalid_argument, "a rigid body takes one mesh (give it all its parts at once)");
    if (body.ref.tet_count() > 0 && body.ref.nodes_per_tet != nodes_per_tet)
        throw Error(Status::invalid_argument, "the body has " + std::to_string(body.ref.nodes_per_tet) +
                                               "-node tets; a mesh of " + std::to_string(nodes_per_tet) +
                                               "-node tets cannot join them");
    const uint32_t old_nodes = body.ref.node_count();
    const uint32_t old_tets = body.ref.tet_count();
    if (uint64_t(old_nodes) + node_count > 0xFFFFFFF0ull || uint64_t(old_tets) + tet_count > 0xFFFFFFF0ull)
        throw Error(Status::invalid_argument, "the body would exceed 2^32 nodes or tets");

    Body candidate;
    candidate.def = body.def;
    candidate.ref = append_reference(body, positions, node_count, tets, tet_count, nodes_per_tet, def_, pool_.get());
    double added_kinetic = 0.0;
    BodyState state = append_state(*this, body, candidate.ref, old_nodes,
                                   &candidate.ref.X[3 * std::size_t(old_nodes)], &added_kinetic);
    const uint32_t n = candidate.ref.node_count();
    candidate.node_mode = body.node_mode;
    candidate.node_mode.resize(n, NodeMode::free);
    std::vector<double> prescribed = body.prescribed_velocity;
    if (!prescribed.empty()) prescribed.resize(3 * std::size_t(n), 0.0);
    std::vector<double> forces = body.node_force, call_forces = body.call_force, applied = body.applied_force;
    for (std::vector<double>* f : {&forces, &call_forces, &applied})
        if (!f->empty()) f->resize(3 * std::size_t(n), 0.0);  // the new nodes' are 0 in all three
    start_motion(candidate, state, pool_.get());
    // Commit: moves only from here on (no allocation, nothing can fail).
    body.ref = std::move(candidate.ref);
    body.state = std::move(state);
    body.node_mode = std::move(candidate.node_mode);
    body.prescribed_velocity = std::move(prescribed);
    body.node_force = std::move(forces);
    body.call_force = std::move(call_forces);
    body.applied_force = std::move(applied);
    if (body.is_dynamic()) state_.counters.initial_energy += added_kinetic;
    state_.counters.scan_overlaps = true;
    body.geometry_revision += 1;
    moved();
}

void World::add_triangle_mesh(BodyHandle handle, const double* positions, uint32_t node_count,
                              const uint32_t* triangles, uint32_t triangle_count) {
    Body& body = bodies_.get(handle);
    if (body.is_dynamic()) throw Error(Status::invalid_argument, "triangle meshes belong to static or kinematic bodies");
    if (body.has_mesh()) throw Error(Status::invalid_argument, "the body already has a mesh");
    // Each triangle: indices in range, three different nodes, an area above 1e-12 of its
    // longest edge squared (the same round-off argument as for tets).
    check_triangles(triangles, triangle_count, node_count, positions, "node", "nodes");
    BodyReference ref;
    ref.X.assign(positions, positions + 3 * std::size_t(node_count));
    ref.surface.triangles.assign(triangles, triangles + 3 * std::size_t(triangle_count));
    compute_surface_data(ref.X.data(), ref.node_count(), ref.surface);
    derive_reference_data(body, ref);
    BodyState state = body.state;
    state.x = ref.X;
    state.v_half.assign(ref.X.size(), 0.0);
    if (body.shapes.empty()) {  // kinematic pivot: the vertices' centroid
        Vec3 c = Vec3::Zero();
        for (uint32_t i = 0; i < node_count; ++i) c += Vec3(&positions[3 * i]);
        for (int k = 0; k < 3; ++k) state.global.center[k] = c[k] / node_count;
    }
    std::vector<NodeMode> modes(node_count, NodeMode::free);
    body.ref = std::move(ref);
    body.state = std::move(state);
    body.node_mode = std::move(modes);
    state_.counters.scan_overlaps = true;
    body.geometry_revision += 1;
    moved();
}

uint32_t World::add_shape(BodyHandle handle, const RigidShape& shape, const double pose[7]) {
    Body& body = bodies_.get(handle);  // a static or kinematic one (checked by the shim)
    RigidShape copy = shape;
    compute_hull_edges(copy);
    body.shapes.reserve(body.shapes.size() + 1);
    body.state.shape_pose.reserve(body.state.shape_pose.size() + 7);
    // Nothing below allocates: the body changes all at once.
    if (!body.has_geometry())
        for (int k = 0; k < 3; ++k) body.state.global.center[k] = pose[k];  // kinematic pivot
    body.shapes.push_back(std::move(copy));
    body.state.shape_pose.insert(body.state.shape_pose.end(), pose, pose + 7);
    body.geometry_revision += 1;
    moved();
    return uint32_t(body.shapes.size() - 1);
}

}  // namespace lfem
