// Small C++ conveniences over the C API for the tests: a world that frees itself, a box body,
// positions as vectors, and a fingerprint of everything a user can read (to prove a failed
// call changed nothing, bit for bit).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstring>
#include <string>
#include <vector>

#include "lfem.h"

namespace lfem_test {

struct World {
    lfem_world* w = nullptr;
    explicit World(const lfem_world_def& def) {
        EXPECT_EQ(lfem_world_create(&def, &w), LFEM_OK) << lfem_last_error();
    }
    World() : World(lfem_world_def_default()) {}
    ~World() { lfem_world_destroy(w); }
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    operator lfem_world*() const { return w; }
};

struct Mesh {
    lfem_mesh* m = nullptr;
    ~Mesh() { lfem_mesh_destroy(m); }
    uint32_t nodes() const { return lfem_mesh_get_node_count(m); }
    uint32_t tets() const { return lfem_mesh_get_tet_count(m); }
    uint32_t nodes_per_tet() const { return lfem_mesh_get_nodes_per_tet(m); }
};

inline void make_box_mesh(Mesh& mesh, double sx, double sy, double sz, uint32_t nx, uint32_t ny,
                          uint32_t nz, double ox = 0, double oy = 0, double oz = 0) {
    const double size[3] = {sx, sy, sz};
    const uint32_t cells[3] = {nx, ny, nz};
    ASSERT_EQ(lfem_mesh_create_box(size, cells, &mesh.m), LFEM_OK) << lfem_last_error();
    const double offset[3] = {ox, oy, oz};
    ASSERT_EQ(lfem_mesh_translate(mesh.m, offset), LFEM_OK) << lfem_last_error();
}

// A box of 10-node tets (lfem_mesh_make_quadratic).
inline void make_quadratic_box_mesh(Mesh& mesh, double sx, double sy, double sz, uint32_t nx, uint32_t ny,
                                    uint32_t nz, double ox = 0, double oy = 0, double oz = 0) {
    make_box_mesh(mesh, sx, sy, sz, nx, ny, nz, ox, oy, oz);
    ASSERT_EQ(lfem_mesh_make_quadratic(mesh.m), LFEM_OK) << lfem_last_error();
}

inline const char* model_name(lfem_model m) {
    switch (m) {
        case LFEM_MODEL_LINEAR: return "linear";
        case LFEM_MODEL_PAPER: return "paper";
        case LFEM_MODEL_COROTATIONAL: return "corotational";
        default: return "neo_hookean";
    }
}

// A body with the mesh: lfem_body_add_mesh, or lfem_body_add_quadratic_mesh for 10-node tets.
inline lfem_body add_body(lfem_world* w, const lfem_body_def& def, const Mesh& mesh) {
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &def, &b), LFEM_OK) << lfem_last_error();
    const auto add = mesh.nodes_per_tet() == 10 ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh;
    EXPECT_EQ(add(w, b, lfem_mesh_get_positions(mesh.m), mesh.nodes(), lfem_mesh_get_tets(mesh.m), mesh.tets()),
              LFEM_OK)
        << lfem_last_error();
    return b;
}

// A static body holding one plane shape (the default: z = 0, facing +z): a floor.
inline lfem_body add_plane_floor(lfem_world* w) {
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    lfem_body floor{};
    EXPECT_EQ(lfem_body_create(w, &d, &floor), LFEM_OK) << lfem_last_error();
    const lfem_shape_def plane = lfem_shape_def_default();
    EXPECT_EQ(lfem_body_add_shape(w, floor, &plane, nullptr), LFEM_OK) << lfem_last_error();
    return floor;
}

inline uint32_t node_count(lfem_world* w, lfem_body b) {
    uint32_t n = 0;
    EXPECT_EQ(lfem_body_get_node_count(w, b, &n), LFEM_OK);
    return n;
}

inline std::vector<double> positions(lfem_world* w, lfem_body b) {
    std::vector<double> x(3 * node_count(w, b));
    EXPECT_EQ(lfem_body_get_positions(w, b, x.data(), uint32_t(x.size() / 3)), LFEM_OK);
    return x;
}

inline std::vector<double> velocities(lfem_world* w, lfem_body b) {
    std::vector<double> v(3 * node_count(w, b));
    EXPECT_EQ(lfem_body_get_velocities(w, b, v.data(), uint32_t(v.size() / 3)), LFEM_OK);
    return v;
}

inline lfem_world_stats stats(lfem_world* w) {
    lfem_world_stats s{};
    EXPECT_EQ(lfem_world_get_stats(w, &s), LFEM_OK);
    return s;
}

