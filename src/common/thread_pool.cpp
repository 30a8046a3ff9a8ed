#include "common/thread_pool.h"

#include <exception>
#include <vector>

#ifdef LFEM_WITH_THREADS
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#endif

namespace lfem {

#ifdef LFEM_WITH_THREADS

struct ThreadPool::Shared {
    std::mutex mutex;
    std::condition_variable wake, done;
    std::vector<std::thread> workers;
    // The loop in progress: workers join it when `round` changes.
    const std::function<void(uint32_t)>* task = nullptr;
    uint32_t count = 0;
    std::atomic<uint32_t> next{0};
    uint64_t round = 0;
    uint32_t busy = 0;  // workers still inside the current loop
    bool stop = false;
    std::exception_ptr error;

    // Takes task indices until none is left.
    void work() {
        for (;;) {
            const uint32_t i = next.fetch_add(1, std::memory_order_relaxed);
            if (i >= count) return;
            try {
                (*task)(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!error) error = std::current_exception();
            }
        }
    }

    void worker_main() {
        uint64_t seen = 0;
        std::unique_lock<std::mutex> lock(mutex);
        for (;;) {
            wake.wait(lock, [&] { return stop || round != seen; });
            if (stop) return;
            seen = round;
            lock.unlock();
            work();
            lock.lock();
            if (--busy == 0) done.notify_one();
        }
    }
};

ThreadPool::ThreadPool(uint32_t threads) : shared_(new Shared) {
    Shared& s = *shared_;
    try {
        for (uint32_t i = 1; i < threads; ++i) s.workers.emplace_back([&s] { s.worker_main(); });
    } catch (...) {
        // Could not start every thread: stop the ones that run, then report.
        {
            std::lock_guard<std::mutex> lock(s.mutex);
            s.stop = true;
        }
        s.wake.notify_all();
        for (std::thread& t : s.workers) t.join();
        throw;
    }
}

ThreadPool::~ThreadPool() {
    Shared& s = *shared_;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.stop = true;
    }
    s.wake.notify_all();
    for (std::thread& t : s.workers) t.join();
}

uint32_t ThreadPool::size() const { return uint32_t(shared_->workers.size()) + 1; }

void ThreadPool::run(uint32_t count, const std::function<void(uint32_t)>& task) {
    Shared& s = *shared_;
    {
        std::lock_guard<std::mutex> lock(s.mutex);
        s.task = &task;
        s.count = count;
        s.next.store(0, std::memory_order_relaxed);
        s.busy = uint32_t(s.workers.size());
        s.error = nullptr;
        ++s.round;
    }
    s.wake.notify_all();
    s.work();  // the caller takes part
    std::unique_lock<std::mutex> lock(s.mutex);
    s.done.wait(lock, [&] { return s.busy == 0; });
    s.task = nullptr;
    if (s.error) {
        std::exception_ptr e = s.error;
        s.error = nullptr;
        std::rethrow_exception(e);
    }
}

#else  // built without threads: every loop runs on the caller

struct ThreadPool::Shared {};

ThreadPool::ThreadPool(uint32_t) : shared_(new Shared) {}
ThreadPool::~ThreadPool() = default;
uint32_t ThreadPool::size() const { return 1; }
void ThreadPool::run(uint32_t count, const std::function<void(uint32_t)>& task) {
    for (uint32_t i = 0; i < count; ++i) task(i);
}

#endif

}  // namespace lfem
