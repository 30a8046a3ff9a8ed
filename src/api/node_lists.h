// Node indices as the caller gives them: checked (in range, no repeats) and translated into a
// body's internal numbering (mesh/node_ordering.h). Shared by the calls that take node lists.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "api/guard.h"
#include "world/body.h"

namespace lfem::api {

// A list of node indices: in range and without repeats (O(count + nodes)).
inline void check_node_list(const Body& b, const uint32_t* nodes, uint32_t count) {
    require(count == 0 || nodes != nullptr, "nodes is NULL");
    std::vector<uint8_t> seen(b.node_count(), 0);
    for (uint32_t i = 0; i < count; ++i) {
        require(nodes[i] < b.node_count(), "nodes[" + std::to_string(i) + "] = " +
                                                   std::to_string(nodes[i]) + " is out of range (" +
                                                   std::to_string(b.node_count()) + " nodes)");
        require(!seen[nodes[i]], "node " + std::to_string(nodes[i]) + " is listed twice");
        seen[nodes[i]] = 1;
    }
}

// A checked list of the caller's node indices in the body's internal numbering.
inline std::vector<uint32_t> internal_nodes(const Body& b, const uint32_t* nodes, uint32_t count) {
    check_node_list(b, nodes, count);
    std::vector<uint32_t> internal(count);
    for (uint32_t i = 0; i < count; ++i) internal[i] = b.numbering().node(nodes[i]);
    return internal;
}

}  // namespace lfem::api
