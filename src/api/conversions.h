// The world's own types and the C ABI's, converted in one place: statuses, definitions,
// handles, events and the profile. Enum values cross by name (a switch per enum), never by
// their numbers, so the two sides may number them as they like.
#pragma once

#include "common/profile.h"
#include "common/status.h"
#include "contact/rigid_shape.h"
#include "lfem.h"
#include "world/definitions.h"

namespace lfem::api {

lfem_status to_c(Status s);
lfem_body to_c(BodyHandle h);
lfem_attachment to_c(AttachmentHandle h);
lfem_event_type to_c(EventType t);
lfem_profile to_c(const Profile& p);
lfem_body_type to_c(BodyKind k);
lfem_model to_c(Model m);
BodyKind from_c(lfem_body_type t);  // one of the four (checked by the caller)
inline BodyHandle from_c(lfem_body h) { return BodyHandle{h.index, h.generation}; }
inline AttachmentHandle from_c(lfem_attachment h) { return AttachmentHandle{h.index, h.generation}; }

// The definitions, both ways: a checked C definition into the world's (to_world_def,
// to_body_def: the enums must hold one of their values, which check_*_def makes sure of), and a
// checkpoint's back into C (with the cookie), so that a file's definitions pass the checks a
// caller's pass.
WorldDef to_world_def(const lfem_world_def& d);
BodyDef to_body_def(const lfem_body_def& d);
lfem_world_def to_c(const WorldDef& d, uint32_t cookie);
lfem_body_def to_c(const BodyDef& d, uint32_t cookie);
// A shape type of the C ABI; false when the value is none of them.
bool shape_type_from_c(lfem_shape_type t, ShapeType& out);

}  // namespace lfem::api
