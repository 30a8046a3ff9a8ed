// Axis-aligned boxes: what every tree and hash of lfem sorts things by (contact's broad phase
// and triangle trees, the skins' search for the tet around a vertex, the queries' trees of
// bodies), and the one ray test they share.
#pragma once

#include <cmath>
#include <utility>

namespace lfem {

struct Aabb {
    double lo[3], hi[3];
};

// A box that contains nothing and overlaps nothing.
inline Aabb empty_box() {
    Aabb b;
    for (int k = 0; k < 3; ++k) b.lo[k] = __builtin_huge_val(), b.hi[k] = -__builtin_huge_val();
    return b;
}

// Whether two boxes overlap (touching counts); a box with a NaN corner overlaps nothing.
inline bool overlaps(const Aabb& a, const Aabb& b) {
    for (int k = 0; k < 3; ++k)
        if (!(a.hi[k] >= b.lo[k] && b.hi[k] >= a.lo[k])) return false;
    return true;
}

// a grown to contain b as well.
inline void join(Aabb& a, const Aabb& b) {
    for (int k = 0; k < 3; ++k) {
        a.lo[k] = a.lo[k] < b.lo[k] ? a.lo[k] : b.lo[k];
        a.hi[k] = a.hi[k] > b.hi[k] ? a.hi[k] : b.hi[k];
    }
}

// The box grown by r on every side.
inline Aabb grown(Aabb b, double r) {
    for (int k = 0; k < 3; ++k) b.lo[k] -= r, b.hi[k] += r;
    return b;
}

// A ray o + t d (d need not be unit) as the slab test wants it: the reciprocal of each
// direction component, and which components are zero (or so small that their reciprocal
// overflows: the ray is parallel to those slabs).
struct RaySlabs {
    double o[3], inv[3];
    bool parallel[3];
    RaySlabs(const double origin[3], const double d[3]) {
        for (int k = 0; k < 3; ++k) {
            o[k] = origin[k];
            inv[k] = 1.0 / d[k];
            parallel[k] = !std::isfinite(inv[k]);
        }
    }
};

// The part [t_enter, t_exit] of [t_min, t_max] in which the ray is inside the box (touching
// counts); false when there is none. The interval is widened by 1e-12 of its scale on each
// side, so that a hit the exact test finds on a box's face is never cut off by rounding here.
inline bool ray_interval(const Aabb& b, const RaySlabs& r, double t_min, double t_max, double& t_enter,
                         double& t_exit) {
    double lo = t_min, hi = t_max;
    for (int k = 0; k < 3; ++k) {
        if (r.parallel[k]) {
            if (!(r.o[k] >= b.lo[k] && r.o[k] <= b.hi[k])) return false;
            continue;
        }
        double a = (b.lo[k] - r.o[k]) * r.inv[k], c = (b.hi[k] - r.o[k]) * r.inv[k];
        if (a > c) std::swap(a, c);
        const double pad = 1e-12 * (std::fabs(a) + std::fabs(c) + (b.hi[k] - b.lo[k]) * std::fabs(r.inv[k]));
        lo = a - pad > lo ? a - pad : lo;
        hi = c + pad < hi ? c + pad : hi;
        if (!(lo <= hi)) return false;  // also a NaN
    }
    t_enter = lo, t_exit = hi;
    return true;
}

}  // namespace lfem
