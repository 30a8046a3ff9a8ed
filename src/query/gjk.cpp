#include "query/gjk.h"

#include <algorithm>
#include <cmath>

#include "common/closest_point.h"

namespace lfem {
namespace {

// Iterations of either loop: a polytope's answer needs a few dozen at most; the cap guards
// against rounding cycling near convergence.
constexpr int kMaxIterations = 64;
constexpr double kTolerance = 1e-12;  // of the size

double extent(const ConvexPoints& c) {
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < c.count; ++i)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c.points[i][k]), hi[k] = std::max(hi[k], c.points[i][k]);
    return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 0.0});
}

double det3(const Vec3& a, const Vec3& b, const Vec3& c) { return a.dot(b.cross(c)); }

// Keeps the points of s[0..n) whose weight is not zero (their order kept).
void keep_weighted(Vec3* s, int& n, const double* w) {
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (w[i] > 0.0) s[m++] = s[i];
    n = m;
}

// The point of the simplex conv(s[0..n)), n <= 4, nearest to q; the simplex is reduced to the
// points that carry it (the smallest face it lies on). A tetrahedron around q returns q with
// all four points kept.
Vec3 nearest_in_simplex(Vec3* s, int& n, const Vec3& q, double scale) {
    double w[4] = {1, 0, 0, 0};
    Vec3 p = s[0];
    if (n == 2) {
        p = closest_on_segment(q, s[0], s[1], w);
    } else if (n == 3) {
        p = closest_on_triangle(q, s[0], s[1], s[2], w);
    } else if (n == 4) {
        const double volume = det3(s[1] - s[0], s[2] - s[0], s[3] - s[0]);
        static const int face[4][4] = {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}};
        bool inside = std::fabs(volume) > 1e-14 * scale * scale * scale;
        for (int f = 0; f < 4 && inside; ++f) {
            const Vec3 &a = s[face[f][0]], &b = s[face[f][1]], &c = s[face[f][2]], &d = s[face[f][3]];
            inside = det3(b - a, c - a, q - a) * det3(b - a, c - a, d - a) >= 0.0;
        }
        if (inside) return q;
        double best = HUGE_VAL;
        for (const auto& f : face) {
            double wf[3];
            const Vec3 pf = closest_on_triangle(q, s[f[0]], s[f[1]], s[f[2]], wf);
            const double d = (pf - q).squaredNorm();
            if (d < best) {
                best = d, p = pf;
                w[f[3]] = 0.0;
                for (int k = 0; k < 3; ++k) w[f[k]] = wf[k];
            }
        }
    }
    if (n > 1) keep_weighted(s, n, w);
    return p;
}

bool holds(const Vec3* s, int n, const Vec3& p) {
    for (int i = 0; i < n; ++i)
        if (s[i] == p) return true;
    return false;
}

}  // namespace

Vec3 support_point(const ConvexPoints& c, const Vec3& d) {
    uint32_t best = 0;
    double most = -HUGE_VAL;
    for (uint32_t i = 0; i < c.count; ++i) {
        const double v = c.points[i].dot(d);
        if (v > most) most = v, best = i;
    }
    return c.points[best];
}

double convex_distance(const ConvexPoints& a, const ConvexPoints& b) { return convex_separation(a, b).norm(); }

Vec3 convex_separation(const ConvexPoints& a, const ConvexPoints& b) {
    const double scale = std::max(extent(a), extent(b)) + 1e-300;
    Vec3 s[4];
    int n = 0;
    Vec3 v = a.points[0] - b.points[0];
    for (int it = 0; it < kMaxIterations; ++it) {
        const double vv = v.squaredNorm();
        if (vv <= kTolerance * kTolerance * scale * scale) return Vec3::Zero();
        const Vec3 w = support_point(a, -v) - support_point(b, v);
        // No point of A - B lies closer to the origin along v than v itself: v is the distance.
        if (vv - v.dot(w) <= kTolerance * scale * std::sqrt(vv) || holds(s, n, w)) break;
        s[n++] = w;
        v = nearest_in_simplex(s, n, Vec3::Zero(), scale);
        if (n == 4) return Vec3::Zero();  // the origin is inside: they overlap
    }
    return v;
}

bool convex_ray_cast(const ConvexPoints& c, const Vec3& origin, const Vec3& dir, double t_max, double& t,
                     Vec3& normal) {
    const double scale = extent(c) + 1e-300;
    double lambda = 0.0;
    Vec3 x = origin, n = Vec3::Zero();
    Vec3 s[4];
    int count = 0;
    Vec3 v = x - c.points[0];
    for (int it = 0; it < kMaxIterations && v.squaredNorm() > kTolerance * kTolerance * scale * scale; ++it) {
        const Vec3 p = support_point(c, v);
        const Vec3 w = x - p;
        if (v.dot(w) > 0.0) {
            // v separates x from the hull: move x along the ray to the plane of p across v.
            const double vr = v.dot(dir);
            if (vr >= 0.0) return false;  // the ray runs away from the hull
            lambda -= v.dot(w) / vr;
            if (lambda > t_max) return false;
            x = origin + lambda * dir;
            n = v;
        }
        if (!holds(s, count, p)) s[count++] = p;
        v = x - nearest_in_simplex(s, count, x, scale);
        if (count == 4) break;  // x inside the hull
    }
    t = lambda;
    const double len = n.norm();
    normal = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
    return true;
}

}  // namespace lfem
