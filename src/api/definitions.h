// Checks of the caller's definitions, shared by the entry points that take them and by
// lfem_world_load (a checkpoint's definitions are held to the same rules). Each throws
// lfem::Error(Status::invalid_argument) naming the field.
#pragma once

#include "lfem.h"

namespace lfem::api {

void check_world_def(const lfem_world_def& d);
void check_body_def(const lfem_body_def& d);

}  // namespace lfem::api
