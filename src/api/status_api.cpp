// Status strings, the thread-local last error and the version query.
#include <string>

#include "api/guard.h"
#include "lfem.h"

namespace {
thread_local std::string t_last_error;
}

namespace lfem::api {
void set_last_error(const char* function, const std::string& message) {
    try {
        t_last_error = std::string(function) + ": " + message;
    } catch (...) {
        // Out of memory while recording the message: keep the status, drop the text.
        t_last_error.clear();
    }
}
}  // namespace lfem::api

extern "C" {

LFEM_API const char* lfem_status_string(lfem_status status) {
    switch (status) {
        case LFEM_OK: return "LFEM_OK: success";
        case LFEM_INVALID_ARGUMENT: return "LFEM_INVALID_ARGUMENT: invalid argument";
        case LFEM_INVALID_MESH: return "LFEM_INVALID_MESH: invalid mesh";
        case LFEM_INVALID_HANDLE: return "LFEM_INVALID_HANDLE: stale, foreign or null handle";
        case LFEM_BUFFER_TOO_SMALL: return "LFEM_BUFFER_TOO_SMALL: buffer too small";
        case LFEM_UNSTABLE: return "LFEM_UNSTABLE: the state blew up, world rolled back";
        case LFEM_IO_ERROR: return "LFEM_IO_ERROR: file could not be read or written";
        case LFEM_OUT_OF_MEMORY: return "LFEM_OUT_OF_MEMORY: out of memory";
        case LFEM_INTERNAL_ERROR: return "LFEM_INTERNAL_ERROR: internal error";
        case LFEM_UNSUPPORTED: return "LFEM_UNSUPPORTED: this build leaves the feature out";
        default: return "unknown status";
    }
}

LFEM_API const char* lfem_last_error(void) { return t_last_error.c_str(); }

LFEM_API uint32_t lfem_version(void) {
    return (uint32_t(LFEM_VERSION_MAJOR) << 16) | (uint32_t(LFEM_VERSION_MINOR) << 8) |
           uint32_t(LFEM_VERSION_PATCH);
}

#define LFEM_STR2(x) #x
#define LFEM_STR(x) LFEM_STR2(x)
LFEM_API const char* lfem_version_string(void) {
    return LFEM_STR(LFEM_VERSION_MAJOR) "." LFEM_STR(LFEM_VERSION_MINOR) "." LFEM_STR(
        LFEM_VERSION_PATCH);
}

}  // extern "C"
