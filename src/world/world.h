// The world: bodies in generation-checked slots, the step pipeline and its statistics. This is
// the C++ object behind the opaque lfem_world; only src/api talks to it from the outside, after
// validating every argument.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_body.h"
#include "contact/contact_record.h"
#include "common/thread_pool.h"
#include "contact/detect_node_triangle.h"
#include "lfem.h"
#include "rigid/rigid_body.h"
#include "world/body.h"

namespace lfem {

struct WorldImage;

// The world's own scalars that a step changes (rolled back with the bodies).
struct WorldCounters {
    double time = 0;
    uint64_t steps = 0;
    double step_size = 0;
    uint32_t substeps_last_call = 0;
    double external_work = 0;      // J, since creation
    double dissipated_energy = 0;  // J, since creation
    double initial_energy = 0;     // J, kinetic energy given with meshes and by set_velocities
    double rotation_drift = 0;     // rad, last sub-step
    uint32_t solver_iterations = 0;  // contact solve of the last sub-step
    double solver_residual = 0;      // m
    double max_penetration = 0;      // m
    bool scan_overlaps = false;      // bodies were added: look for initial overlaps once
};

// What a sub-step adds to the world's energy bookkeeping (per body, then summed).
struct SubstepTally {
    double kinetic = 0;       // J, of the new mid-step velocities
    double work = 0;          // J, of gravity, node forces and supports over the step
    double contact_work = 0;  // J, of the contact forces on moving nodes (<= 0 when passive)
    double damping = 0;       // J, removed by damping over the step
    double drift = 0;         // rad, eq. (2) rotation against the re-fitted one
};

class World {
public:
    // Starts def.thread_count - 1 worker threads (joined by the destructor).
    explicit World(const lfem_world_def& def)
        : def_(def), pool_(new ThreadPool(def.thread_count)) {}

    const lfem_world_def& def() const { return def_; }
    void set_gravity(const double g[3]);
    void set_time_step(double h) { def_.time_step = h; }

    // Bodies. body() throws Error(LFEM_INVALID_HANDLE) for a stale, foreign or null handle.
    lfem_body create_body(const lfem_body_def& def);
    void destroy_body(lfem_body handle);
    bool is_valid(lfem_body handle) const;
    Body& body(lfem_body handle);
    const Body& body(lfem_body handle) const;
    uint32_t body_count() const;
    // Live bodies in slot order (the order every loop uses, so results are deterministic).
    template <class F>
    void for_each_body(F&& f) const {
        for (const Slot& s : slots_)
            if (s.body.generation != 0) f(s.body, uint32_t(&s - slots_.data()));
    }

    // Appends a checked mesh to a body (see lfem_body_add_mesh). All or nothing.
    void add_mesh(Body& body, const double* positions, uint32_t node_count, const uint32_t* tets,
                  uint32_t tet_count);
    // Gives a static or kinematic body a surface of triangles (no tets, no mass), e.g. terrain.
    void add_triangle_mesh(Body& body, const double* positions, uint32_t node_count,
                           const uint32_t* triangles, uint32_t triangle_count);
    // Gives a static or kinematic body a rigid shape at the given placement (7 doubles);
    // returns its index on the body.
    uint32_t add_shape(Body& body, const RigidShape& shape, const double pose[7]);
    // Overwrites velocities; the change of kinetic energy is booked as external work.
    void set_velocities(Body& body, const double* v);

    // Stable limit 2/omega_max over the deformable bodies, neo-Hookean ones at their current
    // shape (from the stiffening their last force computation estimated); +inf without any.
    double stable_step() const;
    // Advance by dt (see lfem_world_step; under the automatic step, retried with more
    // sub-steps when a body outruns its sub-step or blows up). Throws Error:
    // LFEM_INVALID_ARGUMENT when refused up front, LFEM_UNSTABLE after rolling back to the
    // state before the call.
    void step(double dt);

    // Takes over the definition, bodies, counters and contacts of a checkpoint (see
    // checkpoint.h); meant for a new world (the shim discards it if this throws).
    void restore(WorldImage&& image);

    lfem_world_stats stats() const;
    // Linear momentum and angular momentum about the origin of one body.
    void body_momentum(const Body& body, double linear[3], double angular[3]) const;
    // Synchronized velocities of a body at the current time, 3 per node.
    void synchronized_velocities(const Body& body, double* out) const;
    const WorldCounters& counters() const { return counters_; }
    // Time and counts per phase of the step, accumulated (see lfem_profile).
    const lfem_profile& profile() const { return profile_; }
    void reset_profile() { profile_ = lfem_profile{}; }
    // Pairs found by the last sub-step, in a fixed order (body_a, node, body_b); those with
    // active() are the contacts.
    const std::vector<ContactRecord>& contacts() const { return contacts_; }
    // The C record of a contact (handles, contact point, force).
    lfem_contact contact_as_c(const ContactRecord& c) const;

private:
    friend void save_checkpoint(const World& world, const std::string& path);
    struct Slot {
        Body body;  // generation 0 = free slot
    };
    // Per-slot arrays a sub-step needs beside the body state (not rolled back: rebuilt
    // every sub-step).
    struct StepScratch {
        std::vector<double> x_start, v_old, inv_mass, shape_pose_start;
        double support_work = 0;
        double support_torque[3] = {0, 0, 0};
        double torque[3] = {0, 0, 0};  // "paper": torque of the step about the start centre
        double center_start[3] = {0, 0, 0};  // "paper": centre of mass at the step's start
    };
    void substep(double h, double& kinetic, double& strain, double& work);
    // Sorts the deformable bodies with a mesh into on_pool_ and side_by_side_ (step.cpp),
    // once per sub-step.
    void plan_deformable_loops();
    // Calls work(slot, pool) for every deformable body with a mesh: the on_pool_ bodies one
    // after another with the pool for their own loops, the side_by_side_ ones side by side on
    // the pool with none. Each call may write only that body's state, scratch and tally.
    template <class Work>
    void for_each_deformable(const Work& work);
    void solve_contacts(double h);
    double step_velocity(uint32_t slot, uint32_t node, int axis, double h) const;

    lfem_world_def def_;
    std::vector<Slot> slots_;
    std::vector<uint32_t> free_slots_;
    WorldCounters counters_;
    lfem_profile profile_{};
    std::vector<ContactRecord> contacts_;
    std::vector<StepScratch> scratch_;
    std::vector<SubstepTally> tallies_;      // per slot, this sub-step's energy bookkeeping
    std::vector<uint8_t> touched_;           // per slot: in contact this sub-step
    std::vector<uint32_t> on_pool_;          // slots of the bodies that run their loops on the pool
    std::vector<uint32_t> side_by_side_;     // slots of the bodies run one per task
    std::vector<RigidResponse> rigid_responses_;  // per slot, rigid bodies only
    std::vector<ContactBody> contact_bodies_;
    std::vector<uint32_t> contact_body_of_slot_;
    std::vector<ContactRecord> detected_;
    DetectionScratch detection_;
    std::unique_ptr<ThreadPool> pool_;  // the step's parallel loops
};

}  // namespace lfem
