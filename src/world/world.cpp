// Body slots, mesh insertion and the statistics of a world. The step itself is in step.cpp.
#include "world/world.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>

#include "common/error.h"
#include "fem/internal_forces.h"
#include "fem/element_colouring.h"
#include "fem/stable_step.h"
#include "fem/tet_element.h"
#include "mesh/boundary.h"
#include "mesh/mesh_check.h"
#include "rigid/global_rotation.h"
#include "rigid/rigid_body.h"
#include "world/checkpoint.h"

namespace lfem {
namespace {

// Generations come from one process-wide counter, so a handle of another world (foreign) can
// never match a slot's generation in this one: it is detected like a stale handle.
std::atomic<uint32_t> g_next_generation{1};

uint32_t next_generation() {
    uint32_t g = g_next_generation.fetch_add(1, std::memory_order_relaxed);
    if (g == 0) g = g_next_generation.fetch_add(1, std::memory_order_relaxed);  // wrapped
    return g;
}

// From the boundary triangles: the boundary nodes (contact slaves), the mean edge length
// (contact tolerances) and the feature nodes.
void compute_surface_data(BodyReference& ref) {
    std::vector<uint8_t> on_boundary(ref.X.size() / 3, 0);
    double edges = 0.0;
    for (std::size_t t = 0; t < ref.boundary.size(); t += 3)
        for (int v = 0; v < 3; ++v) {
            const uint32_t i = ref.boundary[t + v], j = ref.boundary[t + (v + 1) % 3];
            on_boundary[i] = 1;
            edges += (Vec3(&ref.X[3 * i]) - Vec3(&ref.X[3 * j])).norm();
        }
    ref.edge_length = edges / double(ref.boundary.size());
    ref.boundary_nodes.clear();
    for (uint32_t i = 0; i < on_boundary.size(); ++i)
        if (on_boundary[i]) ref.boundary_nodes.push_back(i);
    // Feature nodes: where the surface bends by more than 15 degrees (edges, corners). A
    // node inside a flat face of an immovable body adds nothing the other body's nodes do
    // not already enforce, and as a second, redundant support it makes the load jump
    // between the two from step to step (a soft cube resting on a floor shook at 1e-4 m/s
    // with them, 2e-6 m/s without).
    std::vector<double> normal(ref.X.size(), 0.0), face(3 * (ref.boundary.size() / 3));
    for (std::size_t t = 0; t < ref.boundary.size(); t += 3) {
        const uint32_t* f = &ref.boundary[t];
        const Vec3 n = (Vec3(&ref.X[3 * f[1]]) - Vec3(&ref.X[3 * f[0]]))
                           .cross(Vec3(&ref.X[3 * f[2]]) - Vec3(&ref.X[3 * f[0]]));
        for (int k = 0; k < 3; ++k) face[t + k] = n[k];
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k) normal[3 * f[v] + k] += n[k];
    }
    std::vector<uint8_t> feature(on_boundary.size(), 0);
    const double cos15 = std::cos(15.0 * 3.14159265358979323846 / 180.0);
    for (std::size_t t = 0; t < ref.boundary.size(); t += 3)
        for (int v = 0; v < 3; ++v) {
            const uint32_t i = ref.boundary[t + v];
            if (Vec3(&normal[3 * i]).normalized().dot(Vec3(&face[t]).normalized()) < cos15)
                feature[i] = 1;
        }
    ref.feature_nodes.clear();
    for (uint32_t i = 0; i < feature.size(); ++i)
        if (feature[i]) ref.feature_nodes.push_back(i);
}

}  // namespace

void World::restore(WorldImage&& image) {
    std::vector<Slot> slots(image.bodies.size());
    uint32_t highest = 0;
    for (std::size_t i = 0; i < slots.size(); ++i) {
        highest = std::max(highest, image.bodies[i].generation);
        slots[i].body = std::move(image.bodies[i]);
        BodyReference& ref = slots[i].body.ref;
        ref.colouring = colour_element_blocks(ref.tets.data(), ref.tet_count(), ref.node_count());
    }
    def_ = image.def;
    slots_ = std::move(slots);
    free_slots_ = std::move(image.free_slots);
    counters_ = image.counters;
    contacts_ = std::move(image.contacts);
    // Bodies created from now on get generations above the loaded ones, so that no handle of
    // a destroyed body can become valid again.
    uint32_t next = g_next_generation.load(std::memory_order_relaxed);
    while (next <= highest &&
           !g_next_generation.compare_exchange_weak(next, highest + 1, std::memory_order_relaxed)) {
    }
}

