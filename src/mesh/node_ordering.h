// Node and tet order for locality (issue 7). The element loop gathers the 4 nodes of each tet
// and scatters forces back to them; when neighbouring tets and nodes lie far apart in memory
// (a mesh from a generator that numbers in no spatial order, or shuffled) every gather misses
// the cache, and blocks of consecutive tets share nodes with so many others that the element
// colouring cannot run them side by side. A body therefore keeps its nodes in a sweep order of
// their reference positions (slabs, rows, then along the rows) and its tets sorted by their
// nodes, so that the loop walks memory nearly in order. Callers keep their own numbering: the
// C shim translates at the API boundary.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

struct LocalityOrder {
    std::vector<uint32_t> node_of_old;  // new index of each given node
    std::vector<uint32_t> old_of_tet;   // given index of each new tet
    std::vector<double> positions;      // 3 per node, in the new order
    std::vector<uint32_t> tets;         // nodes_per_tet per tet, in the new order and numbering
};

// Orders one mesh (given positions and tets of nodes_per_tet nodes, 4 or 10): nodes in sweep
// order (ties, i.e. coincident nodes, by given index), tets by their sorted new corner indices,
// and each tet's corners turned, by an even permutation (orientation kept; mid-edge nodes follow
// their edges), to start at its lowest corner. Apart from coincident nodes, the result depends
// only on the geometry, not on how the caller numbered the mesh, so neither do the results of a
// simulation. O(n log n + t log t).
LocalityOrder order_for_locality(const double* positions, uint32_t node_count,
                                 const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet = 4);

// How a body's internal numbering maps to the caller's. Empty node maps, or an empty tet map,
// mean "the same" (a box from lfem_mesh_create_box keeps its node order, for one).
// Meshes added later keep their own blocks: API node old_nodes + i of a second mesh is
// internal node old_nodes + node_of_old[i].
struct Numbering {
    std::vector<uint32_t> node_of_api;  // internal node of each API node
    std::vector<uint32_t> api_of_node;  // API node of each internal node
    std::vector<uint32_t> api_of_tet;   // API tet of each internal tet

    uint32_t node(uint32_t api) const { return node_of_api.empty() ? api : node_of_api[api]; }
    uint32_t api_node(uint32_t i) const { return api_of_node.empty() ? i : api_of_node[i]; }
    uint32_t api_tet(uint32_t e) const { return api_of_tet.empty() ? e : api_of_tet[e]; }

    // Translations of whole arrays (in and out must not overlap). 3 doubles per node; one
    // value per tet; nodes_per_tet node indices per tet (node indices translated as well).
    void nodes_to_api(const double* internal, uint32_t node_count, double* api) const;
    void nodes_from_api(const double* api, uint32_t node_count, double* internal) const;
    void tets_to_api(const double* internal, uint32_t tet_count, double* api) const;
    void tet_nodes_to_api(const uint32_t* internal, uint32_t tet_count, uint32_t nodes_per_tet, uint32_t* api) const;

    // Appends a mesh block: nodes [old_nodes, old_nodes + order's nodes), tets likewise.
    void append(const LocalityOrder& order, uint32_t old_nodes, uint32_t old_tets);
    // True when the arrays are mutual inverses of the right sizes (checkpoint loading).
    bool consistent(uint32_t node_count, uint32_t tet_count) const;
};

}  // namespace lfem
