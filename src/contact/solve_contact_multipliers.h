// The forward increment Lagrange multiplier solve (Carpenter, Taylor & Katona 1991): the
// multipliers of step n make the constraints hold at step n+1,
//   x^{n+1} = x* + Mhat^-1 G^T lambda,   Mhat = diag(m/h^2 + c/2h),
// found by projected Gauss-Seidel over the node-triangle pairs, with tension release
// (lambda_n >= 0) and Coulomb friction (eq. 7) in the same sweep.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "common/thread_pool.h"
#include "contact/contact_body.h"
#include "contact/contact_record.h"
#include "contact/link_constraint.h"
#include "common/profile.h"

namespace lfem {

// The arrays the solve reuses from sub-step to sub-step (for their capacity: no allocation per
// sub-step once they have grown), owned by the caller.
class ContactSolveScratch {
public:
    ContactSolveScratch();
    ~ContactSolveScratch();
    ContactSolveScratch(const ContactSolveScratch&) = delete;
    ContactSolveScratch& operator=(const ContactSolveScratch&) = delete;
    struct Arrays;
    Arrays& arrays() { return *arrays_; }

private:
    std::unique_ptr<Arrays> arrays_;
};

// The normal force the solve left between two bodies (for the events' tallies): the sum of
// the multipliers of their active pairs, added in list order.
struct BodyPairForce {
    uint32_t slot_a = 0, slot_b = 0;  // world slots, slot_a <= slot_b
    double force = 0;                 // N
    // The fastest approach among the pair's active records: the speed (m/s) at which the node
    // closed on the face along the normal before the solve, the node where the solve left it,
    // and the normal turned to point from slot_a toward slot_b.
    double approach_speed = 0;
    double point[3] = {0, 0, 0};
    double normal[3] = {0, 0, 0};
};

struct ContactSolveResult {
    uint32_t iterations = 0;
    double residual = 0;         // m, the largest change of a pair's gap or slip in the last sweep
    double max_penetration = 0;  // m, deepest remaining penetration (beyond kept offsets)
    bool converged = true;       // every group ended within its tolerance
    double deepest_kept_offset = 0;  // m, of the records as the solve left them (ContactRecord::kept_offset)
};

// `body_of_slot[s]` is the index in `bodies` of the body in world slot s; `runs` are the
// records' runs of one pair of bodies (detect_node_triangle gives them). Records carry warm
// start multipliers on entry and the converged ones (newtons) on exit; `x` of the bodies is
// moved from x* to x^{n+1}. Pairs linked through no movable body form groups that converge on
// their own, side by side on the pool (results independent of the thread count). A sweep after
// which no gap or slip of a group changed by more than the group's stopping tolerance ends its
// solve, or max_iterations sweeps: the tolerance is relative_tolerance times the larger of the
// largest relative motion of a pair of the group over a step of h (the relative velocity at
// the start of the step, times h) and the motion the loads give a free node of its bodies in the
// sub-step (ContactBody::load_motion), at least 1e-9 of its finest boundary edge. The result gives the
// iterations and residual of the slowest group. The attachments' links (link_constraint.h)
// are solved in the same sweeps, each in the group of its bodies; they carry their multipliers
// in and out like the records. pair_forces gets the force between every two bodies that touch
// (each pair once, group by group), taken by each group as it ends, like the deepest kept
// offset: the records are not read again on the calling thread. Adds its time to
// profile.normal_solve and, when a pair has friction, profile.friction.
ContactSolveResult solve_contact_multipliers(const std::vector<ContactBody>& bodies,
                                             const std::vector<uint32_t>& body_of_slot,
                                             std::vector<ContactRecord>& records, const std::vector<RecordRun>& runs,
                                             std::vector<LinkRecord>& links,
                                             uint32_t max_iterations, double relative_tolerance,
                                             double h, ContactSolveScratch& scratch, Profile& profile,
                                             std::vector<BodyPairForce>& pair_forces, ThreadPool* pool);

}  // namespace lfem
