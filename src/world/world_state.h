// What a step changes beside the bodies' own states: the world's counters and the contact list
// (which also warm-starts the next solve). A roll-back restores it with the bodies' states; a
// checkpoint writes it with the bodies.
#pragma once

#include <cstdint>
#include <vector>

#include "contact/contact_record.h"
#include "world/attachments.h"

namespace lfem {

// Non-fatal trouble, counted as MuJoCo counts its warnings: how often, when last and for which
// body (slot and generation, as a handle).
struct Warning {
    uint64_t count = 0;
    double last_time = 0;  // s
    uint32_t last_slot = 0, last_generation = 0;  // generation 0: no body (or none yet)
    void note(uint64_t n, double time, uint32_t slot, uint32_t generation) {
        count += n;
        last_time = time, last_slot = slot, last_generation = generation;
    }
};

struct Warnings {
    Warning inverted_tets;    // sub-steps that ended with a body's tet turned inside out (per body)
    Warning stays_inverted;   // a body kept inverted tets for kStaysInverted s in a row
    Warning fallen_in;        // nodes found inside another body (or their own), pushed out
    Warning unconverged;      // a contact solve stopped at contact_iterations sweeps (no body)
};

// How long a body's tets may stay inverted before it is reported as staying so (s).
constexpr double kStaysInverted = 0.5;

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
    Warnings warnings;
};

struct WorldState {
    WorldCounters counters;
    // Pairs found by the last sub-step, in a fixed order (body_a, node, body_b); those with
    // active() are the contacts.
    std::vector<ContactRecord> contacts;
    Attachments attachments;
    // The pairs of bodies that touched at the end of the last call (lower slot << 32 | higher
    // slot, ascending): where contact events begin and end.
    std::vector<uint64_t> touching;
};

}  // namespace lfem