void World::set_gravity(const double g[3]) {
    for (int k = 0; k < 3; ++k) def_.gravity[k] = g[k];
}

lfem_body World::create_body(const lfem_body_def& def) {
    uint32_t index;
    if (!free_slots_.empty()) {
        index = free_slots_.back();
    } else {
        slots_.emplace_back();  // may throw bad_alloc before anything changed
        index = uint32_t(slots_.size() - 1);
    }
    Body body;
    body.def = def;
    body.lame = lame_from_young_poisson(def.young_modulus, def.poisson_ratio);
    body.generation = next_generation();
    if (!free_slots_.empty() && free_slots_.back() == index) free_slots_.pop_back();
    slots_[index].body = std::move(body);
    return lfem_body{index, slots_[index].body.generation};
}

bool World::is_valid(lfem_body h) const {
    return h.generation != 0 && h.index < slots_.size() &&
           slots_[h.index].body.generation == h.generation;
}

Body& World::body(lfem_body h) {
    return const_cast<Body&>(static_cast<const World&>(*this).body(h));
}

const Body& World::body(lfem_body h) const {
    if (h.generation == 0 && h.index == 0) throw Error(LFEM_INVALID_HANDLE, "null body handle");
    if (!is_valid(h))
        throw Error(LFEM_INVALID_HANDLE, "body handle {" + std::to_string(h.index) + ", " +
                                             std::to_string(h.generation) +
                                             "} is stale or belongs to another world");
    return slots_[h.index].body;
}

void World::destroy_body(lfem_body h) {
    Body& b = body(h);
    free_slots_.reserve(free_slots_.size() + 1);  // the only allocation: before any change
    b = Body{};                                   // generation 0: the slot is free
    free_slots_.push_back(h.index);
    // The body's contacts go with it: a query must not read its freed nodes, and a later body
    // in the same slot must not be warm-started from them (found by fuzz_api).
    contacts_.erase(std::remove_if(contacts_.begin(), contacts_.end(),
                                   [&](const ContactRecord& r) {
                                       return r.body_a == h.index || r.body_b == h.index;
                                   }),
                    contacts_.end());
}

uint32_t World::body_count() const {
    uint32_t n = 0;
    for_each_body([&](const Body&, uint32_t) { ++n; });
    return n;
}

