// The world: it keeps the bodies and runs the stages of a step in order. Each stage owns its
// state: the contact stage (contact/contact_stage.h) what contact keeps between sub-steps, the
// event log (event_log.h) what the events gather during a call, the pipeline (pipeline.h) the
// sub-step's scratch; the world keeps what a roll-back restores (the bodies and WorldState).
// Only src/api talks to it from the outside, after validating every argument and translating
// the caller's node numbering. Its jobs live in files of their own: body_registry.* (slots and
// handles), add_mesh.cpp (mesh ingestion), loads_and_supports.cpp (what the caller changes
// between steps), attachments.cpp, sleep.cpp, step.cpp (a call: sub-steps, roll-back, blow-up
// test), substep.cpp (the pipeline of one sub-step), statistics.cpp and body_reads.cpp (what
// can be read), queries.cpp.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "common/cpu_dispatch.h"
#include "common/profile.h"
#include "common/thread_pool.h"
#include "contact/contact_stage.h"
#include "query/query_scene.h"
#include "world/body.h"
#include "world/body_registry.h"
#include "world/definitions.h"
#include "world/event_log.h"
#include "world/pipeline.h"
#include "world/world_state.h"

namespace lfem {

// The point of a body's surface nearest to a point (World::closest_surface_point).
struct SurfacePoint {
    Vec3 point = Vec3::Zero();  // m
    uint32_t triangle = 0;      // in the body's boundary triangle order
    double distance = 0;        // m
};

// What an attachment holds and to what (World::create_attachment): the body's nodes (internal
// numbering) or points by position (3 each), exactly one of the two non-empty; the target body
// or, for the null handle, the caller's frame; the break force (N, 0: never), and a spring's
// stiffness (N/m, 0: rigid) and damping (N s/m).
struct AttachmentSpec {
    std::vector<uint32_t> nodes;
    std::vector<double> points;
    BodyHandle target;
    double frame[7] = {0, 0, 0, 1, 0, 0, 0};
    double break_force = 0, stiffness = 0, damping = 0;
};

struct WorldImage;
struct CallAttempt;  // step.cpp

// The deformable tets below which a sub-step runs on the calling thread alone.
constexpr uint64_t kPoolWork = 2048;

// How far (in boundary edges) two parts of a self-contact body may close in one sub-step of
// the automatic step. Found by the bar-over-a-rod scene (tests/physics/test_self_contact.cpp):
// its tips meet at 5 m/s; locked edges appeared at 0.6 of an edge per sub-step, none at 0.4.
constexpr double kSelfContactMotion = 0.25;

// What the moving bodies add up to at the current time (synchronized velocities).
struct WorldTotals {
    double kinetic_energy = 0;  // J
    double strain_energy = 0;   // J
    Vec3 linear_momentum = Vec3::Zero();   // kg m/s
    Vec3 angular_momentum = Vec3::Zero();  // kg m^2/s, about the origin
    double energy_error = 0;    // J: kinetic + strain + dissipated - external work - initial
    double added_mass = 0;      // kg, by mass scaling
    uint32_t inverted_tets = 0; // of the deformable bodies, at x
    double min_jacobian = 1;    // their smallest volume ratio J at x
};

// A body's inversion as lfem_body_get_inversion reports it.
struct Inversion {
    uint32_t inverted_tets = 0;
    double min_jacobian = 1;
    double inverted_for = 0;  // s
};

class World {
public:
    // Starts def.thread_count - 1 worker threads (joined by the destructor). The kernels'
    // instruction-set variant is chosen here, once for the process (common/cpu_dispatch.h).
    explicit World(const WorldDef& def) : def_(def), pool_(new ThreadPool(def.thread_count)) { cpu_level(); }

    const WorldDef& def() const { return def_; }
    void set_gravity(const double g[3]);
    void set_time_step(double h) { def_.time_step = h; }

