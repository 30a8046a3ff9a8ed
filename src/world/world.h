// The world: the bodies, the step pipeline and its statistics. This is the C++ object behind
// the opaque lfem_world; only src/api talks to it from the outside, after validating every
// argument and translating the caller's node numbering. Its jobs live in files of their own:
// body_registry.* (slots and handles), add_mesh.cpp (mesh ingestion), loads_and_supports.cpp
// (what the caller changes between steps), step.cpp (a call: sub-steps, roll-back, blow-up
// test), substep.cpp (the pipeline of one sub-step), statistics.cpp (energies, momenta,
// velocities).
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "common/cpu_dispatch.h"
#include "common/thread_pool.h"
#include "contact/contact_bodies.h"
#include "contact/detect_node_triangle.h"
#include "contact/solve_contact_multipliers.h"
#include "query/query_scene.h"
#include "world/body.h"
#include "contact/link_constraint.h"
#include "world/body_registry.h"
#include "world/world_state.h"

namespace lfem {

struct WorldImage;

// The deformable tets below which a sub-step runs on the calling thread alone.
constexpr uint64_t kPoolWork = 2048;

// One event of a call (lfem_event), with the world's handles.
struct StepEvent {
    EventType type = EventType::contact_begin;
    BodyHandle a{}, b{};
    AttachmentHandle attachment{};
    double normal_impulse = 0;  // N s
    double max_force = 0;       // N
};

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

class World {
public:
    // Starts def.thread_count - 1 worker threads (joined by the destructor). The kernels'
    // instruction-set variant is chosen here, once for the process (common/cpu_dispatch.h).
    explicit World(const WorldDef& def)
        : def_(def), pool_(new ThreadPool(def.thread_count)) { cpu_level(); }

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
    // Binds a render mesh (vertices in the body's rest frame, triangles checked by the caller)
    // to the body's tets (see lfem_body_add_skin); returns its index on the body.
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

    // ---- attachments (attachments.cpp); node indices internal, checked by the caller
    AttachmentHandle create_attachment(BodyHandle body, const std::vector<uint32_t>& nodes, BodyHandle target,
                                      const double frame[7], double break_force);
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

    // ---- events of the last call (events.cpp)
    const std::vector<StepEvent>& events() const { return events_; }

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
    // LFEM_INVALID_ARGUMENT when refused up front, LFEM_UNSTABLE after rolling back to the
    // state before the call.
    void step(double dt);

    // ---- what can be read (statistics.cpp)
    WorldTotals totals() const;
    // Adds the kinetic energy of one moving body (synchronized velocities) to sum, node by node.
    void add_kinetic_energy(const Body& body, double& sum) const;
    // Linear momentum and angular momentum about the origin of one body.
    void body_momentum(const Body& body, Vec3& linear, Vec3& angular) const;
    // Synchronized velocities of a body at the current time, 3 per node.
    void synchronized_velocities(const Body& body, double* out) const;
    const WorldCounters& counters() const { return state_.counters; }
    // Pairs found by the last sub-step, in a fixed order (body_a, node, body_b); those with
    // active() are the contacts.
    const std::vector<ContactRecord>& contacts() const { return state_.contacts; }
    // Time and counts per phase of the step, accumulated (see lfem_profile).
    const Profile& profile() const { return profile_; }
    void reset_profile() {
        profile_ = Profile{};
        queries_.reset_counts();
    }
    void clear_warnings() { state_.counters.warnings = Warnings{}; }

    // ---- queries (queries.cpp): reads of the current geometry through a cache of their own
    // (query/query_scene.h), which no step reads. Each query is a const call that updates the
    // cache: not to be made from two threads at once.
    bool cast_ray(const QueryRay& ray, const QueryFilter& filter, RayHit& out) const;
    void cast_ray_all(const QueryRay& ray, const QueryFilter& filter, std::vector<RayHit>& out) const;
    void overlap_box(const Aabb& box, const QueryFilter& filter, std::vector<uint32_t>& slots) const;
    const QueryCounts& query_counts() const { return queries_.counts(); }
    void reset_query_counts() { queries_.reset_counts(); }

