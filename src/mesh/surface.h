// The surface of a body as contact sees it: the boundary triangles, the nodes on them (the
// contact slave nodes), the nodes on edges and corners, and the mean edge length that scales
// the contact tolerances.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

struct Surface {
    std::vector<uint32_t> triangles;      // 3 per outward boundary triangle
    std::vector<uint32_t> nodes;          // nodes of the triangles, ascending
    std::vector<uint32_t> feature_nodes;  // nodes where the surface bends by more than 15 degrees
    double edge_length = 0;               // mean edge length of the triangles (m)
    // The triangles around each node, ascending: node i's are
    // node_triangles[node_triangle_begin[i] .. node_triangle_begin[i + 1]) (derived from the
    // triangles; not saved in checkpoints).
    std::vector<uint32_t> node_triangle_begin, node_triangles;

    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
};

// Fills nodes, feature_nodes and edge_length from the triangles and the reference positions X
// (3 per node, node_count nodes).
void compute_surface_data(const double* X, uint32_t node_count, Surface& surface);

// The node-triangle lists (they depend on the triangles alone).
void compute_node_triangles(uint32_t node_count, Surface& surface);

}  // namespace lfem
