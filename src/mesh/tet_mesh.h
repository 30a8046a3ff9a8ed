// A tetrahedral mesh as flat arrays: what builders and readers produce and what
// lfem_body_add_mesh consumes. This struct is also the opaque lfem_mesh of the C API.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

struct TetMesh {
    std::vector<double> positions;  // x, y, z per node (m)
    std::vector<uint32_t> tets;     // nodes_per_tet node indices per tet, positive volume
    uint32_t nodes_per_tet = 4;     // 4, or 10 for quadratic tets (common/quadratic_tet_nodes.h)

    uint32_t node_count() const { return uint32_t(positions.size() / 3); }
    uint32_t tet_count() const { return uint32_t(tets.size() / nodes_per_tet); }
};

}  // namespace lfem
