// The node numbering of the 10-node (quadratic) tetrahedron, shared by the meshes (mesh/), the
// element (fem/), the skins (skin/) and the files written and read: the four corners first, as
// in a linear tet, then one mid-edge node on each edge, in the order of VTK's
// VTK_QUADRATIC_TETRA (cell type 24):
//   4: (0,1)  5: (1,2)  6: (0,2)  7: (0,3)  8: (1,3)  9: (2,3)
// Gmsh's element type 11 lists the last two the other way round (mesh/gmsh_reader.cpp). Also
// its shape functions and their natural gradients (fem/quadratic_tet.h says how the element
// uses them), which the skins evaluate at their vertices.
#pragma once

#include <cstddef>
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

// The shape functions N_a (a = 0..9) at the point of barycentric coordinates L: the corners'
// N_i = L_i (2 L_i - 1), the mid-edge node of edge (i, j)'s N_ij = 4 L_i L_j. They sum to 1 for
// any L, so nodes moved by one affine map move sum_a N_a X_a by it too.
constexpr void quadratic_shape_values_at(const double L[4], double N[kQuadraticTetNodes]) {
    for (int i = 0; i < 4; ++i) N[i] = L[i] * (2.0 * L[i] - 1.0);
    for (int e = 0; e < 6; ++e) N[4 + e] = 4.0 * L[kQuadraticTetEdges[e][0]] * L[kQuadraticTetEdges[e][1]];
}

// dN_a/dxi (a = 0..9, three natural directions) at the point of barycentric coordinates L.
constexpr void quadratic_gradients_at(const double L[4], double g[kQuadraticTetNodes][3]) {
    const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) g[i][c] = (4.0 * L[i] - 1.0) * dL[i][c];
    for (int e = 0; e < 6; ++e) {
        const int i = kQuadraticTetEdges[e][0], j = kQuadraticTetEdges[e][1];
        for (int c = 0; c < 3; ++c) g[4 + e][c] = 4.0 * (L[j] * dL[i][c] + L[i] * dL[j][c]);
    }
}

// The 3x3 matrix sum_a p_a g_a^T (row r, column c at [3r + c]) of the ten nodes p (each a
// pointer to 3 coordinates) and natural gradients g: the Jacobian J (reference nodes) or Ds
// (current nodes) at a point of the element.
inline void natural_jacobian(const double* const p[kQuadraticTetNodes], const double g[kQuadraticTetNodes][3],
                             double J[9]) {
    for (int k = 0; k < 9; ++k) J[k] = 0.0;
    for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) J[3 * r + c] += p[a][r] * g[a][c];
}

}  // namespace lfem
