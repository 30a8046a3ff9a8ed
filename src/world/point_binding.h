// Points of a body found by position: the tet around each where the body's nodes are now (or
// the nearest within reach: a point on the surface, a little proud of it), its nodes and their
// weights by the tet's shape functions there, as a skin's vertex is bound (skin/skin.h). The
// weights sum to 1 and reproduce the point (extrapolated outside the tet), so a force spread by
// them has the force's moment about any point. Impulses, forces and attachments at a point.
#pragma once

#include <cstdint>

#include "skin/skin.h"
#include "world/body.h"

namespace lfem {

// Throws Error(Status::invalid_argument) naming `what` for a point beyond reach.
Skin bind_points(const Body& body, const double* points, uint32_t count, double reach, const char* what);

}  // namespace lfem