void World::add_mesh(Body& body, const double* positions, uint32_t node_count,
                     const uint32_t* tets, uint32_t tet_count) {
    check_tet_mesh(positions, node_count, tets, tet_count);
    if (body.is_rigid() && body.has_mesh())
        throw Error(LFEM_INVALID_ARGUMENT, "a rigid body takes one mesh (give it all its parts at once)");
    const uint32_t old_nodes = body.ref.node_count();
    const uint32_t old_tets = body.ref.tet_count();
    if (uint64_t(old_nodes) + node_count > 0xFFFFFFF0ull ||
        uint64_t(old_tets) + tet_count > 0xFFFFFFF0ull)
        throw Error(LFEM_INVALID_ARGUMENT, "the body would exceed 2^32 nodes or tets");

    // Build the new reference and state beside the old ones; swap them in only at the end, so
    // any failure (a bad mesh, out of memory) leaves the body untouched.
    BodyReference ref = body.ref;
    {
        // The body keeps the new nodes and tets in the order of node_ordering.h (locality of
        // the element loop); everything below sees the reordered mesh, the caller its own
        // numbering. The reordered copies go as soon as they are appended (peak memory).
        LocalityOrder order = order_for_locality(positions, node_count, tets, tet_count);
        ref.numbering.append(order, old_nodes, old_tets);
        ref.X.insert(ref.X.end(), order.positions.begin(), order.positions.end());
        ref.tets.reserve(ref.tets.size() + order.tets.size());
        for (uint32_t v : order.tets) ref.tets.push_back(v + old_nodes);
    }
    const double* new_positions = &ref.X[3 * std::size_t(old_nodes)];
    const uint32_t* new_tets = &ref.tets[4 * std::size_t(old_tets)];
    ref.mass.resize(ref.X.size() / 3, 0.0);
    std::vector<uint32_t> boundary = extract_boundary_triangles(new_tets, tet_count);
    ref.boundary.insert(ref.boundary.end(), boundary.begin(), boundary.end());
    compute_surface_data(ref);
    ref.Dm_inv.resize(9 * std::size_t(old_tets + tet_count));
    ref.volume.resize(old_tets + tet_count);
    const double rho = body.def.density;
    for (uint32_t e = old_tets; e < old_tets + tet_count; ++e) {
        const uint32_t* t = &ref.tets[4 * e];
        const double* X = ref.X.data();
        const Mat3 Dm = edge_matrix(X + 3 * t[0], X + 3 * t[1], X + 3 * t[2], X + 3 * t[3]);
        const double V = Dm.determinant() / 6.0;
        Eigen::Map<Mat3>(&ref.Dm_inv[9 * std::size_t(e)]) = Dm.inverse();
        ref.volume[e] = V;
        for (int a = 0; a < 4; ++a) ref.mass[t[a]] += rho * V / 4.0;  // lumped mass
    }
    const uint32_t n = ref.node_count();
    ref.total_mass = 0.0;
    for (double m : ref.mass) ref.total_mass += m;
    const Vec3 C = center_of_mass(ref.mass.data(), ref.X.data(), n);
    for (int k = 0; k < 3; ++k) ref.com[k] = C[k];
    ref.colouring = colour_element_blocks(ref.tets.data(), ref.tet_count(), n);
    if (body.is_deformable())
        ref.stable_step = 2.0 / estimate_stable_step(ref, body.lame, pool_.get()).omega_max;

    BodyState state = body.state;
    // Existing nodes continue from their synchronized velocities; new ones get the def's.
    std::vector<double> v(3 * std::size_t(n), 0.0);
    if (old_nodes) synchronized_velocities(body, v.data());
    state.x.insert(state.x.end(), new_positions, new_positions + 3 * std::size_t(node_count));
    const Vec3 c = center_of_mass(ref.mass.data(), state.x.data(), n);
    double added_kinetic = 0.0;
    const Vec3 lin(body.def.linear_velocity), ang(body.def.angular_velocity);
    for (uint32_t i = old_nodes; i < n; ++i) {
        const Vec3 r = Vec3(&state.x[3 * i]) - c;
        const Vec3 vi = lin + ang.cross(r);
        for (int k = 0; k < 3; ++k) v[3 * i + k] = vi[k];
        added_kinetic += 0.5 * ref.mass[i] * vi.squaredNorm();
    }
    state.v_half = std::move(v);
    state.h_last = 0.0;
    state.elastic.assign(3 * std::size_t(n), 0.0);
    if (body.is_deformable() && body.def.model == LFEM_MODEL_COROTATIONAL) {
        state.tet_rotation.resize(4 * std::size_t(ref.tet_count()), 0.0f);
        for (uint32_t e = old_tets; e < ref.tet_count(); ++e) state.tet_rotation[4 * e] = 1.0f;
    }
    for (int k = 0; k < 3; ++k) state.center[k] = c[k];

    std::vector<NodeMode> modes = body.node_mode;
    modes.resize(n, NodeMode::free);
    std::vector<double> prescribed = body.prescribed_velocity;
    if (!prescribed.empty()) prescribed.resize(3 * std::size_t(n), 0.0);
    std::vector<double> forces = body.node_force;
    if (!forces.empty()) forces.resize(3 * std::size_t(n), 0.0);

    Body candidate;
    candidate.def = body.def;
    candidate.lame = body.lame;
    candidate.ref = std::move(ref);
    candidate.node_mode = std::move(modes);
    if (candidate.is_deformable()) {
        if (candidate.def.model == LFEM_MODEL_PAPER) {
            // Frame: fit to the current nodes (identity for an undeformed new body); L of
            // eq. (2) from the nodes' velocities.
            Eigen::Quaterniond q(state.rotation[0], state.rotation[1], state.rotation[2],
                                 state.rotation[3]);
            fit_global_rotation(candidate.ref.mass.data(), state.x.data(), candidate.ref.X.data(),
                                n, c, C, q);
            state.rotation[0] = q.w(), state.rotation[1] = q.x(), state.rotation[2] = q.y(),
            state.rotation[3] = q.z();
            const Vec3 L =
                angular_momentum(candidate.ref.mass.data(), state.x.data(), state.v_half.data(), n, c);
            for (int k = 0; k < 3; ++k) state.angular_momentum[k] = L[k];
        }
        compute_elastic_forces(candidate, state, pool_.get());
    }
    if (candidate.is_rigid()) {
        // The paper's global motion alone: centre of mass, rotation (identity: the reference
        // is the mesh as given) and angular momentum L = I omega of the def's spin.
        rigid_reference_inertia(candidate.ref, candidate.ref.inertia);
        const Eigen::Matrix3d I = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(candidate.ref.inertia);
        const Vec3 L = I * ang;
        for (int k = 0; k < 3; ++k) {
            state.center[k] = C[k];
            state.velocity[k] = lin[k];
            state.angular_momentum[k] = L[k];
        }
        state.rotation[0] = 1.0, state.rotation[1] = state.rotation[2] = state.rotation[3] = 0.0;
    }
    // Commit: moves only from here on (no allocation, nothing can fail).
    body.ref = std::move(candidate.ref);
    body.state = std::move(state);
    body.node_mode = std::move(candidate.node_mode);
    body.prescribed_velocity = std::move(prescribed);
    body.node_force = std::move(forces);
    if (body.is_dynamic()) counters_.initial_energy += added_kinetic;
    counters_.scan_overlaps = true;
}

