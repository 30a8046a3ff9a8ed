// Where a line meets a triangle: the Möller-Trumbore test, shared by contact (does a node's way
// out cross a face, contact/node_face.cpp) and the queries (a ray against a body's surface).
#pragma once

#include <cmath>

#include "common/math.h"

namespace lfem {

// The line from + s d meets triangle (v0, v0 + e1, v0 + e2) at from + s d = (1 - u - v) v0 +
// u (v0 + e1) + v (v0 + e2) with u, v >= 0 and u + v <= 1 (edges and corners count), from
// either side. False for a line parallel to the triangle's plane (or a triangle with no area).
inline bool line_meets_triangle(const Vec3& from, const Vec3& d, const Vec3& v0, const Vec3& e1, const Vec3& e2,
                                double& s, double& u, double& v) {
    const Vec3 pv = d.cross(e2);
    const double det = e1.dot(pv);
    if (std::fabs(det) < 1e-300) return false;
    const Vec3 tv = from - v0;
    u = tv.dot(pv) / det;
    if (u < 0.0 || u > 1.0) return false;
    const Vec3 qv = tv.cross(e1);
    v = d.dot(qv) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    s = e2.dot(qv) / det;
    return true;
}

}  // namespace lfem
