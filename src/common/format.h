// Numbers in error messages: printf's %g with a given number of significant digits (6 by
// default), e.g. "0.00235" or "1.5e+07", so every message writes a number alike.
#pragma once

#include <cstdio>
#include <string>

namespace lfem {

inline std::string format_number(double v, int digits = 6) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return text;
}

// A time in seconds: "0.0025 s".
inline std::string format_seconds(double s) { return format_number(s) + " s"; }

}  // namespace lfem
