// A torus of square section for the tests: a box mesh of n x 2 x 2 cells bent round the z axis
// (major radius R, section side a, centred on the origin), its last layer of nodes merged into
// its first, so that the ring is one closed mesh (its boundary: 16 n triangles).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "lfem.h"

namespace lfem_test {

struct TorusMesh {
    std::vector<double> x;      // 3 per node
    std::vector<uint32_t> tets;  // 4 per tet
};

inline bool make_torus(double R, double a, uint32_t n, TorusMesh& out) {
    const double size[3] = {1.0, a, a};
    const uint32_t cells[3] = {n, 2, 2};
    lfem_mesh* m = nullptr;
    if (lfem_mesh_create_box(size, cells, &m) != LFEM_OK) return false;
    const uint32_t nodes = lfem_mesh_get_node_count(m), tets = lfem_mesh_get_tet_count(m);
    const double* p = lfem_mesh_get_positions(m);
    const uint32_t* t = lfem_mesh_get_tets(m);
    std::vector<uint32_t> index(nodes);
    out.x.clear();
    for (uint32_t i = 0; i < nodes; ++i) {
        const bool last = p[3 * i] > 1.0 - 1e-9;
        if (last) continue;
        index[i] = uint32_t(out.x.size() / 3);
        // y inward (r = R + a/2 - y) keeps the tets' orientation: (tangent, -radial, z) is
        // right-handed.
        const double theta = 2.0 * M_PI * p[3 * i], r = R + a / 2 - p[3 * i + 1];
        out.x.insert(out.x.end(), {r * std::cos(theta), r * std::sin(theta), p[3 * i + 2] - a / 2});
    }
    for (uint32_t i = 0; i < nodes; ++i) {
        if (p[3 * i] <= 1.0 - 1e-9) continue;
        // A node of the last layer (x = 1) is the first layer's node with the same (y, z).
        for (uint32_t j = 0; j < nodes; ++j)
            if (p[3 * j] < 1e-9 && std::fabs(p[3 * j + 1] - p[3 * i + 1]) < 1e-9 && std::fabs(p[3 * j + 2] - p[3 * i + 2]) < 1e-9)
                index[i] = index[j];
    }
    out.tets.clear();
    for (uint32_t e = 0; e < 4 * tets; ++e) out.tets.push_back(index[t[e]]);
    lfem_mesh_destroy(m);
    return true;
}

}  // namespace lfem_test
