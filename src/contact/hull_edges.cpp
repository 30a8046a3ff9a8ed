#include "contact/hull_edges.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lfem {
namespace {

struct HullFace {
    std::array<uint32_t, 3> v;  // counter-clockwise seen from outside
    Vec3 normal;                // unit, outward
    double offset;              // normal . x on the face's plane
};

HullFace make_face(const std::vector<Vec3>& p, uint32_t a, uint32_t b, uint32_t c) {
    HullFace f{{a, b, c}, (p[b] - p[a]).cross(p[c] - p[a]), 0.0};
    const double length = f.normal.norm();
    f.normal = length > 0.0 ? Vec3(f.normal / length) : Vec3::Zero();
    f.offset = f.normal.dot(p[a]);
    return f;
}

// The first four points spanning a volume (0 farthest from the others' first, a line, a plane,
// then the farthest from it), or false.
bool first_tetrahedron(const std::vector<Vec3>& p, double eps, std::array<uint32_t, 4>& t) {
    const uint32_t n = uint32_t(p.size());
    const auto farthest = [&](auto distance) {
        uint32_t best = 0;
        double most = -1.0;
        for (uint32_t i = 0; i < n; ++i)
            if (distance(p[i]) > most) most = distance(p[i]), best = i;
        return std::make_pair(best, most);
    };
    t[0] = 0;
    auto [i1, d1] = farthest([&](const Vec3& x) { return (x - p[0]).norm(); });
    if (!(d1 > eps)) return false;
    const Vec3 axis = (p[i1] - p[0]) / d1;
    auto [i2, d2] = farthest([&](const Vec3& x) { return (x - p[0]).cross(axis).norm(); });
    if (!(d2 > eps)) return false;
    const Vec3 normal = (p[i1] - p[0]).cross(p[i2] - p[0]).normalized();
    auto [i3, d3] = farthest([&](const Vec3& x) { return std::fabs(normal.dot(x - p[0])); });
    if (!(d3 > eps)) return false;
    t = {0, i1, i2, i3};
    return true;
}

// A point lying on an edge of the hull (the middle of a box's edge given as a point) may stay a
// vertex of its triangles, splitting that edge in two: such a point, the end of exactly two
// edges that run on in one line, is taken out and the two made one.
void join_collinear_edges(const std::vector<Vec3>& p, RigidShape& shape) {
    std::vector<uint32_t>& e = shape.hull_edges;
    const uint32_t count = uint32_t(e.size() / 2);
    // Per point: how many edges end there, and the first two of them.
    std::vector<uint32_t> degree(p.size(), 0);
    std::vector<std::array<uint32_t, 2>> ends(p.size());
    for (uint32_t i = 0; i < count; ++i)
        for (int k = 0; k < 2; ++k) {
            const uint32_t v = e[2 * i + k];
            if (degree[v] < 2) ends[v][degree[v]] = i;
            ++degree[v];
        }
    std::vector<bool> dead(count, false);
    const auto other = [&](uint32_t edge, uint32_t v) { return e[2 * edge] == v ? e[2 * edge + 1] : e[2 * edge]; };
    for (uint32_t v = 0; v < p.size(); ++v) {
        if (degree[v] != 2) continue;
        const uint32_t i = ends[v][0], j = ends[v][1], a = other(i, v), b = other(j, v);
        const Vec3 u = p[a] - p[v], w = p[b] - p[v];
        if (!(u.dot(w) < 0.0 && u.cross(w).norm() <= 1e-9 * u.norm() * w.norm())) continue;
        // Edge i runs from a to b now; b's end that was j is i (its degree is the same).
        e[2 * i] = std::min(a, b), e[2 * i + 1] = std::max(a, b);
        dead[j] = true;
        for (uint32_t& end : ends[b])
            if (end == j) end = i;
        degree[v] = 0;
    }
    std::vector<uint32_t> edges;
    std::vector<double> out;
    for (uint32_t i = 0; i < count; ++i) {
        if (dead[i]) continue;
        edges.insert(edges.end(), {e[2 * i], e[2 * i + 1]});
        out.insert(out.end(), shape.hull_edge_out.begin() + 3 * i, shape.hull_edge_out.begin() + 3 * i + 3);
    }
    e.swap(edges);
    shape.hull_edge_out.swap(out);
}

}  // namespace