void World::add_triangle_mesh(Body& body, const double* positions, uint32_t node_count,
                              const uint32_t* triangles, uint32_t triangle_count) {
    if (body.is_dynamic())
        throw Error(LFEM_INVALID_ARGUMENT, "triangle meshes belong to static or kinematic bodies");
    if (body.has_mesh())
        throw Error(LFEM_INVALID_ARGUMENT, "the body already has a mesh");
    // Each triangle: indices in range, three different nodes, an area above 1e-12 of its
    // longest edge squared (the same round-off argument as for tets).
    for (uint32_t t = 0; t < triangle_count; ++t) {
        const uint32_t* f = &triangles[3 * t];
        for (int v = 0; v < 3; ++v)
            if (f[v] >= node_count)
                throw Error(LFEM_INVALID_MESH, "triangle " + std::to_string(t) + " has node index " +
                                                   std::to_string(f[v]) + ", beyond the " +
                                                   std::to_string(node_count) + " nodes");
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
            throw Error(LFEM_INVALID_MESH, "triangle " + std::to_string(t) + " repeats a node");
        const Vec3 a(&positions[3 * f[0]]), b(&positions[3 * f[1]]), c(&positions[3 * f[2]]);
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        if (!((b - a).cross(c - a).norm() > 1e-12 * longest * longest))
            throw Error(LFEM_INVALID_MESH, "triangle " + std::to_string(t) + " has no area");
    }
    BodyReference ref;
    ref.X.assign(positions, positions + 3 * std::size_t(node_count));
    ref.boundary.assign(triangles, triangles + 3 * std::size_t(triangle_count));
    compute_surface_data(ref);
    BodyState state = body.state;
    state.x = ref.X;
    state.v_half.assign(ref.X.size(), 0.0);
    if (body.shapes.empty()) {  // kinematic pivot: the vertices' centroid
        Vec3 c = Vec3::Zero();
        for (uint32_t i = 0; i < node_count; ++i) c += Vec3(&positions[3 * i]);
        for (int k = 0; k < 3; ++k) state.center[k] = c[k] / node_count;
    }
    std::vector<NodeMode> modes(node_count, NodeMode::free);
    body.ref = std::move(ref);
    body.state = std::move(state);
    body.node_mode = std::move(modes);
    counters_.scan_overlaps = true;
}

uint32_t World::add_shape(Body& body, const RigidShape& shape, const double pose[7]) {
    RigidShape copy = shape;
    body.shapes.reserve(body.shapes.size() + 1);
    body.state.shape_pose.reserve(body.state.shape_pose.size() + 7);
    // Nothing below allocates: the body changes all at once.
    if (!body.has_geometry())
        for (int k = 0; k < 3; ++k) body.state.center[k] = pose[k];  // kinematic pivot
    body.shapes.push_back(std::move(copy));
    body.state.shape_pose.insert(body.state.shape_pose.end(), pose, pose + 7);
    return uint32_t(body.shapes.size() - 1);
}

