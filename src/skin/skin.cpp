#include "skin/skin.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/box_tree.h"
#include "common/closest_point.h"
#include "common/error.h"
#include "skin/quadratic_coordinates.h"

namespace lfem {
namespace {

Vec3 node(const SkinTets& m, uint32_t e, uint32_t k) {
    const uint32_t i = m.tets[std::size_t(e) * m.nodes_per_tet + k];
    return Vec3(m.X[3 * std::size_t(i)], m.X[3 * std::size_t(i) + 1], m.X[3 * std::size_t(i) + 2]);
}

Vec3 corner(const SkinTets& m, uint32_t e, int k) { return node(m, e, uint32_t(k)); }

// The box of a tet's corners; of a 10-node tet grown to hold the curved element too: its map
// departs from the corners' affine one by sum_e 4 L_i L_j d_e (d_e: how far edge e's mid-edge
// node sits from the edge's midpoint), and sum_{i<j} 4 L_i L_j <= 3/2 inside the element.
Aabb tet_box(const SkinTets& m, uint32_t e) {
    Aabb b = empty_box();
    for (int k = 0; k < 4; ++k) {
        const Vec3 c = corner(m, e, k);
        for (int d = 0; d < 3; ++d) b.lo[d] = std::min(b.lo[d], c[d]), b.hi[d] = std::max(b.hi[d], c[d]);
    }
    if (m.nodes_per_tet != kQuadraticTetNodes) return b;
    double bulge = 0.0;
    for (int k = 0; k < 6; ++k) {
        const Vec3 mid = 0.5 * (corner(m, e, kQuadraticTetEdges[k][0]) + corner(m, e, kQuadraticTetEdges[k][1]));
        bulge = std::max(bulge, (node(m, e, uint32_t(4 + k)) - mid).norm());
    }
    return grown(b, 1.5 * bulge);
}

// Where a vertex stands in one tet: its weights (nodes_per_tet of them; outside the tet some
// are negative) and its distance from the tet (0 inside).
struct Placement {
    uint32_t tet = UINT32_MAX;
    double w[kQuadraticTetNodes] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    double depth = -HUGE_VAL;   // the smallest coordinate: >= 0 inside, larger deeper inside
    double distance = HUGE_VAL;  // m
    bool corners_only = false;   // a curved 10-node tet whose coordinates Newton did not find
};

// A 10-node tet's weights of the point: its shape functions at the coordinates L of the
// element's map (L in: the corners' coordinates). Where Newton's iterations fail, the corners'
// weights stay (the mid-edge nodes' 0), which reproduce the point and affine motions as well.
void quadratic_weights(const SkinTets& m, uint32_t e, const Vec3& p, Placement& s) {
    Vec3 X[kQuadraticTetNodes];
    for (uint32_t a = 0; a < kQuadraticTetNodes; ++a) X[a] = node(m, e, a);
    double L[4] = {s.w[0], s.w[1], s.w[2], s.w[3]};
    if (!quadratic_coordinates(X, p, L)) {
        s.corners_only = true;
        return;
    }
    quadratic_shape_values_at(L, s.w);
    s.depth = std::min({L[0], L[1], L[2], L[3]});
}

Placement place(const SkinTets& m, uint32_t e, const Vec3& p) {
    const Vec3 x0 = corner(m, e, 0);
    Mat3 D;
    D << corner(m, e, 1) - x0, corner(m, e, 2) - x0, corner(m, e, 3) - x0;
    const Vec3 l = D.inverse() * (p - x0);
    Placement s;
    s.tet = e;
    s.w[1] = l[0], s.w[2] = l[1], s.w[3] = l[2];
    s.w[0] = 1.0 - l[0] - l[1] - l[2];
    s.depth = std::min({s.w[0], s.w[1], s.w[2], s.w[3]});
    const bool in_corners = s.depth >= 0.0;
    if (m.nodes_per_tet == kQuadraticTetNodes) quadratic_weights(m, e, p, s);
    if (s.depth >= 0.0 || in_corners) {  // inside the element (or its corners' straight tet)
        s.distance = 0.0;
        return s;
    }
    // Outside: the distance to the nearest of the four faces of the corners' tet.
    static const int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (const auto& f : face) {
        double w[3];
        const Vec3 q = closest_on_triangle(p, corner(m, e, f[0]), corner(m, e, f[1]), corner(m, e, f[2]), w);
        s.distance = std::min(s.distance, (q - p).norm());
    }
    return s;
}

// The better of two placements: nearer, then by the element's own coordinates (rather than its
// corners' alone), then deeper inside, then the lower tet.
bool better(const Placement& a, const Placement& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.corners_only != b.corners_only) return !a.corners_only;
    if (a.depth != b.depth) return a.depth > b.depth;
    return a.tet < b.tet;
}

std::string vertex_far(uint32_t v, const Vec3& p, const Placement& best, double reach) {
    char buf[256];
    if (best.tet == UINT32_MAX)
        std::snprintf(buf, sizeof buf,
                      "positions: vertex %u at (%.6g, %.6g, %.6g) m lies farther than %.6g m (one mean boundary "
                      "edge) from every tet of the body",
                      v, p[0], p[1], p[2], reach);
    else
        std::snprintf(buf, sizeof buf,
                      "positions: vertex %u at (%.6g, %.6g, %.6g) m lies %.6g m from the nearest tet of the body, "
                      "farther than %.6g m (one mean boundary edge)",
                      v, p[0], p[1], p[2], best.distance, reach);
    return buf;
}

}  // namespace

