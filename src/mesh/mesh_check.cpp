// check_tet_mesh: one pass over the tets (indices, repeated nodes, volume sign and size of the
// corners) and one over the nodes (each used by some tet); for 10-node tets then the topology of
// their mid-edge nodes. check_triangles: one pass over the triangles. Both stop at the first
// problem so the message can name it exactly.
#include "mesh/mesh_check.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/format.h"
#include "common/math.h"
#include "common/quadratic_tet_nodes.h"
#include "mesh/quadratic_mesh.h"
#include "mesh/tet_geometry.h"

namespace lfem {
namespace {

[[noreturn]] void invalid_mesh(const std::string& message) {
    throw Error(Status::invalid_mesh, message);
}

std::string format_volume(double volume) { return format_number(volume, 3); }

}  // namespace

void check_tet_mesh(const double* positions, uint32_t node_count, const uint32_t* tets,
                    uint32_t tet_count, uint32_t nodes_per_tet) {
    if (tet_count == 0) invalid_mesh("the mesh has no tets");

    std::vector<unsigned char> used(node_count, 0);
    for (uint32_t t = 0; t < tet_count; ++t) {
        const uint32_t* tet = tets + std::size_t(nodes_per_tet) * t;
        // Built only on failure: the happy path allocates nothing per tet.
        const auto name = [t] { return "tet " + std::to_string(t); };
        for (uint32_t i = 0; i < nodes_per_tet; ++i) {
            if (tet[i] >= node_count)
                invalid_mesh(name() + " refers to node " + std::to_string(tet[i]) +
                             " but the mesh has " + std::to_string(node_count) + " nodes");
            for (uint32_t j = 0; j < i; ++j)
                if (tet[i] == tet[j])
                    invalid_mesh(name() + " repeats node " + std::to_string(tet[i]));
        }
        const double* x0 = positions + 3 * std::size_t(tet[0]);
        const double* x1 = positions + 3 * std::size_t(tet[1]);
        const double* x2 = positions + 3 * std::size_t(tet[2]);
        const double* x3 = positions + 3 * std::size_t(tet[3]);
        const double six_vol = tet_geometry::six_volume(x0, x1, x2, x3);
        const double longest = tet_geometry::longest_edge(x0, x1, x2, x3);
        if (!std::isfinite(six_vol))
            invalid_mesh(name() + " is too large: its volume overflows a double");
        // Flatness first: a nearly flat tet with a negative sign is degenerate rather than
        // inverted (its sign is rounding noise), and saying so points at the real problem.
        if (tet_geometry::is_flat(six_vol, longest))
            invalid_mesh(name() + " has zero volume (volume " + format_volume(six_vol / 6.0) +
                         " m^3, longest edge " + format_volume(longest) + " m)");
        if (six_vol < 0.0)
            invalid_mesh(name() + " is inverted (volume " + format_volume(six_vol / 6.0) +
                         " m^3); list its nodes so that det[x1-x0, x2-x0, x3-x0] > 0");
        for (uint32_t i = 0; i < nodes_per_tet; ++i) used[tet[i]] = 1;
    }
    for (uint32_t n = 0; n < node_count; ++n)
        if (!used[n]) invalid_mesh("node " + std::to_string(n) + " belongs to no tet");
    if (nodes_per_tet == kQuadraticTetNodes) check_quadratic_topology(tets, tet_count, node_count);
}

void check_triangles(const uint32_t* triangles, uint32_t triangle_count, uint32_t point_count,
                     const double* positions, const char* point, const char* points) {
    for (uint32_t t = 0; t < triangle_count; ++t) {
        const uint32_t* f = &triangles[3 * std::size_t(t)];
        const auto name = [t] { return "triangle " + std::to_string(t); };
        for (int v = 0; v < 3; ++v)
            if (f[v] >= point_count)
                invalid_mesh(name() + " has " + point + " index " + std::to_string(f[v]) + ", beyond the " +
                             std::to_string(point_count) + " " + points);
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) invalid_mesh(name() + " repeats a " + point);
        if (!positions) continue;
        const Vec3 a(&positions[3 * std::size_t(f[0])]), b(&positions[3 * std::size_t(f[1])]),
            c(&positions[3 * std::size_t(f[2])]);
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        if (!((b - a).cross(c - a).norm() > 1e-12 * longest * longest)) invalid_mesh(name() + " has no area");
    }
}

}  // namespace lfem
