// lfem::Error: how code inside the library reports a failure, with its Status. The C shim
// (src/api) catches it and turns it into an lfem_status plus the thread's last-error message;
// it never crosses the C ABI.
#pragma once

#include <stdexcept>
#include <string>

#include "common/status.h"

namespace lfem {

class Error : public std::runtime_error {
public:
    Error(Status status, const std::string& message) : std::runtime_error(message), status_(status) {}
    Status status() const { return status_; }

private:
    Status status_;
};

}  // namespace lfem
