// Checkpoints: the whole state of a world in a versioned binary file, so that a run continued
// from it is bitwise identical to one that never stopped.
#pragma once

#include <string>
#include <vector>

#include "world/world.h"

namespace lfem {

// Everything a step depends on, as read from a checkpoint (World::restore takes it over).
struct WorldImage {
    WorldDef def{};
    std::vector<Body> bodies;        // one per slot; generation 0 = a free slot
    std::vector<uint32_t> free_slots;
    WorldState state;                // counters and contacts (the warm start of the next solve)
};

// Writes `world` to `path`: first to "<path>.tmp", then renamed over `path`, so an existing
// checkpoint is replaced only by a complete one. Throws Error(Status::io_error) when the file
// cannot be written.
void save_checkpoint(const World& world, const std::string& path);

// Reads and checks a checkpoint. Throws Error(Status::io_error) for a missing, truncated,
// corrupted (checksum), foreign (magic, version, layout) or inconsistent file.
WorldImage read_checkpoint(const std::string& path);

}  // namespace lfem
