// What the query tests share: a static body, its shapes, quaternions, and the tolerances of
// closed forms and of GJK.
#pragma once

#include <cmath>

#include "physics/lfem_test_util.h"

namespace lfem_test {

inline lfem_body static_body(lfem_world* w) {
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_OK);
    return b;
}

inline uint32_t add_shape(lfem_world* w, lfem_body b, const lfem_shape_def& s) {
    uint32_t index = UINT32_MAX;
    EXPECT_EQ(lfem_body_add_shape(w, b, &s, &index), LFEM_OK) << lfem_last_error();
    return index;
}

// A unit quaternion (w, x, y, z) of angle a about a unit axis.
inline void quaternion(double a, double ax, double ay, double az, double q[4]) {
    q[0] = std::cos(a / 2), q[1] = ax * std::sin(a / 2), q[2] = ay * std::sin(a / 2), q[3] = az * std::sin(a / 2);
}

inline void expect_near3(const double* got, double x, double y, double z, double tol, const char* what) {
    EXPECT_NEAR(got[0], x, tol) << what;
    EXPECT_NEAR(got[1], y, tol) << what;
    EXPECT_NEAR(got[2], z, tol) << what;
}

inline bool same_body(lfem_body a, lfem_body b) { return a.index == b.index && a.generation == b.generation; }

// Closed forms are met to round-off: the shapes' answers come from a few operations on
// numbers of order 1-10 (1e-12 leaves room for 4 orders of magnitude of rounding); hulls are
// found by GJK to its tolerance of 1e-12 of their size (1e-10 here).
constexpr double kExact = 1e-12;
constexpr double kGjk = 1e-10;

}  // namespace lfem_test
