// The point of a segment or a triangle nearest to a given point, with its barycentric weights:
// what the skins need to find the tet nearest to a vertex just outside a body, and what the
// queries' convex-set algorithm (query/gjk.cpp) needs of its simplices. Ericson's region tests
// ("Real-Time Collision Detection", 5.1.2 and 5.1.5); degenerate simplices (coincident or
// collinear points) fall back to their edges, never divide by zero.
#pragma once

#include <cmath>

#include "common/math.h"

namespace lfem {

// The point of segment ab nearest to p: (1 - t) a + t b, weights w = (1 - t, t).
inline Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b, double w[2]) {
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    w[0] = 1.0 - t, w[1] = t;
    return a + t * ab;
}

// The point of triangle abc nearest to p, with weights w on (a, b, c): >= 0, summing to 1.
inline Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, double w[3]) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    w[0] = w[1] = w[2] = 0.0;
    if (d1 <= 0.0 && d2 <= 0.0) return w[0] = 1.0, a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return w[1] = 1.0, b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0) {
        const double v = d1 / (d1 - d3);
        return w[0] = 1.0 - v, w[1] = v, Vec3(a + v * ab);
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return w[2] = 1.0, c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0) {
        const double v = d2 / (d2 - d6);
        return w[0] = 1.0 - v, w[2] = v, Vec3(a + v * ac);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0) {
        const double v = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return w[1] = 1.0 - v, w[2] = v, Vec3(b + v * (c - b));
    }
    const double sum = va + vb + vc;
    if (sum > 0.0 && va >= 0.0 && vb >= 0.0 && vc >= 0.0) {  // inside the face
        w[1] = vb / sum, w[2] = vc / sum, w[0] = 1.0 - w[1] - w[2];
        return a + w[1] * ab + w[2] * ac;
    }
    // A degenerate (collinear) triangle: the nearest of its edges.
    const Vec3* corner[3] = {&a, &b, &c};
    double best = HUGE_VAL;
    Vec3 nearest = a;
    for (int e = 0; e < 3; ++e) {
        double we[2];
        const Vec3 q = closest_on_segment(p, *corner[e], *corner[(e + 1) % 3], we);
        const double d = (q - p).squaredNorm();
        if (d < best) {
            best = d, nearest = q;
            w[0] = w[1] = w[2] = 0.0;
            w[e] = we[0], w[(e + 1) % 3] = we[1];
        }
    }
    return nearest;
}

}  // namespace lfem