    // ---- bodies (body_registry.h); body() throws Error(Status::invalid_handle) for a bad handle
    BodyHandle create_body(const BodyDef& def) { return bodies_.create(def); }
    void destroy_body(BodyHandle handle);
    bool is_valid(BodyHandle handle) const { return bodies_.is_valid(handle); }
    const Body& body(BodyHandle handle) const { return bodies_.get(handle); }
    const BodyRegistry& bodies() const { return bodies_; }

    // ---- mesh ingestion (add_mesh.cpp); each all or nothing
    // Appends a checked tet mesh to a body (see lfem_body_add_mesh): tets of nodes_per_tet nodes,
    // 4 or 10 (lfem_body_add_quadratic_mesh), the same for every mesh of a body.
    void add_mesh(BodyHandle body, const double* positions, uint32_t node_count, const uint32_t* tets,
                  uint32_t tet_count, uint32_t nodes_per_tet = 4);
    // Gives a static or kinematic body a surface of triangles (no tets, no mass), e.g. terrain.
    void add_triangle_mesh(BodyHandle body, const double* positions, uint32_t node_count,
                           const uint32_t* triangles, uint32_t triangle_count);
    // Gives a static or kinematic body a rigid shape at the given placement (7 doubles);
    // returns its index on the body.
    uint32_t add_shape(BodyHandle body, const RigidShape& shape, const double pose[7]);
    // Binds a render mesh (vertices in the body's rest frame; its triangles checked as
    // mesh/mesh_check.h says) to the body's tets (see lfem_body_add_skin); returns its index on the body.
    uint32_t add_skin(BodyHandle body, const double* positions, uint32_t vertex_count, const uint32_t* triangles,
                      uint32_t triangle_count);

    // ---- loads and supports (loads_and_supports.cpp). Node indices are the body's own
    // (internal) numbering, checked by the caller: in range, no repeats.
    // Overwrites velocities (3 per node); the change of kinetic energy is booked as external work.
    void set_velocities(BodyHandle body, const double* v);
    void set_node_mode(BodyHandle body, const uint32_t* nodes, uint32_t count, NodeMode mode,
                       const double velocity[3] = nullptr);
    void set_node_forces(BodyHandle body, const uint32_t* nodes, uint32_t count, const double* forces);
    void clear_node_forces(BodyHandle body);
    void set_kinematic_velocity(BodyHandle body, const double linear[3], const double angular[3]);

    // ---- where a body is, and teleports (teleport.cpp)
    // The rigid motion x = R X + t that carries the mesh as added to the nodes now (7 doubles: t,
    // then R as a unit quaternion w x y z): a deformable body's best fit, the frame of the others.
    void body_transform(const Body& body, double out[7]) const;
    Vec3 body_center_of_mass(const Body& body) const;
    // Teleports: no work, velocities kept, the body's pairs end. set_positions: a deformable
    // body's nodes (3 per node, internal order, finite); set_transform: any body but a static
    // one, rigidly, to the pose given (7 finite doubles, the quaternion normalised).
    void set_positions(BodyHandle body, const double* x);
    void set_transform(BodyHandle body, const double transform[7]);
    // ---- settings changed after creation (body_settings.cpp); values checked by the caller
    void set_friction(BodyHandle body, double friction);
    void set_damping(BodyHandle body, double damping);
    // A deformable body's E and nu (not under mass scaling); the stable step follows.
    void set_material(BodyHandle body, double young_modulus, double poisson_ratio);
    void set_user_data(BodyHandle body, void* user_data);
    void set_user_id(BodyHandle body, uint64_t user_id);
    void set_sleep_allowed(BodyHandle body, bool allowed);
    void set_type(BodyHandle body, BodyKind type);  // body_type.cpp
    void set_filter(BodyHandle body, uint32_t category_bits, uint32_t mask_bits);
    // Later skins' indices move down by one.
    void remove_skin(BodyHandle body, uint32_t skin);
    // ---- impulses (impulses.cpp): a deformable or rigid body with a mesh; point and impulse
    // finite (checked by the caller)
    void apply_impulse(BodyHandle body, const double point[3], const double impulse[3]);
    void apply_force(BodyHandle body, const double point[3], const double force[3]);

