// Attachments: points of a deformable body (nodes, or points of its tets found once by position)
// held at fixed offsets in the frame of a target, a rigid, kinematic or static body or a frame
// the caller moves (an animated bone, a hand), or at the same material point of another
// deformable body; rigidly, or by a spring and damper. By the links of the multiplier solve
// (contact/link_constraint.h). They live in the world's state (world_state.h), in
// generation-checked slots like the bodies, so a step that fails rolls them back and checkpoints
// keep them.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

// The target of an attachment that is the caller's frame, not a body.
constexpr uint32_t kFrameTarget = UINT32_MAX;

struct Attachment {
    uint32_t generation = 0;         // 0: a free slot
    uint32_t body = 0;               // slot of the held (deformable) body
    uint32_t body_generation = 0;
    uint32_t target = kFrameTarget;  // slot of the target body, or kFrameTarget
    uint32_t target_generation = 0;
    // The held points: nodes_per_point nodes of the body each, with their weights (a node held
    // alone: one node of weight 1; a point of a tet: its nodes by the shape functions there).
    uint32_t nodes_per_point = 1;
    std::vector<uint32_t> nodes;     // the body's internal numbering
    std::vector<double> weights;
    // A deformable target: each point's nodes of the target and their weights (empty otherwise).
    uint32_t target_nodes_per_point = 0;
    std::vector<uint32_t> target_nodes;
    std::vector<double> target_weights;
    std::vector<double> offsets;     // 3 per point: where each is held, in the target's frame
                                     // (unused for a deformable target)
    std::vector<double> lambda;      // 3 per point: the last multipliers (N), the next warm start
    std::vector<double> target_end;  // 3 per point: the target point where the last sub-step
                                     // left it (the damper's start of the next; kept only for
                                     // a damped spring)
    double stiffness = 0;            // N/m per point and axis; 0: rigid
    double damping = 0;              // N s/m per point and axis (with a stiffness)
    double frame_start[7] = {0, 0, 0, 1, 0, 0, 0};  // the caller's frame (centre, quaternion
    double frame_end[7] = {0, 0, 0, 1, 0, 0, 0};    // w x y z) at the start and the end of the
                                                    // next call: moved uniformly in between
    double break_force = 0;          // N: it breaks when the total force exceeds it (0: never)
    double force[3] = {0, 0, 0};     // N: the total force on the points at the last sub-step

    uint32_t point_count() const { return uint32_t(lambda.size() / 3); }
};

struct Attachments {
    std::vector<Attachment> slots;
    std::vector<uint32_t> free_slots;
};

}  // namespace lfem