Skin bind_skin(const SkinTets& mesh, const double* positions, uint32_t vertex_count, const uint32_t* triangles,
               uint32_t triangle_count, double reach) {
    const uint32_t tets = mesh.tet_count();
    std::vector<double> centroid(3 * std::size_t(tets));
    for (uint32_t e = 0; e < tets; ++e) {
        Vec3 c = Vec3::Zero();
        for (int k = 0; k < 4; ++k) c += corner(mesh, e, k);
        for (int d = 0; d < 3; ++d) centroid[3 * std::size_t(e) + d] = c[d] / 4.0;
    }
    BoxTree tree;
    tree.build(centroid.data(), tets);
    tree.refit([&](uint32_t e) { return tet_box(mesh, e); });
    Skin skin;
    const uint32_t per = mesh.nodes_per_tet;
    skin.nodes_per_vertex = per;
    skin.nodes.resize(per * std::size_t(vertex_count));
    skin.weights.resize(per * std::size_t(vertex_count));
    for (uint32_t v = 0; v < vertex_count; ++v) {
        const Vec3 p(positions[3 * std::size_t(v)], positions[3 * std::size_t(v) + 1], positions[3 * std::size_t(v) + 2]);
        Placement best;
        auto consider = [&](uint32_t e) {
            const Placement s = place(mesh, e, p);
            if (better(s, best)) best = s;
        };
        // The tets around the point first; only a vertex inside none looks within reach.
        Aabb box;
        for (int d = 0; d < 3; ++d) box.lo[d] = box.hi[d] = p[d];
        tree.query(box, [&](uint32_t e) {
            if (overlaps(tet_box(mesh, e), box)) consider(e);
        });
        if (!(best.distance == 0.0)) {
            const Aabb near = grown(box, reach);
            tree.query(near, [&](uint32_t e) {
                if (overlaps(tet_box(mesh, e), near)) consider(e);
            });
        }
        if (!(best.distance <= reach)) throw Error(Status::invalid_argument, vertex_far(v, p, best, reach));
        for (uint32_t k = 0; k < per; ++k) {
            skin.nodes[per * std::size_t(v) + k] = mesh.tets[std::size_t(best.tet) * per + k];
            skin.weights[per * std::size_t(v) + k] = best.w[k];
        }
    }
    skin.triangles.assign(triangles, triangles + 3 * std::size_t(triangle_count));
    return skin;
}

void deform_skin(const Skin& skin, const double* x, std::vector<double>& positions, std::vector<double>* normals) {
    const uint32_t nv = skin.vertex_count();
    positions.assign(3 * std::size_t(nv), 0.0);
    const std::size_t per = skin.nodes_per_vertex;
    for (std::size_t v = 0; v < nv; ++v)
        for (std::size_t k = 0; k < per; ++k) {
            const double w = skin.weights[per * v + k];
            const double* xn = &x[3 * std::size_t(skin.nodes[per * v + k])];
            for (int d = 0; d < 3; ++d) positions[3 * v + d] += w * xn[d];
        }
    if (!normals) return;
    std::vector<double>& n = *normals;
    n.assign(3 * std::size_t(nv), 0.0);
    const double* p = positions.data();
    for (std::size_t t = 0; t < skin.triangle_count(); ++t) {
        const uint32_t* f = &skin.triangles[3 * t];
        const Vec3 a(&p[3 * std::size_t(f[0])]), b(&p[3 * std::size_t(f[1])]), c(&p[3 * std::size_t(f[2])]);
        const Vec3 area2 = (b - a).cross(c - a);
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) n[3 * std::size_t(f[k]) + d] += area2[d];
    }
    for (std::size_t v = 0; v < nv; ++v) {
        const double len = Vec3(&n[3 * v]).norm();
        for (int d = 0; d < 3; ++d) n[3 * v + d] = len > 0.0 ? n[3 * v + d] / len : 0.0;
    }
}

}  // namespace lfem
