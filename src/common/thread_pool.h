// A small fixed pool of worker threads for the data-parallel loops of a step (element forces,
// predictor, commit). Created with the world, joined when it is destroyed. A parallel loop
// gives each thread a contiguous range of the task indices (so the same body stays on the same
// core from phase to phase); a thread done with its range takes what is left of the others'
// from their backs.
// Every task writes only its own outputs, so results never depend on which thread ran which
// task (or on how many there are). Built with LFEM_WITH_THREADS=OFF the pool has no workers
// and runs every task on the calling thread.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "common/block_array.h"

namespace lfem {

class ThreadPool {
public:
    // threads: total threads taking part in a loop, the caller included (1 = no workers).
    explicit ThreadPool(uint32_t threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    // Threads that actually run tasks (1 when built without threads).
    uint32_t size() const;
    // Calls task(i) for every i in [0, count) and returns when all have finished. The first
    // exception a task throws is rethrown here (after the others have finished).
    void run(uint32_t count, const std::function<void(uint32_t)>& task);

private:
    struct Shared;
    std::unique_ptr<Shared> shared_;
};

// Runs task(i) for i in [0, count) on the pool, or inline without one. The task is passed to
// the pool by reference, so no std::function holding a copy of it is allocated per loop.
template <class Task>
inline void parallel_for(ThreadPool* pool, uint32_t count, const Task& task) {
    if (pool && count > 1 && pool->size() > 1) {
        pool->run(count, std::cref(task));
    } else {
        for (uint32_t i = 0; i < count; ++i) task(i);
    }
}

// Nodes per block of the parallel node loops. Fixed, not per thread, so that sums taken per
// block and then added in block order come out the same for any thread count.
constexpr uint32_t kNodeBlock = 2048;

// K sums taken together by blocked_sum: plain numbers indexed 0..K-1 (a matrix's entries).
template <int K>
struct Sums {
    double v[K] = {};
    Sums& operator+=(const Sums& o) {
        for (int k = 0; k < K; ++k) v[k] += o.v[k];
        return *this;
    }
};

// Calls term(i, partial) for every node i in [0, n), in fixed blocks of kNodeBlock nodes on the
// pool; term adds to its block's partial sums (a Sum, value-initialised to zero; a struct of
// named sums with a member-wise +=, or Sums<K>) and may write node i's own outputs. The blocks'
// sums are then added to total in block order, so the result is bitwise the same for any
// thread count. total keeps what it held: the caller sets its start.
template <class Sum, class Term>
void blocked_sum(uint32_t n, ThreadPool* pool, Sum& total, const Term& term) {
    const uint32_t blocks = (n + kNodeBlock - 1) / kNodeBlock;
    BlockArray<Sum, 4> partial(blocks);
    parallel_for(pool, blocks, [&](uint32_t b) {
        // A local sum, stored once per block: the compiler keeps it in registers, where the
        // block's entry of `partial` would be stored and reloaded at every node (the outputs
        // term writes might alias it). The same additions in the same order.
        Sum out{};
        for (uint32_t i = b * kNodeBlock, end = std::min(n, (b + 1) * kNodeBlock); i < end; ++i) term(i, out);
        partial[b] = out;
    });
    for (uint32_t b = 0; b < blocks; ++b) total += partial[b];
}

}  // namespace lfem