void compute_hull_edges(RigidShape& shape) {
    shape.hull_edges.clear();
    shape.hull_edge_out.clear();
    if (shape.type != ShapeType::convex_hull || shape.points.size() < 12) return;
    std::vector<Vec3> p(shape.points.size() / 3);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = Vec3(&shape.points[3 * i]);
    double size = 0.0;
    for (const Vec3& x : p) size = std::max(size, (x - p[0]).norm());
    // A point no farther than this outside the hull so far is on it (or inside): left out.
    const double eps = 1e-9 * size;
    std::array<uint32_t, 4> t;
    if (!first_tetrahedron(p, eps, t)) return;
    std::vector<HullFace> faces;
    const Vec3 inside = (p[t[0]] + p[t[1]] + p[t[2]] + p[t[3]]) / 4.0;
    for (const auto& [a, b, c] : {std::array<uint32_t, 3>{t[0], t[1], t[2]}, {t[0], t[1], t[3]}, {t[0], t[2], t[3]},
                                  {t[1], t[2], t[3]}}) {
        HullFace f = make_face(p, a, b, c);
        faces.push_back(f.normal.dot(inside) > f.offset ? make_face(p, a, c, b) : f);
    }
    // Each further point: the faces it sees are replaced by a fan from it to their horizon (the
    // directed edges of seen faces whose reverse belongs to no seen face).
    std::vector<std::array<uint32_t, 2>> seen_edges, horizon;
    std::vector<HullFace> kept;
    for (uint32_t i = 0; i < p.size(); ++i) {
        if (i == t[0] || i == t[1] || i == t[2] || i == t[3]) continue;
        seen_edges.clear();
        for (const HullFace& f : faces)
            if (f.normal.dot(p[i]) - f.offset > eps)
                for (int k = 0; k < 3; ++k) seen_edges.push_back({f.v[k], f.v[(k + 1) % 3]});
        if (seen_edges.empty()) continue;  // inside, or on the hull
        std::sort(seen_edges.begin(), seen_edges.end());
        horizon.clear();
        for (const auto& e : seen_edges)
            if (!std::binary_search(seen_edges.begin(), seen_edges.end(), std::array<uint32_t, 2>{e[1], e[0]}))
                horizon.push_back(e);
        kept.clear();
        for (const HullFace& f : faces)
            if (!(f.normal.dot(p[i]) - f.offset > eps)) kept.push_back(f);
        for (const auto& e : horizon) kept.push_back(make_face(p, e[0], e[1], i));
        faces.swap(kept);
    }
    // The edges of the hull's triangles, each with its (two) faces side by side.
    std::vector<std::array<uint32_t, 3>> sides;  // lower point, higher point, face
    for (uint32_t f = 0; f < faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = faces[f].v[k], b = faces[f].v[(k + 1) % 3];
            sides.push_back({std::min(a, b), std::max(a, b), f});
        }
    std::sort(sides.begin(), sides.end());
    // Two faces at less than 1e-4 rad to each other are one flat face split by a diagonal.
    constexpr double kFlatCos = 1.0 - 5e-9;
    for (std::size_t k = 0; k + 1 < sides.size(); ++k) {
        if (sides[k][0] != sides[k + 1][0] || sides[k][1] != sides[k + 1][1]) continue;
        const Vec3& n0 = faces[sides[k][2]].normal;
        const Vec3& n1 = faces[sides[k + 1][2]].normal;
        if (n0.dot(n1) > kFlatCos) continue;
        const Vec3 out = n0 + n1;
        shape.hull_edges.insert(shape.hull_edges.end(), {sides[k][0], sides[k][1]});
        shape.hull_edge_out.insert(shape.hull_edge_out.end(), {out[0], out[1], out[2]});
    }
    join_collinear_edges(p, shape);
}

}  // namespace lfem
