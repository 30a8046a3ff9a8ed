// What one sub-step's pipeline (substep.cpp) keeps beside the bodies' states: per slot, the
// step's start and tallies; the lists of bodies each stage concerns; the attachments' links.
// Rebuilt every sub-step, never rolled back or saved.
#pragma once

#include <cstdint>
#include <vector>

#include "common/math.h"
#include "common/thread_pool.h"
#include "contact/contact_body.h"
#include "contact/detect_node_triangle.h"
#include "contact/link_constraint.h"
#include "fem/central_difference.h"

namespace lfem {

// What a sub-step adds to the world's energy bookkeeping (per body, then summed).
struct SubstepTally {
    double kinetic = 0;       // J, of the new mid-step velocities
    double work = 0;          // J, of gravity, node forces and supports over the step
    double contact_work = 0;  // J, of the contact forces on moving nodes (<= 0 when passive)
    double damping = 0;       // J, removed by damping over the step
    double drift = 0;         // rad, eq. (2) rotation against the re-fitted one
};

// One body's scratch of the sub-step.
struct BodyScratch {
    StepStart start;                       // deformable: x^n, v^{n-1/2}, 1/mhat, supports
    std::vector<double> x_start;           // rigid and kinematic: x^n
    std::vector<double> shape_pose_start;  // kinematic: the shapes' placements at the start
    Vec3 center_start = Vec3::Zero();      // "paper": centre of mass at x^n; rigid: the centre
    Vec3 torque = Vec3::Zero();            // "paper": torque of the step about center_start
    RigidResponse rigid;                   // rigid: the contact solve's response
    SubstepTally tally;
    bool touched = false;                  // in contact this sub-step
    double load_motion = 0;                // m: how far gravity and node forces move a free node
                                           // in the sub-step (the contact solve's scale at rest)
    uint64_t phase_ticks[3] = {0, 0, 0};   // side by side: its commit, rotation, forces (ticks())
};

// The bodies each stage concerns, in slot order, sorted once per sub-step.
struct StageLists {
    std::vector<uint32_t> deformable, rigid, kinematic, paper, with_geometry;
    // The deformable bodies again, by how their loops run: one after another with the pool
    // for their own loops, or side by side on the pool, one body per task.
    std::vector<uint32_t> on_pool, side_by_side;
    ThreadPool* pool = nullptr;  // the sub-step's pool: none for a world too small to share
};

struct Pipeline {
    std::vector<BodyScratch> bodies;  // per slot
    // Per slot: h_mid (mid_step) of a body stepped in this sub-step, the interval over which its
    // forces change its velocities (predictor, contact response, the events' impulses); 0 for a
    // body not stepped. The one place it is computed (plan_stages).
    std::vector<double> h_mid;
    StageLists stages;
    std::vector<LinkRecord> links;  // the attachments' links of the sub-step
    double frame_fraction = 1;      // how far through the call the sub-step ends
    bool first_substep = true;      // the call's first sub-step (a force for one call, plan_stages)
    FallenIn fallen;                // by the sub-step's detection
    bool unconverged = false;       // the sub-step's contact solve used every sweep
};

}  // namespace lfem
