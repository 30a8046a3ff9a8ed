// What a step changes beside the bodies' own states: the world's counters and the contact list
// (which also warm-starts the next solve). A roll-back restores it with the bodies' states; a
// checkpoint writes it with the bodies.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_record.h"

namespace lfem {

// The world's own scalars that a step changes.
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

struct WorldState {
    WorldCounters counters;
    // Pairs found by the last sub-step, in a fixed order (body_a, node, body_b); those with
    // active() are the contacts.
    std::vector<ContactRecord> contacts;
};

}  // namespace lfem
