// A small fixed pool of worker threads for the data-parallel loops of a step (element forces,
// predictor, commit). Created with the world, joined when it is destroyed. No work stealing: a
// parallel loop hands out task indices from one shared counter, and every task writes only its
// own outputs, so results never depend on which thread ran which task (or on how many there
// are). Built with LFEM_WITH_THREADS=OFF the pool has no workers and runs every task on the
// calling thread.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

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

// Runs task(i) for i in [0, count) on the pool, or inline without one.
inline void parallel_for(ThreadPool* pool, uint32_t count, const std::function<void(uint32_t)>& task) {
    if (pool && count > 1 && pool->size() > 1) {
        pool->run(count, task);
    } else {
        for (uint32_t i = 0; i < count; ++i) task(i);
    }
}

}  // namespace lfem