    // ---- attachments (attachments.cpp); node indices internal, checked by the caller
    AttachmentHandle create_attachment(BodyHandle body, const AttachmentSpec& spec);
    void destroy_attachment(AttachmentHandle attachment);
    bool is_valid(AttachmentHandle attachment) const;
    // Throws Error(Status::invalid_handle) for a bad handle.
    const Attachment& attachment(AttachmentHandle attachment) const;
    void set_attachment_frame(AttachmentHandle attachment, const double frame[7]);

    // ---- sleeping (sleep.cpp)
    void wake_body(BodyHandle body) {
        this->body(body);  // the handle first
        wake(body.index);
    }
    bool is_awake(const Body& b) const { return b.state.asleep == 0; }

    // ---- events of the last call (event_log.h)
    const std::vector<StepEvent>& events() const { return events_.events(); }

    // ---- stepping (step.cpp, substep.cpp)
    // Stable limit 2/omega_max over the deformable bodies, neo-Hookean ones at their current
    // shape (from the stiffening their last force computation estimated); +inf without any.
    double stable_step() const;
    // The automatic step's bound for bodies with self-contact: their parts may close by at most
    // kSelfContactMotion of an edge per sub-step (node-to-face contact catches a node that
    // crosses a face; two parts meeting edge-first with more motion per step than that can
    // lock their edges past each other before any node crosses). +inf without such a body.
    double self_contact_step() const;
    // Advance by dt (see lfem_world_step; under the automatic step, retried with more
    // sub-steps when a body outruns its sub-step or blows up). Throws Error:
    // Status::invalid_argument when refused up front, Status::unstable after rolling back to
    // the state before the call.
    void step(double dt);

    // ---- what can be read (statistics.cpp, body_reads.cpp)
    WorldTotals totals() const;
    // Adds the kinetic energy of one moving body (synchronized velocities) to sum, node by node.
    void add_kinetic_energy(const Body& body, double& sum) const;
    // Linear momentum and angular momentum about the origin of one body.
    void body_momentum(const Body& body, Vec3& linear, Vec3& angular) const;
    // Synchronized velocities of a body at the current time, 3 per node.
    void synchronized_velocities(const Body& body, double* out) const;
    // Per tet, in the body's internal order: the von Mises stress (Pa; 0 for a body that is not
    // deformable).
    void von_mises_stress(const Body& body, double* out) const;
    // The body's rotation as a row-major matrix: its frame's for rigid, kinematic and "paper"
    // bodies, the identity for the others.
    void rotation_matrix(const Body& body, double out[9]) const;
    Inversion inversion(const Body& body) const;
    // The caller's indices (ascending) of the nodes inside the box [lo, hi] (bounds included).
    std::vector<uint32_t> nodes_in_box(const Body& body, const double lo[3], const double hi[3]) const;
    const WorldCounters& counters() const { return state_.counters; }
    // Pairs found by the last sub-step, in a fixed order (body_a, node, body_b); those with
    // active() are the contacts.
    const std::vector<ContactRecord>& contacts() const { return state_.contacts; }
    // Time and counts per phase of the step, accumulated (see lfem_profile).
    const Profile& profile() const { return profile_; }
    void reset_profile() {
        profile_ = Profile{};
        queries_.scene.reset_counts();
    }
    void clear_warnings() { state_.counters.warnings = Warnings{}; }

