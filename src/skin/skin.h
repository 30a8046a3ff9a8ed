// Skins: a render mesh (a fine triangle mesh a game draws) embedded in a body's tets. Each
// vertex is bound once, when the skin is added, to the tet that contains it in the body's rest
// frame (or, for a vertex just outside the body, to the nearest tet) by the weights of its
// position there: x_v = sum_k w_k x_k over the tet's nodes. Of a 4-node tet they are the
// barycentric coordinates L (over its four corners); of a 10-node tet, its ten shape functions
// N_a(L) at the vertex (quadratic_coordinates.h finds L in a curved element), so the vertex
// follows the element's own quadratic displacement, as contact's surface of its mid-edge nodes
// does. The weights of a vertex outside its tet are the same polynomials extended (some
// negative); they sum to 1 and reproduce the vertex's rest position, so every vertex, inside
// or out, follows an affine motion of its tet exactly: a body stretched, sheared, turned or
// moved uniformly carries its skin with it to round-off. After a step the deformed vertices and
// their smooth normals (area-weighted over the skin's own triangles) are read in one call.
#pragma once

#include <cstdint>
#include <vector>

#include "common/math.h"
#include "common/span.h"

namespace lfem {

struct Skin {
    std::vector<uint32_t> nodes;      // nodes_per_vertex per vertex: the body nodes it follows
                                      // (the body's own numbering)
    std::vector<double> weights;      // nodes_per_vertex per vertex: their weights (summing to 1)
    std::vector<uint32_t> triangles;  // 3 vertex indices per triangle, as the caller gave them
    uint32_t nodes_per_vertex = 4;    // the nodes of a tet: 4, or 10 on a body of 10-node tets

    uint32_t vertex_count() const { return uint32_t(weights.size() / nodes_per_vertex); }
    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
};

// The tets a skin is bound in: reference positions (3 per node) and tets of nodes_per_tet node
// indices each, whose first four are the corners (a 10-node tet's mid-edge nodes follow them).
struct SkinTets {
    Span<const double> X;
    Span<const uint32_t> tets;
    uint32_t nodes_per_tet = 4;
    uint32_t tet_count() const { return uint32_t(tets.size() / nodes_per_tet); }
};

// The skin of the given vertices (3 doubles each, in the frame of X) and triangles (checked by
// the caller: indices below vertex_count). Each vertex is bound to the tet that contains it
// (several on a shared face or edge: the one it is deepest in, then the lowest index), or else
// to the nearest tet if that is at most `reach` (m) away (a curved 10-node tet's distance is
// its corners' straight tet's). A vertex of a curved 10-node tet whose coordinates Newton's
// iterations do not find (far outside a strongly curved element) is bound to the corners alone
// by their barycentric weights (the mid-edge nodes' weights 0). Throws Error(Status::invalid_argument)
// naming the first vertex that lies farther than reach from every tet. O(T log T + V log T).
Skin bind_skin(const SkinTets& mesh, const double* positions, uint32_t vertex_count, const uint32_t* triangles,
               uint32_t triangle_count, double reach);

// The skin's vertices at the body's node positions x (3 per node): positions (3 per vertex)
// and, when normals is not null, the unit smooth normals (3 per vertex): the sum over the
// triangles around the vertex of (b - a) x (c - a) (twice each triangle's area times its unit
// normal), in triangle order, normalised; zero for a vertex whose triangles have no area.
void deform_skin(const Skin& skin, const double* x, std::vector<double>& positions, std::vector<double>* normals);

}  // namespace lfem
