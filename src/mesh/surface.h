// The surface of a body as contact sees it: the boundary triangles, the nodes on them (the
// contact slave nodes), the nodes on edges and corners, and the mean edge length that scales
// the contact tolerances. A body of 10-node tets shows contact each 6-node boundary triangle
// as the 4 flat triangles of its corner and mid-edge nodes (the faces of the element's sub-tets,
// fem/quadratic_tet.h), so its mid-edge nodes are slave nodes and master vertices like any
// other: detection and the multiplier solve need nothing of their own for quadratic bodies.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

struct Surface {
    std::vector<uint32_t> triangles;      // 3 per outward boundary triangle (flat)
    std::vector<uint32_t> quadratic_faces; // 10-node bodies: 6 per boundary face (corners a, b,
                                           // c, mid-edge nodes of ab, bc, ca), whose 4 flat
                                           // triangles are in `triangles`; empty otherwise
    std::vector<uint32_t> nodes;          // nodes of the triangles, ascending
    std::vector<uint32_t> feature_nodes;  // nodes where the surface bends by more than 15 degrees
    double edge_length = 0;               // mean edge length of the triangles (m)
    // The triangles around each node, ascending: node i's are
    // node_triangles[node_triangle_begin[i] .. node_triangle_begin[i + 1]) (derived from the
    // triangles; not saved in checkpoints).
    std::vector<uint32_t> node_triangle_begin, node_triangles;
    // The tet each triangle bounds (UINT32_MAX for a surface without tets), derived from the
    // tets and the triangles like the lists above.
    std::vector<uint32_t> triangle_element;
    // The tets around each surface node: node i's are
    // node_elements[node_element_begin[i] .. node_element_begin[i + 1]) (none for other nodes).
    std::vector<uint32_t> node_element_begin, node_elements;
    // The sharp edges of the surface at rest, 4 per edge: its nodes u < v and the triangles it
    // joins (the second UINT32_MAX at an open border), ascending by (u, v). Sharp: the two faces
    // meet at more than 15 degrees (a cube's edges, not the folds of its flat faces), or the
    // edge is a border. The edges that can cross another body's between their nodes
    // (contact/edge_edge.h); derived like the lists above.
    std::vector<uint32_t> sharp_edges;
    // The other edges joining two triangles (the folds of a flat or gently curved face), 4 each
    // the same way. A fold the load bends outward can hold a sharp edge lying across the face
    // between its nodes (a knife edge: contact/edge_edge.h).
    std::vector<uint32_t> fold_edges;
    // Per triangle, 3 per triangle (the edge from its corner v to corner v + 1): that edge's
    // place among the sharp edges, or the number of sharp edges plus its place among the folds;
    // UINT32_MAX for an edge of three or more triangles (derived like the lists above).
    std::vector<uint32_t> triangle_edges;

    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
};

// Fills nodes, feature_nodes and edge_length from the triangles and the reference positions X
// (3 per node, node_count nodes).
void compute_surface_data(const double* X, uint32_t node_count, Surface& surface);

// The 4 flat triangles (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca) of each 6-node face
// (6 indices per face as in Surface::quadratic_faces), oriented as the face: 12 indices per face.
std::vector<uint32_t> split_quadratic_faces(const std::vector<uint32_t>& faces);

// The tet that each triangle bounds: tets of nodes_per_tet nodes (4 or 10, corners first).
void compute_triangle_elements(const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet, Surface& surface);

// The tets around each surface node.
void compute_node_elements(const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet, uint32_t node_count,
                           Surface& surface);

// The sharp edges and the folds from the triangles and the reference positions X.
void compute_sharp_edges(const double* X, Surface& surface);

// The node-triangle lists (they depend on the triangles alone).
void compute_node_triangles(uint32_t node_count, Surface& surface);

}  // namespace lfem
