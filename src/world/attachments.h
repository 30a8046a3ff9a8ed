// Attachments: nodes of a deformable body held at fixed offsets in the frame of a target, a
// rigid, kinematic or static body or a frame the caller moves (an animated bone, a hand), by
// the links of the multiplier solve (contact/link_constraint.h). They live in the world's state
// (world_state.h), in generation-checked slots like the bodies, so a step that fails rolls
// them back and checkpoints keep them.
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
    std::vector<uint32_t> nodes;     // the held nodes (the body's internal numbering)
    std::vector<double> offsets;     // 3 per node: where each is held, in the target's frame
    std::vector<double> lambda;      // 3 per node: the last multipliers (N), the next warm start
    double frame_start[7] = {0, 0, 0, 1, 0, 0, 0};  // the caller's frame (centre, quaternion
    double frame_end[7] = {0, 0, 0, 1, 0, 0, 0};    // w x y z) at the start and the end of the
                                                    // next call: moved uniformly in between
    double break_force = 0;          // N: it breaks when the total force exceeds it (0: never)
    double force[3] = {0, 0, 0};     // N: the total force on the nodes at the last sub-step
};

struct Attachments {
    std::vector<Attachment> slots;
    std::vector<uint32_t> free_slots;
};

}  // namespace lfem
