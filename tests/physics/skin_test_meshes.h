// Render meshes for the skin and query tests: a sphere (an octahedron subdivided and projected,
// vertices shared: smooth), a box surface whose faces have vertices of their own (flat),
// scattered points; a body moved by a known field (every node prescribed v = f(X), so
// x(t) = X + t f(X), a linear map for f(X) = B X); the queries' answers as vectors.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
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

// A skin added (its index) and read back (positions and normals, 3 per vertex each).
struct SkinRead {
    std::vector<double> x, n;
};

inline SkinRead read_skin(lfem_world* w, lfem_body b, uint32_t skin) {
    uint32_t nv = 0;
    EXPECT_EQ(lfem_body_get_skin_sizes(w, b, skin, &nv, nullptr), LFEM_OK) << lfem_last_error();
    SkinRead r;
    r.x.resize(3 * std::size_t(nv));
    r.n.resize(3 * std::size_t(nv));
    EXPECT_EQ(lfem_body_get_skin_vertices(w, b, skin, r.x.data(), r.n.data(), nv), LFEM_OK) << lfem_last_error();
    return r;
}

inline uint32_t add_skin(lfem_world* w, lfem_body b, const SkinMesh& s) {
    uint32_t index = UINT32_MAX;
    EXPECT_EQ(lfem_body_add_skin(w, b, s.x.data(), s.vertices(), s.tri.data(), s.triangles(), &index), LFEM_OK)
        << lfem_last_error();
    return index;
}

// Saves the world to path, loads it back, and checks that the two read the same (skins
// included) and step alike; skips the test in a build without checkpoint files.
inline void expect_checkpoint_keeps(lfem_world* w, lfem_body b, const char* path) {
    const lfem_status saved = lfem_world_save(w, path);
    if (saved == LFEM_UNSUPPORTED) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    ASSERT_EQ(saved, LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path, &loaded), LFEM_OK) << lfem_last_error();
    std::remove(path);
    EXPECT_EQ(fingerprint(w, {b}), fingerprint(loaded, {b}));
    EXPECT_EQ(lfem_world_step(w, 0.01), LFEM_OK);
    EXPECT_EQ(lfem_world_step(loaded, 0.01), LFEM_OK);
    EXPECT_EQ(fingerprint(w, {b}), fingerprint(loaded, {b}));
    lfem_world_destroy(loaded);
}

// A world without gravity (bodies stay where their prescribed motions take them).
inline lfem_world_def no_gravity() {
    lfem_world_def d = lfem_world_def_default();
    d.gravity[2] = 0.0;
    return d;
}

// Random points in the box [lo, hi] grown by `out` on every side (out > 0: some just outside),
// every three a triangle.
inline SkinMesh scattered(const double lo[3], const double hi[3], double out, uint32_t count, unsigned seed) {
    std::mt19937 rng(seed);
    SkinMesh s;
    for (uint32_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k)
            s.x.push_back(std::uniform_real_distribution<double>(lo[k] - out, hi[k] + out)(rng));
    for (uint32_t i = 0; i + 2 < count; i += 3) s.tri.insert(s.tri.end(), {i, i + 1, i + 2});
    return s;
}

// Prescribes v_i = field(X_i) on every node i at its current position X_i: the body's nodes
// then move by x_i(t) = X_i + t field(X_i) exactly, whatever its material does.
template <class Field>
void prescribe_motion(lfem_world* w, lfem_body b, const Field& field) {
    const std::vector<double> X = positions(w, b);
    for (uint32_t i = 0; i < X.size() / 3; ++i) {
        const std::array<double, 3> v = field(&X[3 * std::size_t(i)]);
        ASSERT_EQ(lfem_body_prescribe_node_velocity(w, b, &i, 1, v.data()), LFEM_OK) << lfem_last_error();
    }
}

// Prescribes v_i = B X_i (B row-major) on every node: the body then moves by x(t) = (I + t B) X
// exactly, whatever its material does.
inline void prescribe_linear_motion(lfem_world* w, lfem_body b, const double B[9]) {
    prescribe_motion(w, b, [&](const double* X) {
        std::array<double, 3> v;
        for (int r = 0; r < 3; ++r) v[r] = B[3 * r] * X[0] + B[3 * r + 1] * X[1] + B[3 * r + 2] * X[2];
        return v;
    });
}

// (I + t B) p.
inline std::array<double, 3> linear_map(const double B[9], double t, const double* p) {
    std::array<double, 3> q;
    for (int r = 0; r < 3; ++r) q[r] = p[r] + t * (B[3 * r] * p[0] + B[3 * r + 1] * p[1] + B[3 * r + 2] * p[2]);
    return q;
}

// Query helpers: the closest hit (found or not), every hit, and the bodies a box overlaps.
struct Hit {
    bool found = false;
    lfem_ray_hit h{};
};

inline Hit cast(lfem_world* w, const double o[3], const double d[3], double max = HUGE_VAL,
         lfem_query_filter f = lfem_query_filter_default()) {
    Hit r;
    int hit = -1;
    EXPECT_EQ(lfem_world_cast_ray(w, o, d, max, f, &r.h, &hit), LFEM_OK) << lfem_last_error();
    EXPECT_TRUE(hit == 0 || hit == 1);
    r.found = hit == 1;
    return r;
}

inline std::vector<lfem_ray_hit> cast_all(lfem_world* w, const double o[3], const double d[3], double max = HUGE_VAL,
                                   lfem_query_filter f = lfem_query_filter_default()) {
    uint32_t count = 0;
    const lfem_status asked = lfem_world_cast_ray_all(w, o, d, max, f, nullptr, 0, &count);
    EXPECT_EQ(asked, count ? LFEM_BUFFER_TOO_SMALL : LFEM_OK);
    std::vector<lfem_ray_hit> hits(count);
    EXPECT_EQ(lfem_world_cast_ray_all(w, o, d, max, f, hits.data(), count, &count), LFEM_OK) << lfem_last_error();
    return hits;
}

inline std::vector<lfem_body> overlap(lfem_world* w, const double lo[3], const double hi[3],
                               lfem_query_filter f = lfem_query_filter_default()) {
    uint32_t count = 0;
    lfem_world_overlap_box(w, lo, hi, f, nullptr, 0, &count);
    std::vector<lfem_body> out(count);
    EXPECT_EQ(lfem_world_overlap_box(w, lo, hi, f, out.data(), count, &count), LFEM_OK) << lfem_last_error();
    return out;
}

}  // namespace lfem_test
