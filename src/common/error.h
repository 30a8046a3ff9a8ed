// lfem::Error: how code inside the library reports a failure. The C shim (src/api) catches it
// and turns it into an lfem_status plus the thread's last-error message; it never crosses the
// C ABI.
#pragma once

#include <stdexcept>
#include <string>

#include "lfem.h"

namespace lfem {

class Error : public std::runtime_error {
public:
    Error(lfem_status status, const std::string& message)
        : std::runtime_error(message), status_(status) {}
    lfem_status status() const { return status_; }

private:
    lfem_status status_;
};

}  // namespace lfem