inline double stable_step(lfem_world* w) {
    double h = 0;
    EXPECT_EQ(lfem_world_get_stable_step(w, &h), LFEM_OK);
    return h;
}

// Nodes of a body within a box.
inline std::vector<uint32_t> nodes_in_box(lfem_world* w, lfem_body b, const double lo[3],
                                          const double hi[3]) {
    uint32_t count = 0;
    lfem_body_find_nodes_in_box(w, b, lo, hi, nullptr, 0, &count);
    std::vector<uint32_t> nodes(count);
    EXPECT_EQ(lfem_body_find_nodes_in_box(w, b, lo, hi, nodes.data(), count, &count), LFEM_OK);
    return nodes;
}

// Sum of the contact forces on body `on` (N): nodes of `on` get the force, triangles of `on`
// get its opposite.
inline void contact_force_on(lfem_world* w, lfem_body on, double out[3]) {
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
    out[0] = out[1] = out[2] = 0;
    for (const lfem_contact& k : c) {
        const double sign = k.body_a.index == on.index ? 1.0 : (k.body_b.index == on.index ? -1.0 : 0.0);
        for (int d = 0; d < 3; ++d) out[d] += sign * k.force[d];
    }
}

// Sum of the contact forces (N) that body `from` puts on body `on`: contacts of a node of `on`
// on a face or shape of `from` count their force, those of a node of `from` on a face of `on`
// its opposite; contacts with any other body are left out.
inline void contact_force_between(lfem_world* w, lfem_body on, lfem_body from, double out[3]) {
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
    auto same = [](lfem_body a, lfem_body b) { return a.index == b.index && a.generation == b.generation; };
    out[0] = out[1] = out[2] = 0;
    for (const lfem_contact& k : c) {
        const double sign = same(k.body_a, on) && same(k.body_b, from) ? 1.0
                            : same(k.body_a, from) && same(k.body_b, on) ? -1.0
                                                                         : 0.0;
        for (int d = 0; d < 3; ++d) out[d] += sign * k.force[d];
    }
}

// The events of the last step (asked for their count first, as a caller does).
inline std::vector<lfem_event> events_of(lfem_world* w) {
    uint32_t count = 0;
    const lfem_status asked = lfem_world_get_events(w, nullptr, 0, &count);
    EXPECT_EQ(asked, count ? LFEM_BUFFER_TOO_SMALL : LFEM_OK);
    std::vector<lfem_event> out(count);
    EXPECT_EQ(lfem_world_get_events(w, out.data(), count, &count), LFEM_OK);
    return out;
}

// The last step's events of one type.
inline int count_events(lfem_world* w, lfem_event_type type) {
    int k = 0;
    for (const lfem_event& e : events_of(w)) k += e.type == type;
    return k;
}

// A cube of 10 cm (2^3 cells) at the origin, linear, nu = 0, E = 1e5 Pa, stretched by `factor`
// along x (lfem_body_set_positions): a uniform strain eps = factor - 1 that linear tets take
// exactly, holding W = E eps^2 V / 2 with no lateral stress. Returns the cube.
inline lfem_body stretched_linear_cube(lfem_world* w, Mesh& m, double factor) {
    make_box_mesh(m, 0.1, 0.1, 0.1, 2, 2, 2, 0, 0, 0);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_LINEAR;
    d.poisson_ratio = 0.0;
    d.young_modulus = 1e5;
    const lfem_body b = add_body(w, d, m);
    std::vector<double> x = positions(w, b);
    for (size_t i = 0; i < x.size(); i += 3) x[i] *= factor;
    EXPECT_EQ(lfem_body_set_positions(w, b, x.data(), uint32_t(x.size() / 3)), LFEM_OK) << lfem_last_error();
    return b;
}

// Root mean square of a body's node speeds (m/s).
// A body's momentum and angular momentum about the origin.
struct Momenta {
    double P[3], L[3];
};

inline Momenta momenta(lfem_world* w, lfem_body b) {
    Momenta m{};
    EXPECT_EQ(lfem_body_get_momentum(w, b, m.P, m.L), LFEM_OK);
    return m;
}

inline double rms_velocity(lfem_world* w, lfem_body b) {
    const std::vector<double> v = velocities(w, b);
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s / (v.size() / 3));
}

