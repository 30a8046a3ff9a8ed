// The node numbering of the 10-node (quadratic) tetrahedron, shared by the meshes (mesh/), the
// element (fem/) and the files written and read: the four corners first, as in a linear tet,
// then one mid-edge node on each edge, in the order of VTK's VTK_QUADRATIC_TETRA (cell type 24):
//   4: (0,1)  5: (1,2)  6: (0,2)  7: (0,3)  8: (1,3)  9: (2,3)
// Gmsh's element type 11 lists the last two the other way round (mesh/gmsh_reader.cpp).
#pragma once

#include <cstdint>

namespace lfem {

constexpr uint32_t kLinearTetNodes = 4;
constexpr uint32_t kQuadraticTetNodes = 10;

// The corners (i, j) of the edge that mid-edge node 4 + e sits on.
constexpr int kQuadraticTetEdges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};

// The local index (4..9) of the mid-edge node between corners i and j (i != j, 0..3).
constexpr int mid_edge_node(int i, int j) {
    for (int e = 0; e < 6; ++e)
        if ((kQuadraticTetEdges[e][0] == i && kQuadraticTetEdges[e][1] == j) ||
            (kQuadraticTetEdges[e][0] == j && kQuadraticTetEdges[e][1] == i))
            return 4 + e;
    return -1;
}

}  // namespace lfem
