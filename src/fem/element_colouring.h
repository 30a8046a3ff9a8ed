// Colouring of element blocks for the parallel element loop. Tets are cut into blocks of
// consecutive indices, and the blocks are coloured so that no two blocks of one colour share a
// node: the blocks of a colour can scatter their nodal forces at the same time without races,
// and every node receives its element contributions in the same order (colour by colour,
// block by block, tet by tet) whatever the number of threads. Results are therefore bitwise
// independent of the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "common/thread_pool.h"

namespace lfem {

struct ElementColouring {
    uint32_t block_size = 0;            // tets per block (the last block may be shorter)
    std::vector<uint32_t> colour_start; // colour c owns blocks[colour_start[c] .. colour_start[c+1])
    std::vector<uint32_t> blocks;       // block indices grouped by colour, ascending in each

    uint32_t colour_count() const {
        return colour_start.empty() ? 0 : uint32_t(colour_start.size() - 1);
    }
    uint32_t block_count() const { return uint32_t(blocks.size()); }
};

// Tets per block: large enough that handing out a block costs nothing, small enough that a
// million-tet body has thousands of blocks to share between threads.
constexpr uint32_t kElementBlockSize = 256;

// Greedy colouring of the blocks in index order, O(tets + node-block incidences); tets holds
// nodes_per_tet node indices per tet (4, or 10 for quadratic tets).
ElementColouring colour_element_blocks(const uint32_t* tets, uint32_t tet_count,
                                       uint32_t node_count, uint32_t block_size = kElementBlockSize,
                                       uint32_t nodes_per_tet = 4);

// Runs block(b) for every block, colour after colour, the blocks of one colour side by side on
// the pool (nullable): the element loop's order, the same for any thread count.
template <class Block>
void for_each_block_by_colour(const ElementColouring& colouring, ThreadPool* pool, const Block& block) {
    for (uint32_t c = 0; c < colouring.colour_count(); ++c) {
        const uint32_t* blocks = colouring.blocks.data() + colouring.colour_start[c];
        parallel_for(pool, colouring.colour_start[c + 1] - colouring.colour_start[c],
                     [&](uint32_t i) { block(blocks[i]); });
    }
}

}  // namespace lfem
