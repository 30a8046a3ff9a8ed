// The one place where C++ failures become C statuses. Every exported function runs its body
// through guard(): lfem::Error keeps its status and message, std::bad_alloc becomes
// LFEM_OUT_OF_MEMORY, anything else LFEM_INTERNAL_ERROR. No exception leaves the library.
#pragma once

#include <cmath>
#include <cstddef>
#include <new>
#include <string>

#include "api/conversions.h"
#include "common/error.h"
#include "lfem.h"

namespace lfem::api {

// Records the message of a failed call for lfem_last_error() on this thread.
void set_last_error(const char* function, const std::string& message);

template <class Body>
lfem_status guard(const char* function, Body&& body) noexcept {
    try {
        body();
        return LFEM_OK;
    } catch (const Error& e) {
        set_last_error(function, e.what());
        return to_c(e.status());
    } catch (const std::bad_alloc&) {
        set_last_error(function, "out of memory");
        return LFEM_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        set_last_error(function, std::string("internal error: ") + e.what());
        return LFEM_INTERNAL_ERROR;
    } catch (...) {
        set_last_error(function, "internal error: unknown exception");
        return LFEM_INTERNAL_ERROR;
    }
}

// Argument checks shared by every entry point: each throws lfem::Error(Status::invalid_argument)
// naming the argument, so the shim reads as a list of requirements.
inline void require(bool condition, const std::string& message) {
    if (!condition) throw Error(Status::invalid_argument, message);
}
inline void require_pointer(const void* p, const char* name) {
    require(p != nullptr, std::string(name) + " is NULL");
}
inline void require_finite(const double* v, std::size_t n, const char* name) {
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(v[i]))
            throw Error(Status::invalid_argument,
                        std::string(name) + "[" + std::to_string(i) + "] is not finite");
}

// A pose as the caller gives it (a frame, a transform): a finite centre and a quaternion
// (w, x, y, z) that can be normalised.
inline void require_pose(const double* pose, const char* name) {
    require_pointer(pose, name);
    require_finite(pose, 7, name);
    const double q2 = pose[3] * pose[3] + pose[4] * pose[4] + pose[5] * pose[5] + pose[6] * pose[6];
    require(q2 > 1e-12, std::string(name) + "'s quaternion (elements 3..6) must not be zero");
}

// A feature this build leaves out: LFEM_UNSUPPORTED, naming the CMake option that brings it
// back. Called after the arguments were checked, so a bad argument still gets its own status.
[[noreturn]] inline void unsupported(const std::string& what, const char* option) {
    throw Error(Status::unsupported, what + " is not part of this build of lfem (configured with " +
                                      option + "=OFF; rebuild with " + option + "=ON)");
}

}  // namespace lfem::api
