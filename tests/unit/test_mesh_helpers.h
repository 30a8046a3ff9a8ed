// Geometric and topological facts about tet meshes, computed independently of the library code
// under test (std::map instead of the library's face sort), for the mesh unit tests.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.h"

namespace lfem::test {

inline const double* node(const TetMesh& m, uint32_t i) { return &m.positions[3 * std::size_t(i)]; }

inline double six_volume(const double* a, const double* b, const double* c, const double* d) {
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
           u[2] * (v[0] * w[1] - v[1] * w[0]);
}

inline double tet_six_volume(const TetMesh& m, uint32_t t) {
    const uint32_t* q = &m.tets[4 * std::size_t(t)];
    return six_volume(node(m, q[0]), node(m, q[1]), node(m, q[2]), node(m, q[3]));
}

inline double mesh_volume(const TetMesh& m) {
    double sum = 0.0;
    for (uint32_t t = 0; t < m.tet_count(); ++t) sum += tet_six_volume(m, t);
    return sum / 6.0;
}

inline double smallest_six_volume(const TetMesh& m) {
    double smallest = HUGE_VAL;
    for (uint32_t t = 0; t < m.tet_count(); ++t)
        smallest = std::min(smallest, tet_six_volume(m, t));
    return smallest;
}

inline bool every_node_used(const TetMesh& m) {
    std::vector<bool> used(m.node_count(), false);
    for (uint32_t n : m.tets) used.at(n) = true;
    return std::all_of(used.begin(), used.end(), [](bool u) { return u; });
}

// The largest number of tets sharing one triangle, and the number of triangles in just one.
struct FaceCounts {
    int most_tets_on_a_face = 0;
    std::size_t faces_in_one_tet = 0;
};

inline FaceCounts count_faces(const TetMesh& m) {
    std::map<std::array<uint32_t, 3>, int> faces;
    for (uint32_t t = 0; t < m.tet_count(); ++t)
        for (int skip = 0; skip < 4; ++skip) {
            std::array<uint32_t, 3> f{};
            int k = 0;
            for (int i = 0; i < 4; ++i)
                if (i != skip) f[k++] = m.tets[4 * std::size_t(t) + i];
            std::sort(f.begin(), f.end());
            ++faces[f];
        }
    FaceCounts c;
    for (const auto& [face, count] : faces) {
        c.most_tets_on_a_face = std::max(c.most_tets_on_a_face, count);
        if (count == 1) ++c.faces_in_one_tet;
    }
    return c;
}

// Facts about a triangulated surface (3 node indices per triangle).
struct SurfaceFacts {
    bool closed = true;            // every edge in exactly two triangles
    bool consistent = true;        // ... traversed in opposite directions by them
    long euler = 0;                // V - E + F
    double enclosed_volume = 0.0;  // divergence theorem: sum of a.((b-a)x(c-a)) / 6
    double area = 0.0;
};

inline SurfaceFacts surface_facts(const TetMesh& m, const std::vector<uint32_t>& triangles) {
    SurfaceFacts s;
    std::map<std::pair<uint32_t, uint32_t>, int> directed;  // edge a->b: times used
    std::set<uint32_t> vertices;
    const std::size_t count = triangles.size() / 3;
    for (std::size_t t = 0; t < count; ++t) {
        const uint32_t* tri = &triangles[3 * t];
        for (int i = 0; i < 3; ++i) {
            vertices.insert(tri[i]);
            ++directed[{tri[i], tri[(i + 1) % 3]}];
        }
        const double* a = node(m, tri[0]);
        const double* b = node(m, tri[1]);
        const double* c = node(m, tri[2]);
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        s.enclosed_volume += (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6.0;
        s.area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (const auto& [edge, uses] : directed) {
        const std::pair<uint32_t, uint32_t> reverse{edge.second, edge.first};
        const auto it = directed.find(reverse);
        const int reverse_uses = it == directed.end() ? 0 : it->second;
        if (uses + reverse_uses != 2) s.closed = false;
        if (uses != 1 || reverse_uses != 1) s.consistent = false;
        edges.insert({std::min(edge.first, edge.second), std::max(edge.first, edge.second)});
    }
    s.euler = long(vertices.size()) - long(edges.size()) + long(count);
    return s;
}

}  // namespace lfem::test
