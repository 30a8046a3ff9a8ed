// The sweeps of the multiplier solve over an array of constraint pairs (constraint_pair.h):
// the warm start, one pass of normal updates (the paper's tension release), one of friction
// updates (eq. 7), and the write-back into the records. A solve runs them over a whole contact
// group, or over the parts of a big one that the threads share (group_partition.h).
#pragma once

#include <cstdint>
#include <vector>

#include "contact/constraint_pair.h"
#include "contact/contact_record.h"

namespace lfem {

// Applies the pairs' warm-start multipliers (the records' last step's, for the same node and
// body), so that a resting contact starts converged. Returns whether some pair has friction.
bool warm_start_pairs(ConstraintPair* pairs, uint32_t count);

// One sweep's normal updates: lambda_n <- max(0, lambda_n - (g - g_target)/H), the clamp the
// paper's tension release. Returns the sweep's measure of change: with `first`, the largest move
// an update made; after it, the largest change of an active or penetrating pair's gap since the
// last sweep, measured before the pair's update.
double normal_pass(ConstraintPair* pairs, uint32_t count, bool first);

// One sweep's friction updates: the tangential slip of the node relative to the triangle over
// the step, cancelled by the stick trial, then returned onto the Coulomb cone (eq. 7). Its
// measure of change likewise (the slips of pairs that carry force).
double friction_pass(ConstraintPair* pairs, uint32_t count, bool first);

// The pairs' multipliers back into their records (records[order[k]] is pairs[k]'s), with what
// the next step's detection reads (gap_after, plane_gap); returns the deepest penetration.
double write_back(const ConstraintPair* pairs, uint32_t count, const uint32_t* order,
                  std::vector<ContactRecord>& records);

}  // namespace lfem