// Every byte a user can read back about the given bodies and the world.
inline std::vector<unsigned char> fingerprint(lfem_world* w, const std::vector<lfem_body>& bodies) {
    std::vector<unsigned char> out;
    auto append = [&](const void* p, size_t n) {
        const unsigned char* c = static_cast<const unsigned char*>(p);
        out.insert(out.end(), c, c + n);
    };
    const lfem_world_stats s = stats(w);
    append(&s, sizeof s);
    for (int k = 0; k < LFEM_WARNING_KIND_COUNT; ++k) {  // without the body's generation: it
        lfem_warning warning{};                            // is process-wide (see below)
        lfem_world_get_warning(w, lfem_warning_kind(k), &warning);
        append(&warning.count, sizeof warning.count);
        append(&warning.last_time, sizeof warning.last_time);
        append(&warning.last_body.index, sizeof warning.last_body.index);
    }
    for (lfem_body b : bodies) {
        const int valid = lfem_body_is_valid(w, b);
        append(&valid, sizeof valid);
        if (!valid) continue;
        const bool nodes = node_count(w, b) > 0;  // a body of shapes alone has none
        const std::vector<double> x = nodes ? positions(w, b) : std::vector<double>();
        const std::vector<double> v = nodes ? velocities(w, b) : std::vector<double>();
        append(x.data(), x.size() * sizeof(double));
        append(v.data(), v.size() * sizeof(double));
        uint32_t tets = 0, tris = 0;
        lfem_body_get_tet_count(w, b, &tets);
        lfem_body_get_boundary_triangle_count(w, b, &tris);
        append(&tets, sizeof tets);
        append(&tris, sizeof tris);
        std::vector<double> vm(tets);
        if (tets) lfem_body_get_von_mises_stress(w, b, vm.data(), tets);
        append(vm.data(), vm.size() * sizeof(double));
        uint32_t skins = 0;
        lfem_body_get_skin_count(w, b, &skins);
        append(&skins, sizeof skins);
        for (uint32_t k = 0; k < skins; ++k) {  // every skin: its triangles and vertices
            uint32_t nv = 0, nt = 0;
            lfem_body_get_skin_sizes(w, b, k, &nv, &nt);
            std::vector<uint32_t> t(3 * std::size_t(nt));
            std::vector<double> p(3 * std::size_t(nv)), n(3 * std::size_t(nv));
            lfem_body_get_skin_triangles(w, b, k, t.data(), nt);
            lfem_body_get_skin_vertices(w, b, k, p.data(), n.data(), nv);
            append(t.data(), t.size() * sizeof(uint32_t));
            append(p.data(), p.size() * sizeof(double));
            append(n.data(), n.size() * sizeof(double));
        }
    }
    return out;
}

// Sum of signed tet volumes of a body's current configuration (m^3); the corners' tets of
// 10-node tets (nodes_per_tet 10).
inline double volume(const std::vector<double>& x, const uint32_t* tets, uint32_t tet_count,
                     uint32_t nodes_per_tet = 4) {
    double v = 0;
    for (uint32_t e = 0; e < tet_count; ++e) {
        const uint32_t* t = tets + std::size_t(nodes_per_tet) * e;
        const double* a = &x[3 * t[0]];
        const double* b = &x[3 * t[1]];
        const double* c = &x[3 * t[2]];
        const double* d = &x[3 * t[3]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double p[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double q[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        v += (u[0] * (p[1] * q[2] - p[2] * q[1]) - u[1] * (p[0] * q[2] - p[2] * q[0]) +
              u[2] * (p[0] * q[1] - p[1] * q[0])) / 6.0;
    }
    return v;
}

// How far point y lies inside tet q (4 node indices into x, 3 coordinates per node): its
// smallest barycentric weight, negative outside; -HUGE_VAL for an inverted or flat tet, which
// has no inside. The tests count a node as inside another body's volume when this is above
// 0.02 for one of its tets: 2 % of the tet's height, twenty times the contact solve's residual
// (1e-3 of an edge), so a node resting on a face never counts.
inline double depth_in_tet(const std::vector<double>& x, const uint32_t* q, const double* y) {
    double e[3][3];
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) e[c][k] = x[3 * q[c + 1] + k] - x[3 * q[0] + k];
    auto det3 = [](const double* a, const double* b, const double* c) {
        return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    };
    const double det = det3(e[0], e[1], e[2]);
    if (!(det > 0.0)) return -HUGE_VAL;
    const double d[3] = {y[0] - x[3 * q[0]], y[1] - x[3 * q[0] + 1], y[2] - x[3 * q[0] + 2]};
    const double b1 = det3(d, e[1], e[2]) / det, b2 = det3(e[0], d, e[2]) / det, b3 = det3(e[0], e[1], d) / det;
    return std::min(std::min(1.0 - b1 - b2 - b3, b1), std::min(b2, b3));
}

// Distance from point y to the triangle with corners a, b, c (the closest point found by the
// triangle's Voronoi regions: corners, edges, face).
inline double distance_to_triangle(const double* y, const double* a, const double* b, const double* c) {
    auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    for (int k = 0; k < 3; ++k) ab[k] = b[k] - a[k], ac[k] = c[k] - a[k], ap[k] = y[k] - a[k], bp[k] = y[k] - b[k], cp[k] = y[k] - c[k];
    auto from = [&](const double* o, const double* u, double s, const double* v, double t) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) {
            const double q = o[k] + s * u[k] + t * v[k] - y[k];
            d2 += q * q;
        }
        return std::sqrt(d2);
    };
    const double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d1 <= 0 && d2 <= 0) return from(a, ab, 0, ac, 0);
    if (d3 >= 0 && d4 <= d3) return from(a, ab, 1, ac, 0);
    if (d6 >= 0 && d5 <= d6) return from(a, ab, 0, ac, 1);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return from(a, ab, d1 / (d1 - d3), ac, 0);
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return from(a, ab, 0, ac, d2 / (d2 - d6));
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return from(a, ab, 1 - w, ac, w);
    }
    const double den = va + vb + vc;
    return from(a, ab, vb / den, ac, vc / den);
}