    // ---- queries (queries.cpp): reads of the current geometry through a cache of their own
    // (query/query_scene.h), which no step reads. Each query is a const call that updates the
    // cache: not to be made from two threads at once.
    bool cast_ray(const QueryRay& ray, const QueryFilter& filter, RayHit& out) const;
    void cast_ray_all(const QueryRay& ray, const QueryFilter& filter, std::vector<RayHit>& out) const;
    void overlap_box(const Aabb& box, const QueryFilter& filter, std::vector<uint32_t>& slots) const;
    void overlap_capsule(const QueryCapsule& capsule, const QueryFilter& filter, std::vector<Overlap>& out) const;
    bool cast_sphere(const QueryRay& ray, double radius, const QueryFilter& filter, RayHit& out) const;
    const QueryCounts& query_counts() const { return queries_.scene.counts(); }
    // The point of the body's boundary triangles nearest to a point (a body with triangles).
    SurfacePoint closest_surface_point(const Body& body, const double point[3]) const;

    // ---- checkpoints (checkpoint.h)
    const WorldState& state() const { return state_; }
    // Takes over the definition, bodies, counters and contacts of a checkpoint; meant for a new
    // world (the shim discards it if this throws).
    void restore(WorldImage&& image);

private:
    class CallGuard;  // step.cpp
    // The queries' cache and the revision of positions and geometry it was made for.
    struct QueryCache {
        uint64_t revision = 1;  // moved by every change of positions or geometry
        QueryScene scene;
    };

    // step.cpp: a call of lfem_world_step.
    double step_limit() const;
    uint32_t substeps_for(double dt, double limit) const;
    double blow_up_energy_scale(double& start_energy);
    CallAttempt run_substeps(uint32_t substeps, double h, double limit, double start_energy, double scale);
    void finish_call(double dt);
    // substep.cpp: the pipeline of src/DESIGN.md section 2.
    void substep(double h, double& kinetic, double& strain, double& work);
    void plan_stages(double h);
    template <class Work>
    void for_each_deformable(const Work& work);
    void predict(double h);
    void move_kinematic_bodies(double h);
    void detect();
    void solve(double h);
    void mark_touching(const ContactOutcome& outcome);
    void commit_rotate_and_load(double h);  // commit, rotation update, element forces
    void commit_rigid_bodies(double h);
    void body_commit(uint32_t slot, double h, ThreadPool* pool);
    void body_rotation(uint32_t slot, double h, ThreadPool* pool);
    void body_forces(uint32_t slot, ThreadPool* pool);
    void add_up_energy(double h, double& kinetic, double& strain, double& work);
    void count_warnings(double h);
    // Positions or geometry may have changed: the queries' cache is stale. After a step (with
    // the pool), once queries are in use, it is made current at once, so that a query pays
    // only for what it meets; if that runs out of memory it throws (the step rolls back) and
    // leaves the cache stale for every revision.
    void moved(ThreadPool* pool = nullptr);
    // attachments.cpp
    void build_links(double fraction, double h);
    Vec3 link_target_end(const LinkRecord& link) const;
    void take_link_forces(double h);
    void finish_attachment_frames();
    void drop_call_forces();
    void drop_attachments_of(uint32_t slot);
    void reframe_attachments(uint32_t slot, const Vec3& c_was, const Quat& q_was);
    // teleport.cpp
    void place_deformable(BodyHandle body, const double* x, const Quat& turn);
    void end_contacts_of(uint32_t slot);
    // statistics.cpp
    Vec3 rigid_velocity(const Body& body, Vec3& V, Vec3& omega) const;
    // sleep.cpp
    void wake(uint32_t slot);
    void wake_touching(uint32_t slot);
    void wake_touched_sleepers();
    void update_sleep(double dt);

    WorldDef def_;
    BodyRegistry bodies_;
    WorldState state_;        // what a step changes beside the bodies (counters, contacts, ...)
    Profile profile_{};
    Pipeline pipeline_;       // the sub-step's scratch
    ContactStage contact_;
    EventLog events_;
    std::unique_ptr<ThreadPool> pool_;  // the step's parallel loops
    mutable QueryCache queries_;        // never read by a step
};

}  // namespace lfem
