#include "skin/skin.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "common/box_tree.h"
#include "common/closest_point.h"
#include "common/error.h"

namespace lfem {
namespace {

Vec3 corner(const SkinTets& m, uint32_t e, int k) {
    const uint32_t i = m.tets[std::size_t(e) * m.nodes_per_tet + k];
    return Vec3(m.X[3 * std::size_t(i)], m.X[3 * std::size_t(i) + 1], m.X[3 * std::size_t(i) + 2]);
}

Aabb tet_box(const SkinTets& m, uint32_t e) {
    Aabb b = empty_box();
    for (int k = 0; k < 4; ++k) {
        const Vec3 c = corner(m, e, k);
        for (int d = 0; d < 3; ++d) b.lo[d] = std::min(b.lo[d], c[d]), b.hi[d] = std::max(b.hi[d], c[d]);
    }
    return b;
}

// Where a vertex stands in one tet: its barycentric weights (affine: outside the tet some are
// negative) and its distance from the tet (0 inside).
struct Placement {
    uint32_t tet = UINT32_MAX;
    double w[4] = {0, 0, 0, 0};
    double depth = -HUGE_VAL;   // the smallest weight: >= 0 inside, larger deeper inside
    double distance = HUGE_VAL;  // m
};

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
    if (s.depth >= 0.0) {
        s.distance = 0.0;
        return s;
    }
    // Outside: the distance to the nearest of the four faces.
    static const int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (const auto& f : face) {
        double w[3];
        const Vec3 q = closest_on_triangle(p, corner(m, e, f[0]), corner(m, e, f[1]), corner(m, e, f[2]), w);
        s.distance = std::min(s.distance, (q - p).norm());
    }
    return s;
}

// The better of two placements: nearer, then deeper inside, then the lower tet.
bool better(const Placement& a, const Placement& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
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
    skin.nodes.resize(4 * std::size_t(vertex_count));
    skin.weights.resize(4 * std::size_t(vertex_count));
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
        if (!(best.distance <= reach)) throw Error(LFEM_INVALID_ARGUMENT, vertex_far(v, p, best, reach));
        for (int k = 0; k < 4; ++k) {
            skin.nodes[4 * std::size_t(v) + k] = mesh.tets[std::size_t(best.tet) * mesh.nodes_per_tet + k];
            skin.weights[4 * std::size_t(v) + k] = best.w[k];
        }
    }
    skin.triangles.assign(triangles, triangles + 3 * std::size_t(triangle_count));
    return skin;
}

void deform_skin(const Skin& skin, const double* x, std::vector<double>& positions, std::vector<double>* normals) {
    const uint32_t nv = skin.vertex_count();
    positions.assign(3 * std::size_t(nv), 0.0);
    for (std::size_t v = 0; v < nv; ++v)
        for (int k = 0; k < 4; ++k) {
            const double w = skin.weights[4 * v + k];
            const double* xn = &x[3 * std::size_t(skin.nodes[4 * v + k])];
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