    // ---- checkpoints (checkpoint.h)
    const WorldState& state() const { return state_; }
    // Takes over the definition, bodies, counters and contacts of a checkpoint; meant for a new
    // world (the shim discards it if this throws).
    void restore(WorldImage&& image);

private:
    // What a sub-step adds to the world's energy bookkeeping (per body, then summed).
    struct SubstepTally {
        double kinetic = 0;       // J, of the new mid-step velocities
        double work = 0;          // J, of gravity, node forces and supports over the step
        double contact_work = 0;  // J, of the contact forces on moving nodes (<= 0 when passive)
        double damping = 0;       // J, removed by damping over the step
        double drift = 0;         // rad, eq. (2) rotation against the re-fitted one
    };
    // Per-slot arrays a sub-step needs beside the body state (not rolled back: rebuilt every
    // sub-step).
    struct StepScratch {
        StepStart start;                       // deformable: x^n, v^{n-1/2}, 1/mhat, supports
        std::vector<double> x_start;           // rigid and kinematic: x^n
        std::vector<double> shape_pose_start;  // kinematic: the shapes' placements at the start
        Vec3 center_start = Vec3::Zero();      // "paper": centre of mass at x^n; rigid: the centre
        Vec3 torque = Vec3::Zero();            // "paper": torque of the step about center_start
        RigidResponse rigid;                   // rigid: the contact solve's response
        SubstepTally tally;
        bool touched = false;                  // in contact this sub-step
        uint64_t phase_ticks[3] = {0, 0, 0};   // side by side: its commit, rotation, forces (ticks())
    };
    // The bodies each stage concerns, in slot order, sorted once per sub-step.
    struct StageLists {
        std::vector<uint32_t> deformable, rigid, kinematic, paper, with_geometry;
        // The deformable bodies again, by how their loops run: one after another with the pool
        // for their own loops, or side by side on the pool, one body per task.
        std::vector<uint32_t> on_pool, side_by_side;
        ThreadPool* pool = nullptr;  // the sub-step's pool: none for a world too small to share
        bool any_asleep = false;     // some body with geometry sleeps
    };
    struct Snapshot;

    // step.cpp: a call of lfem_world_step.
    uint32_t substeps_for(double dt, double limit) const;
    double blow_up_energy_scale(double& start_energy);
    void finish_call(double dt);
    // substep.cpp: the pipeline of src/DESIGN.md section 1.
    void substep(double h, double& kinetic, double& strain, double& work);
    void plan_stages();
    template <class Work>
    void for_each_deformable(const Work& work);
    void predict(double h);
    void move_kinematic_bodies(double h);
    void detect();
    void solve(double h);
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
    void build_links(double fraction);
    void take_link_forces(double h);
    void finish_attachment_frames();
    void drop_attachments_of(uint32_t slot);
    // sleep.cpp
    void wake(uint32_t slot);
    void wake_touching(uint32_t slot);
    void wake_touched_sleepers();
    void update_sleep(double dt);
    // events.cpp
    void begin_call_events();
    void tally_contact_pairs(double h);  // also marks the bodies that touch, completes kept_offset_
    void finish_call_events();

    WorldDef def_;
    BodyRegistry bodies_;
    WorldState state_;
    Profile profile_{};
    // Sub-step scratch.
    std::vector<StepScratch> scratch_;
    StageLists stages_;
    ContactBodies contact_bodies_;
    std::vector<ContactRecord> detected_, frozen_;  // frozen_: pairs among sleeping bodies
    std::vector<RecordRun> detected_runs_;          // detected_'s runs of one pair of bodies
    FallenIn fallen_;           // by the sub-step's detection
    bool unconverged_ = false;  // the sub-step's contact solve used every sweep
    std::vector<LinkRecord> links_;  // the attachments' links of the sub-step
    double frame_fraction_ = 1;      // how far through the call the sub-step ends
    // Events: of the last call; gathered during the call (contact pairs' tallies, broken
    // attachments, sleep and wake); wake events of calls between steps, for the next call.
    struct PairTally {
        double impulse = 0, max_force = 0;
        double substep_force = 0;  // N, summed over the sub-step being tallied
        uint64_t last_substep = 0;
    };
    std::vector<StepEvent> events_, broken_, sleep_events_, pending_events_;
    std::unordered_map<uint64_t, PairTally> pair_tally_;
    std::vector<PairTally*> substep_pairs_;  // the pairs met in the sub-step being tallied
    uint64_t substep_serial_ = 0;
    std::vector<BodyPairForce> pair_forces_;  // the sub-step's solve's, for the tally
    // The contact list's deepest_kept_offset, from the solve and the frozen pairs after a
    // sub-step; known only from there to the next sub-step of the same attempt of a call (the
    // list changes between calls and on a retry).
    double kept_offset_ = 0;
    bool kept_offset_known_ = false;
    bool in_call_ = false;
    DetectionScratch detection_;
    ContactSolveScratch solve_scratch_;
    std::unique_ptr<ThreadPool> pool_;  // the step's parallel loops
    uint64_t revision_ = 1;             // moved by every change of positions or geometry
    mutable QueryScene queries_;        // the queries' cache (never read by a step)
};

}  // namespace lfem
