// The four kinds of body, as every stage sees them (the public BodyKind, converted by the
// shim): what moves a body and what contact makes of it.
#pragma once

#include <cstdint>

namespace lfem {

enum class BodyKind : int32_t {
    deformable,   // finite elements: moves and deforms
    static_body,  // never moves
    kinematic,    // moves rigidly at a prescribed velocity, unaffected by forces
    rigid,        // the global translation and rotation alone (eq. 2), moved by forces
};

}  // namespace lfem
