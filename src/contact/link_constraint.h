// Attachments in the multiplier solve: a node of a deformable body held at a point of a target,
// eq. (4) as an equality, G x = x_node - x_target = 0, with three multipliers and no clamp
// (an attachment pulls as well as pushes; there is no tension release). The target is a point
// of a rigid body, which the solve moves too (two-way: a rope holds a weight and the weight
// swings the rope), or a point the solve does not move: a kinematic or static body's, or the
// caller's frame's. Solved in the same Gauss-Seidel sweeps as the contact pairs.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/constraint_point.h"
#include "contact/contact_body.h"

namespace lfem {

struct LinkRecord {
    uint32_t body_a = 0, node = 0;  // slot of the held node's body, the node
    uint32_t body_b = UINT32_MAX;   // slot of a rigid target body, or UINT32_MAX: the target
                                    // point does not move in the solve
    double target[3] = {0, 0, 0};   // m: the target point at the end of the step (a rigid
                                    // target's predicted one)
    double lambda[3] = {0, 0, 0};   // N: warm start in, the force on the node out
};

// The two points of a link, resolved once per solve.
struct LinkPair {
    PointRef node, target;
};

// The points of every link; pairs[k] refers into links[k] (keep both alive and unmoved).
void make_link_pairs(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     std::vector<LinkRecord>& links, std::vector<LinkPair>& pairs);

// Applies the link's warm-start multipliers.
void warm_start_link(const LinkRecord& link, LinkPair& pair);

// One Gauss-Seidel update of a link, axis by axis (a rigid target's response couples them):
// lambda_d <- lambda_d - r_d / H_d with r the node's offset from the target. Returns the
// largest move it made.
double update_link(LinkRecord& link, LinkPair& pair);

}  // namespace lfem
