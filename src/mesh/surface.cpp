#include "mesh/surface.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/math.h"

namespace lfem {

void compute_surface_data(const double* X, uint32_t node_count, Surface& s) {
    const std::vector<uint32_t>& tri = s.triangles;
    std::vector<uint8_t> on_boundary(node_count, 0);
    double edges = 0.0;
    for (std::size_t t = 0; t < tri.size(); t += 3)
        for (int v = 0; v < 3; ++v) {
            const uint32_t i = tri[t + v], j = tri[t + (v + 1) % 3];
            on_boundary[i] = 1;
            edges += (Vec3(&X[3 * i]) - Vec3(&X[3 * j])).norm();
        }
    s.edge_length = edges / double(tri.size());
    s.nodes.clear();
    for (uint32_t i = 0; i < on_boundary.size(); ++i)
        if (on_boundary[i]) s.nodes.push_back(i);
    // Feature nodes: where the surface bends by more than 15 degrees (edges, corners). A
    // node inside a flat face of an immovable body adds nothing the other body's nodes do
    // not already enforce, and as a second, redundant support it makes the load jump
    // between the two from step to step (a soft cube resting on a floor shook at 1e-4 m/s
    // with them, 2e-6 m/s without).
    std::vector<double> normal(3 * std::size_t(node_count), 0.0), face(3 * (tri.size() / 3));
    for (std::size_t t = 0; t < tri.size(); t += 3) {
        const uint32_t* f = &tri[t];
        const Vec3 n = (Vec3(&X[3 * f[1]]) - Vec3(&X[3 * f[0]])).cross(Vec3(&X[3 * f[2]]) - Vec3(&X[3 * f[0]]));
        for (int k = 0; k < 3; ++k) face[t + k] = n[k];
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k) normal[3 * f[v] + k] += n[k];
    }
    std::vector<uint8_t> feature(on_boundary.size(), 0);
    const double cos15 = std::cos(15.0 * 3.14159265358979323846 / 180.0);
    for (std::size_t t = 0; t < tri.size(); t += 3)
        for (int v = 0; v < 3; ++v) {
            const uint32_t i = tri[t + v];
            if (Vec3(&normal[3 * i]).normalized().dot(Vec3(&face[t]).normalized()) < cos15) feature[i] = 1;
        }
    s.feature_nodes.clear();
    for (uint32_t i = 0; i < feature.size(); ++i)
        if (feature[i]) s.feature_nodes.push_back(i);
}

