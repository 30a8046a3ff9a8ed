// Render meshes for the skin and query tests: a sphere (an octahedron subdivided and projected,
// vertices shared: smooth), a box surface whose faces have vertices of their own (flat), and a
// body moved by a known linear map (every node prescribed v = B X, so x(t) = X + t B X).
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "physics/lfem_test_util.h"

namespace lfem_test {

struct SkinMesh {
    std::vector<double> x;       // 3 per vertex
    std::vector<uint32_t> tri;   // 3 per triangle, counter-clockwise seen from outside
    uint32_t vertices() const { return uint32_t(x.size() / 3); }
    uint32_t triangles() const { return uint32_t(tri.size() / 3); }
};

// The sphere of radius r about c: an octahedron whose faces are split in four `level` times,
// every vertex pushed out onto the sphere.
inline SkinMesh sphere_skin(const double c[3], double r, int level) {
    std::vector<std::array<double, 3>> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<uint32_t> t = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    for (int l = 0; l < level; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
        auto mid = [&](uint32_t a, uint32_t b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            auto it = middle.find(key);
            if (it != middle.end()) return it->second;
            std::array<double, 3> m;
            double n = 0;
            for (int k = 0; k < 3; ++k) m[k] = v[a][k] + v[b][k], n += m[k] * m[k];
            for (double& mk : m) mk /= std::sqrt(n);
            v.push_back(m);
            return middle[key] = uint32_t(v.size() - 1);
        };
        std::vector<uint32_t> finer;
        for (std::size_t f = 0; f < t.size(); f += 3) {
            const uint32_t a = t[f], b = t[f + 1], cc = t[f + 2];
            const uint32_t ab = mid(a, b), bc = mid(b, cc), ca = mid(cc, a);
            for (uint32_t i : {a, ab, ca, ab, b, bc, ca, bc, cc, ab, bc, ca}) finer.push_back(i);
        }
        t = finer;
    }
    SkinMesh s;
    for (const auto& p : v)
        for (int k = 0; k < 3; ++k) s.x.push_back(c[k] + r * p[k]);
    s.tri = t;
    return s;
}

// The surface of the box [lo, hi]: each face an n x n grid of squares (two triangles each) on
// vertices of its own, so every vertex's smooth normal is its face's normal.
inline SkinMesh box_skin(const double lo[3], const double hi[3], uint32_t n) {
    SkinMesh s;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;  // (u, w, axis) right-handed
            const uint32_t first = s.vertices();
            for (uint32_t i = 0; i <= n; ++i)
                for (uint32_t j = 0; j <= n; ++j) {
                    double p[3];
                    p[axis] = side ? hi[axis] : lo[axis];
                    p[u] = lo[u] + (hi[u] - lo[u]) * i / n;
                    p[w] = lo[w] + (hi[w] - lo[w]) * j / n;
                    s.x.insert(s.x.end(), p, p + 3);
                }
            for (uint32_t i = 0; i < n; ++i)
                for (uint32_t j = 0; j < n; ++j) {
                    const uint32_t a = first + i * (n + 1) + j, b = a + (n + 1), c = b + 1, d = a + 1;
                    // u x w = axis: counter-clockwise in (u, w) faces +axis; the far side, -axis.
                    if (side) s.tri.insert(s.tri.end(), {a, b, c, a, c, d});
                    else s.tri.insert(s.tri.end(), {a, c, b, a, d, c});
                }
        }
    return s;
}

// Prescribes v_i = B X_i (B row-major) on every node: the body then moves by x(t) = (I + t B) X
// exactly, whatever its material does.
inline void prescribe_linear_motion(lfem_world* w, lfem_body b, const double B[9]) {
    const std::vector<double> X = positions(w, b);
    for (uint32_t i = 0; i < X.size() / 3; ++i) {
        double v[3];
        for (int r = 0; r < 3; ++r) v[r] = B[3 * r] * X[3 * i] + B[3 * r + 1] * X[3 * i + 1] + B[3 * r + 2] * X[3 * i + 2];
        ASSERT_EQ(lfem_body_prescribe_node_velocity(w, b, &i, 1, v), LFEM_OK) << lfem_last_error();
    }
}

// (I + t B) p.
inline std::array<double, 3> linear_map(const double B[9], double t, const double* p) {
    std::array<double, 3> q;
    for (int r = 0; r < 3; ++r) q[r] = p[r] + t * (B[3 * r] * p[0] + B[3 * r + 1] * p[1] + B[3 * r + 2] * p[2]);
    return q;
}

}  // namespace lfem_test
