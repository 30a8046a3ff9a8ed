// The composite 10-node tetrahedron: the same ten nodes, quadrature points and lumped mass as the
// quadratic tet (quadratic_tet.h), a different strain. Its displacement is piecewise linear over
// the eight sub-tets that lump its mass (one at each corner, four filling the inner octahedron),
// and the deformation gradient used at the quadrature points is the L2 projection of the
// sub-tets' constant gradients onto the fields linear over the whole tet (the composite
// tetrahedron of Guo, Ortiz and Thoutireddy; the explicit codes' modified tet, C3D10M, is of its
// kind).
//
// Why: with the quadratic shape functions a smooth stress gradient loads the corners with
// -V/20 of it and the mid-edge nodes with V/5, against lumped masses of V/32 and 7V/48, so the
// nodes of a section accelerate unequally and a plane wave sheds energy into shear modes. The
// projection makes every linear stress field do the virtual work it does on the sub-tets (a
// linear field is its own projection), whose loads are the integrals of their positive
// piecewise-linear shape functions: the same shares as the lumped mass, so a smooth load moves
// all nodes of a section alike. The projected gradient is still linear over the tet, so the
// element bends without the linear tet's locking. Its price: a quadratic displacement is no
// longer reproduced exactly (the quadratic patch test); a linear one still is.
//
// In natural coordinates the projected gradient at quadrature point q is a fixed combination of
// the nodes, Ds_q = sum_a x_a bhat_qa^T, so the element runs through the quadratic kernel with
// the table bhat in place of dN_a/dxi (J_q = sum_a X_a bhat_qa^T; for a straight-sided tet it
// is the element's one Jacobian). The octahedron is split along each of its three diagonals in
// turn and the three results averaged, so the table treats the six mid-edge nodes alike, as the
// lumped mass does.
#pragma once

#include "fem/quadratic_tet.h"

namespace lfem {
namespace composite_detail {

// Natural coordinates of the ten nodes (corners, then the mid-edge nodes in kQuadraticTetEdges
// order).
struct NodeCoordinates {
    double xi[kQuadraticTetNodes][3];
};
constexpr NodeCoordinates node_coordinates() {
    NodeCoordinates n{};
    for (int c = 0; c < 3; ++c) n.xi[c + 1][c] = 1.0;
    for (int e = 0; e < 6; ++e)
        for (int c = 0; c < 3; ++c)
            n.xi[4 + e][c] = 0.5 * (n.xi[kQuadraticTetEdges[e][0]][c] + n.xi[kQuadraticTetEdges[e][1]][c]);
    return n;
}

// Sub-tet s (local nodes v[0..3]) with weight w: adds w * C_q(s) * grad N_(s,v) to table[q][v],
// with C_q(s) = sum_b L_b(q) sum_a Minv_ba int_s L_a, the projection's coefficient of the
// sub-tet's gradient at point q. M_ab = int_T L_a L_b = V/20 (1 + delta_ab), so
// Minv = (20/V)(I - 11^T/5), V = 1/6 the natural tet's volume.
constexpr void add_sub_tet(const int v[4], double w, double table[kQuadraturePoints][kQuadraticTetNodes][3]) {
    const NodeCoordinates n = node_coordinates();
    double D[3][3] = {};  // columns: edges from v[0]
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) D[r][c] = n.xi[v[c + 1]][r] - n.xi[v[0]][r];
    const double det = D[0][0] * (D[1][1] * D[2][2] - D[1][2] * D[2][1]) -
                       D[0][1] * (D[1][0] * D[2][2] - D[1][2] * D[2][0]) +
                       D[0][2] * (D[1][0] * D[2][1] - D[1][1] * D[2][0]);
    // Rows of D^-1 are the gradients of the sub-tet's barycentric functions 1..3.
    double inv[3][3] = {};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            inv[r][c] = (D[r1][c1] * D[r2][c2] - D[r1][c2] * D[r2][c1]) / det;
        }
    double grad[4][3] = {};
    for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) grad[k + 1][c] = inv[k][c], grad[0][c] -= inv[k][c];
    const double volume = (det < 0 ? -det : det) / 6.0, V = 1.0 / 6.0;
    double integral[4] = {};  // int_s L_a: the sub-tet's volume times L_a's mean over its nodes
    for (int k = 0; k < 4; ++k) {
        const double* x = n.xi[v[k]];
        const double L[4] = {1.0 - x[0] - x[1] - x[2], x[0], x[1], x[2]};
        for (int a = 0; a < 4; ++a) integral[a] += 0.25 * volume * L[a];
    }
    double sum = 0.0;
    for (double i : integral) sum += i;
    double projected[4] = {};  // sum_a Minv_ba int_s L_a
    for (int b = 0; b < 4; ++b) projected[b] = 20.0 / V * (integral[b] - sum / 5.0);
    for (int q = 0; q < kQuadraturePoints; ++q) {
        double C = 0.0;
        for (int b = 0; b < 4; ++b) C += (b == q ? kQuadratureA : kQuadratureB) * projected[b];
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) table[q][v[k]][c] += w * C * grad[k][c];
    }
}

// Two edges of the tet (indices into kQuadraticTetEdges) that share no corner.
constexpr bool edges_opposite(int e, int f) {
    const int* a = kQuadraticTetEdges[e];
    const int* b = kQuadraticTetEdges[f];
    return a[0] != b[0] && a[0] != b[1] && a[1] != b[0] && a[1] != b[1];
}

// The three pairs of opposite edges: (0,1)-(2,3), (1,2)-(0,3), (0,2)-(1,3).
constexpr int kDiagonalEdges[3][2] = {{0, 5}, {1, 3}, {2, 4}};

}  // namespace composite_detail

constexpr QuadraticGradients composite_gradients() {
    QuadraticGradients t{};
    for (int i = 0; i < 4; ++i) {  // the corner sub-tets
        int v[4] = {i, 0, 0, 0}, k = 1;
        for (int j = 0; j < 4; ++j)
            if (j != i) v[k++] = mid_edge_node(i, j);
        composite_detail::add_sub_tet(v, 1.0, t.g);
    }
    // The octahedron along each of its diagonals, which join the midpoints of opposite edges.
    // Its other four nodes form the ring around the diagonal, ordered x, y, x', y' with x, x'
    // and y, y' opposite.
    for (int e = 0; e < 3; ++e) {
        const int A = 4 + composite_detail::kDiagonalEdges[e][0], B = 4 + composite_detail::kDiagonalEdges[e][1];
        int others[4] = {}, k = 0;
        for (int m = 4; m < 10; ++m)
            if (m != A && m != B) others[k++] = m;
        int ring[4] = {others[0], 0, 0, 0}, side = 1;
        for (int j = 1; j < 4; ++j) {
            if (composite_detail::edges_opposite(others[0] - 4, others[j] - 4)) ring[2] = others[j];
            else ring[side] = others[j], side += 2;
        }
        for (int s = 0; s < 4; ++s) {
            const int v[4] = {A, B, ring[s], ring[(s + 1) % 4]};
            composite_detail::add_sub_tet(v, 1.0 / 3.0, t.g);
        }
    }
    return t;
}

inline constexpr QuadraticGradients kCompositeGradients = composite_gradients();

// The natural gradients a body's 10-node tets use at their quadrature points: the quadratic
// shape functions' or the composite element's.
inline const QuadraticGradients& element_gradients(bool composite) {
    return composite ? kCompositeGradients : kQuadraticGradients;
}

}  // namespace lfem
