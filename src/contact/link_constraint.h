// Attachments in the multiplier solve: a point of a deformable body (a node, or a point of one
// of its tets: the tet's nodes by their shape functions' weights) held at a point of a target,
// eq. (4) as an equality, G x = x_point - x_target = 0, with three multipliers and no clamp (an
// attachment pulls as well as pushes; there is no tension release). The target is a point of a
// rigid body, which the solve moves too (two-way: a rope holds a weight and the weight swings
// the rope), a point of another deformable body (its tet's nodes, weighted the same way), or a
// point the solve does not move: a kinematic or static body's, or the caller's frame's. Solved
// in the same Gauss-Seidel sweeps as the contact pairs.
//
// A compliant link is a spring of stiffness k with a damper c instead: its force at the end of
// the sub-step, lambda = -k r - c (r - r0) / h for the offset r = x_point - x_target (r0 at
// the start), is found by the same update with the compliance 1 / (k + c / h) added to the
// response (the implicit spring of the forward increment: stable at any stiffness).
#pragma once

#include <cstdint>
#include <vector>

#include "contact/constraint_point.h"
#include "contact/contact_body.h"

namespace lfem {

// The most nodes one side of a link joins: a 10-node tet's.
constexpr uint32_t kLinkNodes = 10;

// One side's nodes of a body and their weights (summing to 1): a node alone is one of weight 1.
struct LinkNodes {
    uint32_t node[kLinkNodes] = {};
    double weight[kLinkNodes] = {};
    uint32_t count = 0;
};

struct LinkRecord {
    uint32_t body_a = 0;            // slot of the held point's (deformable) body
    LinkNodes held;                 // the held point: sum of weight_k x_node_k
    uint32_t body_b = UINT32_MAX;   // slot of a rigid or deformable target body, or UINT32_MAX:
                                    // the target point does not move in the solve
    LinkNodes target_nodes;         // a deformable target: its point's nodes (count 0 otherwise)
    double target[3] = {0, 0, 0};   // m: the target point at the end of the step (a rigid
                                    // target's predicted one; unused for a deformable target)
    double compliance = 0;          // m/N: 1 / (k + c / h); 0 for a hard link
    double start_share = 0;         // (c / h) / (k + c / h): the weight of r0 (the damper's)
    double r0[3] = {0, 0, 0};       // m: the offset at the start of the sub-step
    double lambda[3] = {0, 0, 0};   // N: warm start in, the force on the held point out
};

// One side of a link as the solve moves it: its points and weights.
struct LinkSide {
    PointRef point[kLinkNodes];
    double weight[kLinkNodes] = {};
    uint32_t count = 0;

    Vec3 position() const {
        Vec3 p = weight[0] * point[0].position();
        for (uint32_t k = 1; k < count; ++k) p += weight[k] * point[k].position();
        return p;
    }
    double response(const Vec3& e) const {
        double H = weight[0] * weight[0] * point[0].response(e);
        for (uint32_t k = 1; k < count; ++k) H += weight[k] * weight[k] * point[k].response(e);
        return H;
    }
    double push(const Vec3& d) {
        double largest = 0.0;
        for (uint32_t k = 0; k < count; ++k) largest = std::max(largest, point[k].push(weight[k] * d));
        return largest;
    }
};

// The two sides of a link, resolved once per solve.
struct LinkPair {
    LinkSide node, target;
};

// The points of every link; pairs[k] refers into links[k] (keep both alive and unmoved).
void make_link_pairs(const std::vector<ContactBody>& bodies, const std::vector<uint32_t>& body_of_slot,
                     std::vector<LinkRecord>& links, std::vector<LinkPair>& pairs);

// Applies the link's warm-start multipliers.
void warm_start_link(const LinkRecord& link, LinkPair& pair);

// One Gauss-Seidel update of a link, axis by axis (a rigid target's response couples them):
// lambda_d <- lambda_d - (r_d + compliance lambda_d - start_share r0_d) / (H_d + compliance),
// with r the held point's offset from the target (a hard link: -r_d / H_d). Returns the
// largest move it made.
double update_link(LinkRecord& link, LinkPair& pair);

}  // namespace lfem