std::vector<uint32_t> split_quadratic_faces(const std::vector<uint32_t>& faces) {
    std::vector<uint32_t> triangles;
    triangles.reserve(2 * faces.size());
    for (std::size_t f = 0; f + 6 <= faces.size(); f += 6) {
        const uint32_t a = faces[f], b = faces[f + 1], c = faces[f + 2];
        const uint32_t ab = faces[f + 3], bc = faces[f + 4], ca = faces[f + 5];
        triangles.insert(triangles.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    return triangles;
}

void compute_triangle_elements(const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet, Surface& s) {
    const uint32_t triangles = s.triangle_count();
    s.triangle_element.assign(triangles, UINT32_MAX);
    if (tet_count == 0) return;
    // Each boundary face by its sorted corners: a flat triangle's own, or the corners of the
    // 6-node face whose four flat triangles it is one of.
    const bool quadratic = !s.quadratic_faces.empty();
    using Key = std::array<uint32_t, 4>;  // sorted corners, then the face
    std::vector<Key> faces;
    const uint32_t face_count = quadratic ? uint32_t(s.quadratic_faces.size() / 6) : triangles;
    faces.reserve(face_count);
    for (uint32_t f = 0; f < face_count; ++f) {
        const uint32_t* c = quadratic ? &s.quadratic_faces[6 * std::size_t(f)] : &s.triangles[3 * std::size_t(f)];
        Key k = {c[0], c[1], c[2], f};
        std::sort(k.begin(), k.begin() + 3);
        faces.push_back(k);
    }
    std::sort(faces.begin(), faces.end());
    static constexpr int kFaceCorners[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    for (uint32_t e = 0; e < tet_count; ++e)
        for (const auto& corners : kFaceCorners) {
            Key k = {0, 0, 0, 0};
            for (int i = 0; i < 3; ++i) k[i] = tets[std::size_t(nodes_per_tet) * e + corners[i]];
            std::sort(k.begin(), k.begin() + 3);
            const auto it = std::lower_bound(faces.begin(), faces.end(), k);
            if (it == faces.end() || (*it)[0] != k[0] || (*it)[1] != k[1] || (*it)[2] != k[2]) continue;
            const uint32_t f = (*it)[3];
            if (quadratic)
                for (uint32_t t = 4 * f; t < 4 * f + 4; ++t) s.triangle_element[t] = e;
            else
                s.triangle_element[f] = e;
        }
}

void compute_node_elements(const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet, uint32_t node_count,
                           Surface& s) {
    std::vector<uint8_t> on_surface(node_count, 0);
    for (uint32_t i : s.triangles) on_surface[i] = 1;
    s.node_element_begin.assign(std::size_t(node_count) + 1, 0);
    for (std::size_t k = 0; k < std::size_t(nodes_per_tet) * tet_count; ++k)
        if (on_surface[tets[k]]) ++s.node_element_begin[tets[k] + 1];
    for (uint32_t i = 0; i < node_count; ++i) s.node_element_begin[i + 1] += s.node_element_begin[i];
    s.node_elements.resize(s.node_element_begin[node_count]);
    std::vector<uint32_t> next(s.node_element_begin.begin(), s.node_element_begin.end() - 1);
    for (uint32_t e = 0; e < tet_count; ++e)
        for (uint32_t v = 0; v < nodes_per_tet; ++v) {
            const uint32_t i = tets[std::size_t(nodes_per_tet) * e + v];
            if (on_surface[i]) s.node_elements[next[i]++] = e;
        }
}

void compute_sharp_edges(const double* X, Surface& s) {
    // Every triangle's edges by their sorted nodes, then the triangle and the edge's place in it:
    // an edge's (one or two) triangles side by side.
    using Key = std::array<uint32_t, 4>;
    std::vector<Key> sides;
    sides.reserve(s.triangles.size());
    for (uint32_t t = 0; t < s.triangle_count(); ++t)
        for (uint32_t v = 0; v < 3; ++v) {
            const uint32_t i = s.triangles[3 * std::size_t(t) + v], j = s.triangles[3 * std::size_t(t) + (v + 1) % 3];
            sides.push_back({std::min(i, j), std::max(i, j), t, v});
        }
    std::sort(sides.begin(), sides.end());
    const auto unit_normal = [&](uint32_t t) { return unit_triangle_normal(X, &s.triangles[3 * std::size_t(t)]); };
    const double cos15 = std::cos(15.0 * 3.14159265358979323846 / 180.0);
    s.sharp_edges.clear();
    s.fold_edges.clear();
    s.triangle_edges.assign(s.triangles.size(), UINT32_MAX);
    constexpr uint32_t kFold = 0x80000000u;  // a fold's place, until the sharp edges are counted
    for (std::size_t k = 0; k < sides.size();) {
        std::size_t end = k + 1;
        while (end < sides.size() && sides[end][0] == sides[k][0] && sides[end][1] == sides[k][1]) ++end;
        // A border (one triangle) or a bend (two meeting at an angle); an edge of three or more
        // triangles (a non-manifold surface) has no outer side to turn a normal to: left out.
        const bool border = end == k + 1;
        uint32_t id = UINT32_MAX;
        if (border || (end == k + 2 && unit_normal(sides[k][2]).dot(unit_normal(sides[k + 1][2])) < cos15)) {
            id = uint32_t(s.sharp_edges.size() / 4);
            s.sharp_edges.insert(s.sharp_edges.end(), {sides[k][0], sides[k][1], sides[k][2], border ? UINT32_MAX : sides[k + 1][2]});
        } else if (end == k + 2) {
            id = kFold | uint32_t(s.fold_edges.size() / 4);
            s.fold_edges.insert(s.fold_edges.end(), {sides[k][0], sides[k][1], sides[k][2], sides[k + 1][2]});
        }
        for (std::size_t q = k; q < end && id != UINT32_MAX; ++q) s.triangle_edges[3 * std::size_t(sides[q][2]) + sides[q][3]] = id;
        k = end;
    }
    const uint32_t sharp = uint32_t(s.sharp_edges.size() / 4);
    for (uint32_t& id : s.triangle_edges)
        if (id != UINT32_MAX && (id & kFold)) id = sharp + (id & ~kFold);
}

void compute_node_triangles(uint32_t node_count, Surface& s) {
    const uint32_t triangles = s.triangle_count();
    s.node_triangle_begin.assign(std::size_t(node_count) + 1, 0);
    for (uint32_t i : s.triangles) ++s.node_triangle_begin[i + 1];
    for (uint32_t i = 0; i < node_count; ++i) s.node_triangle_begin[i + 1] += s.node_triangle_begin[i];
    s.node_triangles.resize(s.triangles.size());
    std::vector<uint32_t> next(s.node_triangle_begin.begin(), s.node_triangle_begin.end() - 1);
    for (uint32_t t = 0; t < triangles; ++t)  // ascending per node: triangles in order
        for (int v = 0; v < 3; ++v) s.node_triangles[next[s.triangles[3 * std::size_t(t) + v]]++] = t;
}

}  // namespace lfem