// A body's geometry as the depth measure below reads it: positions, tets (4 nodes each) and
// boundary triangles, all in the caller's numbering.
struct BodyShape {
    std::vector<double> x;
    const uint32_t* tets = nullptr;
    uint32_t tet_count = 0;
    std::vector<uint32_t> triangles;
};

inline BodyShape body_shape(lfem_world* w, lfem_body b, const Mesh& mesh) {
    BodyShape s;
    s.x = positions(w, b);
    s.tets = lfem_mesh_get_tets(mesh.m);
    s.tet_count = mesh.tets();
    uint32_t count = 0;
    EXPECT_EQ(lfem_body_get_boundary_triangle_count(w, b, &count), LFEM_OK);
    s.triangles.resize(3 * std::size_t(count));
    EXPECT_EQ(lfem_body_get_boundary_triangles(w, b, s.triangles.data(), count), LFEM_OK);
    return s;
}

// How far point y lies inside a body: 0 when it lies in none of its tets, else its distance
// from the body's surface, the true depth of a node that has passed through it (a node at an
// interior face between two tets, in neither by much, is as deep as it is). `own`: y is that
// node of the body itself (UINT32_MAX: it is not), whose own tets and triangles are left out
// (it lies on them); `own` and `own2`: y is a point of the body's edge between those nodes.
// Brute force, for the small meshes of the tests.
inline double depth_inside(const double* y, const BodyShape& s, uint32_t own = UINT32_MAX, uint32_t own2 = UINT32_MAX) {
    const auto owns = [&](uint32_t v) { return v == own || v == own2; };
    bool inside = false;
    for (uint32_t e = 0; e < s.tet_count && !inside; ++e) {
        const uint32_t* q = s.tets + 4 * e;
        if (owns(q[0]) || owns(q[1]) || owns(q[2]) || owns(q[3])) continue;
        bool beside = false;
        for (int k = 0; k < 3 && !beside; ++k) {
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            for (int a = 0; a < 4; ++a) lo = std::min(lo, s.x[3 * q[a] + k]), hi = std::max(hi, s.x[3 * q[a] + k]);
            beside = y[k] < lo || y[k] > hi;
        }
        inside = !beside && depth_in_tet(s.x, q, y) >= 0.0;
    }
    if (!inside) return 0.0;
    double depth = HUGE_VAL;
    for (std::size_t t = 0; t < s.triangles.size(); t += 3) {
        const uint32_t* f = &s.triangles[t];
        if (owns(f[0]) || owns(f[1]) || owns(f[2])) continue;
        depth = std::min(depth, distance_to_triangle(y, &s.x[3 * f[0]], &s.x[3 * f[1]], &s.x[3 * f[2]]));
    }
    return depth;
}

// The mean edge of a body's boundary triangles (m), as the library scales its tolerances.
inline double mean_boundary_edge(const BodyShape& s) {
    double sum = 0;
    for (std::size_t t = 0; t < s.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t u = s.triangles[t + k], v = s.triangles[t + (k + 1) % 3];
            double d2 = 0;
            for (int c = 0; c < 3; ++c) d2 += (s.x[3 * u + c] - s.x[3 * v + c]) * (s.x[3 * u + c] - s.x[3 * v + c]);
            sum += std::sqrt(d2);
        }
    return sum / double(s.triangles.size());
}

