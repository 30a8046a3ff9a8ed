// How a failure is classified inside the library: the shim (src/api) maps each to the public
// lfem_status of the same name (api/conversions.cpp), so kernels never see the C ABI.
#pragma once

#include <cstdint>

namespace lfem {

enum class Status : int32_t {
    ok,
    invalid_argument,  // a null pointer, a NaN, a number out of its range
    invalid_mesh,      // bad indices, inverted or zero-volume tets, unused nodes
    invalid_handle,    // a stale, foreign or null handle
    buffer_too_small,  // the caller's capacity is below what the answer needs
    unstable,          // the state blew up; the world was rolled back
    io_error,          // a file could not be read or written, or is malformed
    out_of_memory,
    internal_error,    // a bug
    unsupported,       // a feature this build leaves out
};

}  // namespace lfem