void World::set_velocities(Body& body, const double* v) {
    const uint32_t n = body.ref.node_count();
    double before = 0.0, after = 0.0;
    if (body.is_deformable()) {
        std::vector<double> old(3 * std::size_t(n));
        synchronized_velocities(body, old.data());
        for (uint32_t i = 0; i < n; ++i) {
            const double m = body.ref.mass[i];
            for (int k = 0; k < 3; ++k) {
                before += 0.5 * m * old[3 * i + k] * old[3 * i + k];
                after += 0.5 * m * v[3 * i + k] * v[3 * i + k];
            }
        }
    }
    std::copy(v, v + 3 * std::size_t(n), body.state.v_half.begin());
    body.state.h_last = 0.0;  // v_half now holds synchronized velocities
    if (body.is_deformable() && body.def.model == LFEM_MODEL_PAPER) {
        const Vec3 c = center_of_mass(body.ref.mass.data(), body.state.x.data(), n);
        const Vec3 L = angular_momentum(body.ref.mass.data(), body.state.x.data(), v, n, c);
        for (int k = 0; k < 3; ++k) body.state.angular_momentum[k] = L[k];
    }
    counters_.external_work += after - before;
}

double World::stable_step() const {
    double h = std::numeric_limits<double>::infinity();
    for_each_body([&](const Body& b, uint32_t) {
        if (!b.is_deformable() || !b.has_mesh()) return;
        // Neo-Hookean stiffness grows with deformation (a crushed tet is stiffer): the limit
        // at the current nodes. The reference limit already carries the 2 % margin on
        // omega^2 of its Lanczos estimate; only stiffening beyond it shortens the step. The
        // other models' stiffness does not depend on the state.
        // The estimate comes with the elastic forces at x (internal_forces.cpp).
        const double stiffening = b.state.stiffening / 1.02;
        h = std::min(h, b.ref.stable_step / std::sqrt(std::max(stiffening, 1.0)));
    });
    return h;
}

void World::synchronized_velocities(const Body& body, double* out) const {
    const BodyState& s = body.state;
    const uint32_t n = body.ref.node_count();
    if (body.is_rigid()) {
        Vec3 V, omega;
        rigid_synchronized_velocity(body, def_.gravity, V, omega);
        for (uint32_t i = 0; i < n; ++i) {
            const Vec3 v = V + omega.cross(Vec3(&s.x[3 * i]) - Vec3(s.center));
            for (int k = 0; k < 3; ++k) out[3 * i + k] = v[k];
        }
        return;
    }
    if (!body.is_deformable()) {
        // Static: at rest. Kinematic: rigid motion about the moving centre.
        const Vec3 lin(body.def.linear_velocity), ang(body.def.angular_velocity);
        for (uint32_t i = 0; i < n; ++i) {
            Vec3 v = Vec3::Zero();
            if (body.def.type == LFEM_BODY_KINEMATIC)
                v = lin + ang.cross(Vec3(&s.x[3 * i]) - Vec3(s.center));
            for (int k = 0; k < 3; ++k) out[3 * i + k] = v[k];
        }
        return;
    }
    const double h = s.h_last;
    const double* g = def_.gravity;
    const auto in_contact = [&](uint32_t i) {
        return !s.contact_force.empty() && (s.contact_force[3 * i] != 0.0 || s.contact_force[3 * i + 1] != 0.0 ||
                                            s.contact_force[3 * i + 2] != 0.0);
    };
    for (uint32_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) {
            double v = s.v_half[3 * i + k];
            switch (body.node_mode[i]) {
                case NodeMode::fixed: v = 0.0; break;
                case NodeMode::prescribed: v = body.prescribed_velocity[3 * i + k]; break;
                case NodeMode::free:
                    // A node pressed by a contact reports its last step's velocity: the
                    // half-step extrapolation would divide the step-to-step variation of the
                    // contact force (solver tolerance) by h and show jitter that is not there.
                    if (h > 0.0 && !(in_contact(i))) {
                        // v^n = v^{n-1/2} + h/2 a^n with m a^n = R^n - c v^n (central difference)
                        const double m = body.ref.mass[i];
                        double R = m * g[k] + s.elastic[3 * i + k];
                        if (!body.node_force.empty()) R += body.node_force[3 * i + k];
                        v = (2.0 * m / h * v + R) / (2.0 * m / h + body.def.damping * m);
                    }
                    break;
            }
            out[3 * i + k] = v;
        }
    }
}

