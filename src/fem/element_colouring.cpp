#include "fem/element_colouring.h"

#include <algorithm>

namespace lfem {

ElementColouring colour_element_blocks(const uint32_t* tets, uint32_t tet_count,
                                       uint32_t node_count, uint32_t block_size, uint32_t nodes_per_tet) {
    ElementColouring out;
    out.block_size = block_size;
    const uint32_t nb = (tet_count + block_size - 1) / block_size;
    auto block_nodes = [&](uint32_t b, auto&& visit) {
        const uint32_t e1 = std::min(tet_count, (b + 1) * block_size);
        for (std::size_t i = std::size_t(nodes_per_tet) * b * block_size; i < std::size_t(nodes_per_tet) * e1; ++i)
            visit(tets[i]);
    };
    // Node -> blocks touching it (each block listed once per node), as compressed rows.
    std::vector<uint32_t> stamp(node_count, UINT32_MAX), start(std::size_t(node_count) + 1, 0);
    for (uint32_t b = 0; b < nb; ++b)
        block_nodes(b, [&](uint32_t v) {
            if (stamp[v] != b) stamp[v] = b, ++start[v + 1];
        });
    for (uint32_t v = 0; v < node_count; ++v) start[v + 1] += start[v];
    std::vector<uint32_t> node_blocks(start[node_count]), fill(start.begin(), start.end() - 1);
    std::fill(stamp.begin(), stamp.end(), UINT32_MAX);
    for (uint32_t b = 0; b < nb; ++b)
        block_nodes(b, [&](uint32_t v) {
            if (stamp[v] != b) stamp[v] = b, node_blocks[fill[v]++] = b;
        });
    // Greedy: each block takes the lowest colour no earlier neighbouring block holds.
    std::vector<uint32_t> colour(nb, 0), taken;  // taken[c] == b: colour c is used next to b
    uint32_t colours = 0;
    for (uint32_t b = 0; b < nb; ++b) {
        block_nodes(b, [&](uint32_t v) {
            for (uint32_t k = start[v]; k < start[v + 1] && node_blocks[k] < b; ++k)
                taken[colour[node_blocks[k]]] = b;
        });
        uint32_t c = 0;
        while (c < colours && taken[c] == b) ++c;
        if (c == colours) ++colours, taken.push_back(UINT32_MAX);
        colour[b] = c;
    }
    // Group by colour, blocks ascending within each (a counting sort keeps the order).
    out.colour_start.assign(std::size_t(colours) + 1, 0);
    for (uint32_t b = 0; b < nb; ++b) ++out.colour_start[colour[b] + 1];
    for (uint32_t c = 0; c < colours; ++c) out.colour_start[c + 1] += out.colour_start[c];
    out.blocks.resize(nb);
    std::vector<uint32_t> pos(out.colour_start.begin(), out.colour_start.end() - 1);
    for (uint32_t b = 0; b < nb; ++b) out.blocks[pos[colour[b]]++] = b;
    return out;
}

}  // namespace lfem
