// The opaque C types and the checked ways from a C pointer to the C++ object behind it.
#pragma once

#include "api/guard.h"
#include "mesh/tet_mesh.h"
#include "world/world.h"

struct lfem_world {
    explicit lfem_world(const lfem::WorldDef& def) : world(def) {}
    lfem::World world;
};

namespace lfem::api {

// Cookies written by the *_default functions: a definition that did not come from them (say,
// uninitialised stack memory) is refused instead of being trusted.
constexpr uint32_t world_def_cookie = 0x4C46574Du;  // "LFWM"
constexpr uint32_t body_def_cookie = 0x4C46424Du;   // "LFBM"
constexpr uint32_t shape_def_cookie = 0x4C465348u;  // "LFSH"
constexpr uint32_t attachment_def_cookie = 0x4C464154u;  // "LFAT"

inline World& world_of(lfem_world* w) {
    require_pointer(w, "world");
    return w->world;
}
inline const World& world_of(const lfem_world* w) {
    require_pointer(w, "world");
    return w->world;
}

}  // namespace lfem::api
