// One value per block of a blocked loop (a node loop's partial sums, an element loop's block
// results), each written by its own block and read afterwards in block order. A small body's
// few blocks are kept inline, so a loop over it allocates nothing: a scene of 32 small cubes
// allocated two such arrays per cube and sub-step.
#pragma once

#include <cstdint>
#include <vector>

namespace lfem {

template <class T, uint32_t N>
class BlockArray {
public:
    explicit BlockArray(uint32_t count) : count_(count) {
        if (count > N) heap_.resize(count);
    }
    BlockArray(const BlockArray&) = delete;
    BlockArray& operator=(const BlockArray&) = delete;

    uint32_t size() const { return count_; }
    T& operator[](uint32_t b) { return (count_ > N ? heap_.data() : inline_)[b]; }
    const T& operator[](uint32_t b) const { return (count_ > N ? heap_.data() : inline_)[b]; }

private:
    uint32_t count_;
    T inline_[N];
    std::vector<T> heap_;
};

}  // namespace lfem