lfem_world_stats World::stats() const {
    lfem_world_stats st{};
    st.time = counters_.time;
    st.steps = counters_.steps;
    st.step_size = counters_.step_size;
    st.stable_step = stable_step();
    st.substeps_last_call = counters_.substeps_last_call;
    st.body_count = body_count();
    st.external_work = counters_.external_work;
    st.dissipated_energy = counters_.dissipated_energy;
    st.rotation_drift = counters_.rotation_drift;
    for (const ContactRecord& r : contacts_) st.contact_count += r.active();
    st.solver_iterations = counters_.solver_iterations;
    st.solver_residual = counters_.solver_residual;
    st.max_penetration = counters_.max_penetration;
    std::vector<double> v;
    for_each_body([&](const Body& b, uint32_t) {
        if (!b.is_dynamic() || !b.has_mesh()) return;
        if (b.is_rigid()) {
            st.kinetic_energy += rigid_kinetic_energy(b);
            double P[3], L[3];
            body_momentum(b, P, L);
            for (int k = 0; k < 3; ++k) st.linear_momentum[k] += P[k], st.angular_momentum[k] += L[k];
            return;
        }
        v.resize(b.state.v_half.size());
        synchronized_velocities(b, v.data());
        for (uint32_t i = 0; i < b.ref.node_count(); ++i)
            st.kinetic_energy += 0.5 * b.ref.mass[i] * Vec3(&v[3 * i]).squaredNorm();
        double P[3], L[3];
        body_momentum(b, P, L);
        for (int k = 0; k < 3; ++k) {
            st.linear_momentum[k] += P[k];
            st.angular_momentum[k] += L[k];
        }
        st.strain_energy += b.state.strain_energy;
    });
    st.energy_error = st.kinetic_energy + st.strain_energy + st.dissipated_energy -
                      st.external_work - counters_.initial_energy;
    return st;
}

}  // namespace lfem

namespace lfem {

void World::body_momentum(const Body& b, double linear[3], double angular[3]) const {
    Vec3 P = Vec3::Zero(), L = Vec3::Zero();
    if (b.is_rigid() && b.has_mesh()) {
        Vec3 V, omega;
        const Vec3 L_centre = rigid_synchronized_velocity(b, def_.gravity, V, omega);
        P = b.ref.total_mass * V;
        L = Vec3(b.state.center).cross(P) + L_centre;
    } else if (b.is_deformable() && b.has_mesh()) {
        std::vector<double> v(b.state.v_half.size());
        synchronized_velocities(b, v.data());
        for (uint32_t i = 0; i < b.ref.node_count(); ++i) {
            const Vec3 vi(&v[3 * i]);
            P += b.ref.mass[i] * vi;
            L += b.ref.mass[i] * Vec3(&b.state.x[3 * i]).cross(vi);
        }
    }
    for (int k = 0; k < 3; ++k) linear[k] = P[k], angular[k] = L[k];
}

lfem_contact World::contact_as_c(const ContactRecord& c) const {
    lfem_contact out{};
    const Body& a = slots_[c.body_a].body;
    const Body& b = slots_[c.body_b].body;
    out.body_a = lfem_body{c.body_a, a.generation};
    out.body_b = lfem_body{c.body_b, b.generation};
    out.node = a.ref.numbering.api_node(c.node);  // the caller's numbering
    out.shape = c.shape;
    const double w[3] = {1.0 - c.t1 - c.t2, c.t2, c.t1};
    for (int k = 0; k < 3; ++k) {
        out.triangle[k] = c.shape != UINT32_MAX ? c.triangle[k] : b.ref.numbering.api_node(c.triangle[k]);
        out.normal[k] = c.normal[k];
        out.force[k] = c.lambda_n * c.normal[k] + c.lambda_t[k];
        if (c.shape != UINT32_MAX)
            out.position[k] = c.point_end[k];
        else
            for (int v = 0; v < 3; ++v) out.position[k] += w[v] * b.state.x[3 * c.triangle[v] + k];
    }
    out.barycentric[0] = c.t1;
    out.barycentric[1] = c.t2;
    out.sliding = c.sliding ? 1 : 0;
    return out;
}

}  // namespace lfem