// The deepest of points along a's boundary edges (7 on each, between its nodes) inside b (m).
inline double deepest_edge_point(const BodyShape& a, const BodyShape& b) {
    double deepest = 0;
    for (std::size_t t = 0; t < a.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const double* p = &a.x[3 * a.triangles[t + k]];
            const double* q = &a.x[3 * a.triangles[t + (k + 1) % 3]];
            for (int i = 1; i < 8; ++i) {
                const double u = i / 8.0, y[3] = {p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1]), p[2] + u * (q[2] - p[2])};
                deepest = std::max(deepest, depth_inside(y, b));
            }
        }
    return deepest;
}

// The sharp boundary edges of a body's shape (as lfem counts them at rest): two boundary
// triangles meeting at more than 15 degrees, or a border. Each once, as (u, v) with u < v.
inline std::vector<std::array<uint32_t, 2>> sharp_edges(const BodyShape& s) {
    std::map<std::pair<uint32_t, uint32_t>, std::vector<std::array<double, 3>>> faces;
    for (std::size_t t = 0; t < s.triangles.size(); t += 3) {
        const double* a = &s.x[3 * s.triangles[t]];
        const double* b = &s.x[3 * s.triangles[t + 1]];
        const double* c = &s.x[3 * s.triangles[t + 2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& x : n) x /= len;
        for (int k = 0; k < 3; ++k) {
            const uint32_t p = s.triangles[t + k], q = s.triangles[t + (k + 1) % 3];
            faces[{std::min(p, q), std::max(p, q)}].push_back(n);
        }
    }
    std::vector<std::array<uint32_t, 2>> out;
    for (const auto& [edge, n] : faces)
        if (n.size() != 2 || n[0][0] * n[1][0] + n[0][1] * n[1][1] + n[0][2] * n[1][2] < std::cos(15 * M_PI / 180))
            out.push_back({edge.first, edge.second});
    return out;
}

// The deepest of points along a body's own edges (7 on each, between its nodes) inside its own
// tets (depth_inside, leaving out the tets and triangles of the edge's nodes), m.
inline double deepest_own_edge_point(const BodyShape& s, const std::vector<std::array<uint32_t, 2>>& edges) {
    double deepest = 0;
    for (const auto& e : edges) {
        const double* p = &s.x[3 * e[0]];
        const double* q = &s.x[3 * e[1]];
        for (int i = 1; i < 8; ++i) {
            const double u = i / 8.0, y[3] = {p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1]), p[2] + u * (q[2] - p[2])};
            deepest = std::max(deepest, depth_inside(y, s, e[0], e[1]));
        }
    }
    return deepest;
}

// A self-contact body against itself (tests/physics/test_self_contact.cpp, bench_strip_cases):
// the deepest boundary node inside its own body (in units of its mean boundary edge l), how
// many lie deeper than 0.02 l, and the deepest point of its sharp edges (deepest_own_edge_point,
// l). The last is printed, not bounded: a strip's border edges folded back along each other
// (within 10 degrees of parallel) are left to the nodes (the README's known issues).
struct Inside {
    double deepest = 0;
    int count = 0;
    double deepest_edge = 0;
};

inline Inside inside_itself(lfem_world* w, lfem_body b, const Mesh& mesh, const std::vector<std::array<uint32_t, 2>>& edges) {
    const BodyShape s = body_shape(w, b, mesh);
    const double l = mean_boundary_edge(s);
    std::vector<char> boundary(s.x.size() / 3, 0);
    for (uint32_t v : s.triangles) boundary[v] = 1;
    Inside in;
    for (uint32_t p = 0; p < boundary.size(); ++p) {
        if (!boundary[p]) continue;
        const double depth = depth_inside(&s.x[3 * p], s, p) / l;
        in.deepest = std::max(in.deepest, depth);
        in.count += depth > 0.02;
    }
    in.deepest_edge = deepest_own_edge_point(s, edges) / l;
    return in;
}

// A soft deformable body's definition (rho 1000).
inline lfem_body_def soft_def(lfem_model model, double young_modulus, double poisson_ratio, double damping,
                              double friction, bool self_contact) {
    lfem_body_def d = lfem_body_def_default();
    d.model = model;
    d.young_modulus = young_modulus;
    d.poisson_ratio = poisson_ratio;
    d.damping = damping;
    d.friction = friction;
    d.self_contact = self_contact;
    return d;
}

}  // namespace lfem_test
