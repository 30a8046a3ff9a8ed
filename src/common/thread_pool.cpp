#include "common/thread_pool.h"

#include <algorithm>
#include <exception>
#include <memory>
#include <vector>

#if LFEM_WITH_THREADS
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif
#endif

namespace lfem {

#if LFEM_WITH_THREADS

// How long a thread spins, re-reading an atomic, before it sleeps on a condition variable: a
// worker waiting for the next round, the caller waiting for the last task of its round. A step
// runs many short rounds back to back (a few per phase and body, some of tens of
// microseconds); waking a sleeping thread takes the kernel several microseconds, often more
// on a virtual machine, which made two threads slower than one on small bodies. Bounded by the
// clock, not by a count of pauses: a pause takes 10 to 140 cycles depending on the CPU.
constexpr std::chrono::microseconds kSpinTime{50};

// The most tasks of one round: a range's front and back are 16-bit offsets.
constexpr uint32_t kRoundTasks = 0xffff;

inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

// Spins until ready() or kSpinTime has passed; returns ready(). The clock is read every 16
// pauses (a read costs about as much as a few pauses).
template <class Ready>
bool spin_until(const Ready& ready) {
    const auto until = std::chrono::steady_clock::now() + kSpinTime;
    for (;;) {
        for (int i = 0; i < 16; ++i) {
            if (ready()) return true;
            spin_pause();
        }
        if (std::chrono::steady_clock::now() >= until) return ready();
    }
}

// A loop is a "round". Its tasks are split into one contiguous range per thread (the caller's
// first), and each thread runs its own range from its front, then takes what is left of the
// others' from their backs: a loop over the bodies puts each body on the same thread in every
// phase of a sub-step, so the forces one thread wrote are read by that thread's predictor and
// commit from its own cache (with one shared counter the bodies wandered between cores every
// phase, and the predictor was slower on two threads than on one). A thief takes a range's
// last task only while its owner has not started on it: an owner that has started takes it
// itself a moment later, where the thief would read the body's data from the other core and
// hand it back for the next phase. (Taking from the front, as each thread did before, the
// thread that finished first took the next body of the other's range nearly every round, and
// the two fought over that range's counter: 2 to 9 % of a 32-cube frame on two threads.)
// Each range is one 64-bit word, the round's number in its high half and the range's front and
// back (offsets from its start) in its low half, so a worker that wakes late (the machine is
// busy) can never claim a task of a later round, and the caller never waits for a worker that
// has not started: it takes that worker's range and waits only until every task of its round
// has finished. A round has at most kRoundTasks tasks (a range fits 16 bits); run() splits a
// longer loop into rounds of that many.
//
// A round is handed out without a lock: a step runs a hundred rounds a frame, and a mutex taken
// by the caller to post each one and by every worker to read it passed its cache line between
// the cores several times a round. The caller writes the round's task and count into the slot
// of its parity, then its ranges, then `posted`; a worker that sees `posted` reads that slot.
// A worker slow enough to read the slot after the caller has gone on to the round after next
// gets that round's task with this round's number: the ranges by then carry a later round, so
// it claims nothing. The mutex and the condition variables serve only threads that stopped
// spinning and sleep: `sleepers` and `caller_asleep` tell the other side to take the mutex and
// wake them (each side writes its flag before it reads the other's state, sequentially
// consistent, so one of the two always sees the other).
struct ThreadPool::Shared {
    using Task = std::function<void(uint32_t)>;
    struct Slot {
        std::atomic<const Task*> task{nullptr};
        std::atomic<uint32_t> count{0};
    };
    Slot slots[2];                     // round r's task and count in slots[r & 1]
    std::atomic<uint32_t> posted{0};   // the newest round, read by spinning workers
    std::atomic<bool> stop{false};
    std::atomic<uint32_t> sleepers{0};      // workers asleep on `wake`, or about to be
    std::atomic<bool> caller_asleep{false};  // the caller asleep on `done`, or about to be
    std::mutex mutex;
    std::condition_variable wake, done;
    std::vector<std::thread> workers;
    uint32_t round = 0;  // the caller's count of rounds
    // Per thread's range: (round << 32) | its next task index. Each on a cache line of its own.
    struct alignas(64) Range {
        std::atomic<uint64_t> next{0};
    };
    std::unique_ptr<Range[]> ranges;
    uint32_t threads = 1;
    alignas(64) std::atomic<uint32_t> finished{0};  // tasks of the current round that have finished
    std::exception_ptr error;  // the round's first, under mutex

    // The end of range r of a round of `count` tasks: the ranges split [0, count) evenly.
    uint32_t range_end(uint32_t r, uint32_t count) const { return uint32_t(uint64_t(count) * (r + 1) / threads); }

    // The start of range r of a round of `count` tasks.
    uint32_t range_begin(uint32_t r, uint32_t count) const { return r == 0 ? 0 : range_end(r - 1, count); }

    // A range's word: the round, then its front and back (offsets from its start).
    static uint64_t range_word(uint32_t round, uint32_t front, uint32_t back) {
        return uint64_t(round) << 32 | uint64_t(front) << 16 | back;
    }

    // Sets every range of round my_round to all of its tasks.
    void start_ranges(uint32_t my_round, uint32_t count) {
        for (uint32_t r = 0; r < threads; ++r)
            ranges[r].next.store(range_word(my_round, 0, range_end(r, count) - range_begin(r, count)),
                                 std::memory_order_release);
    }

    // Runs tasks of `my_round`: thread `me`'s range from its front, then the others' from their
    // backs, until none is left to claim (but a started range's last task, left to its owner).
    void work(uint32_t me, uint32_t my_round, uint32_t my_count, const Task& fn) {
        // The tasks this thread ran, added to `finished` once at the end: a count shared by
        // every thread, bumped after each task, passed its cache line from core to core a few
        // hundred times a sub-step in a scene of small bodies.
        uint32_t done_here = 0;
        for (uint32_t k = 0; k < threads; ++k) {
            const uint32_t r = (me + k) % threads, begin = range_begin(r, my_count);
            const bool own = k == 0;
            std::atomic<uint64_t>& next = ranges[r].next;
            uint64_t v = next.load(std::memory_order_relaxed);
            for (;;) {
                if (uint32_t(v >> 32) != my_round) break;
                const uint32_t front = uint32_t(v >> 16) & 0xffff, back = uint32_t(v) & 0xffff;
                if (front >= back || (!own && front > 0 && back - front < 2)) break;
                // The owner moves the front up, a thief the back down.
                const uint64_t claimed = own ? v + (uint64_t(1) << 16) : v - 1;
                if (!next.compare_exchange_weak(v, claimed, std::memory_order_acq_rel)) continue;
                try {
                    fn(begin + (own ? front : back - 1));
                } catch (...) {
                    std::lock_guard<std::mutex> lock(mutex);
                    if (!error) error = std::current_exception();
                }
                ++done_here;
                v = next.load(std::memory_order_relaxed);
            }
        }
        if (done_here != 0 && finished.fetch_add(done_here) + done_here == my_count && caller_asleep.load()) {
            std::lock_guard<std::mutex> lock(mutex);
            done.notify_all();
        }
    }

    // One round of `count` (at most kRoundTasks) tasks.
    void run_round(uint32_t count, const Task& task);

    void worker_main(uint32_t me) {
        uint32_t seen = 0;
        for (;;) {
            // A new round usually follows within microseconds: spin for it before sleeping.
            if (!spin_until([&] { return posted.load(std::memory_order_acquire) != seen; })) {
                std::unique_lock<std::mutex> lock(mutex);
                sleepers.fetch_add(1);
                wake.wait(lock, [&] { return posted.load() != seen; });
                sleepers.fetch_sub(1);
            }
            if (stop.load(std::memory_order_acquire)) return;
            seen = posted.load(std::memory_order_acquire);
            const Slot& slot = slots[seen & 1];
            const Task* fn = slot.task.load(std::memory_order_acquire);
            const uint32_t n = slot.count.load(std::memory_order_acquire);
            if (fn) work(me, seen, n, *fn);  // *fn outlives the round: the caller waits for its tasks
        }
    }

    // Wakes the sleeping workers after `posted` changed. Taking the mutex waits for a worker
    // between its check and its sleep, so the notification cannot fall in between.
    void wake_sleepers() {
        if (sleepers.load() == 0) return;
        { std::lock_guard<std::mutex> lock(mutex); }
        wake.notify_all();
    }
};

ThreadPool::ThreadPool(uint32_t threads) : shared_(new Shared) {
    Shared& s = *shared_;
    s.threads = std::max(threads, 1u);
    s.ranges.reset(new Shared::Range[s.threads]);
    try {
        for (uint32_t i = 1; i < s.threads; ++i) s.workers.emplace_back([&s, i] { s.worker_main(i); });
    } catch (...) {
        // Could not start every thread: stop the ones that run, then report.
        s.stop.store(true);
        s.posted.fetch_add(1);
        s.wake_sleepers();
        for (std::thread& t : s.workers) t.join();
        throw;
    }
}

ThreadPool::~ThreadPool() {
    Shared& s = *shared_;
    s.stop.store(true);
    s.posted.fetch_add(1);
    s.wake_sleepers();
    for (std::thread& t : s.workers) t.join();
}

uint32_t ThreadPool::size() const { return uint32_t(shared_->workers.size()) + 1; }

void ThreadPool::run(uint32_t count, const std::function<void(uint32_t)>& task) {
    Shared& s = *shared_;
    if (count <= kRoundTasks) return s.run_round(count, task);
    // Every part runs, as every task of a round does, before the first exception comes back.
    std::exception_ptr first;
    for (uint32_t base = 0, part_count; base < count; base += part_count) {
        part_count = std::min(kRoundTasks, count - base);
        const Shared::Task part = [&task, base](uint32_t i) { task(base + i); };
        try {
            s.run_round(part_count, part);
        } catch (...) {
            if (!first) first = std::current_exception();
        }
    }
    if (first) std::rethrow_exception(first);
}

void ThreadPool::Shared::run_round(uint32_t count, const Task& task) {
    // Nothing of the last round runs any more: its tasks have all finished, and a late worker
    // claims none of this one's before the ranges carry this round's number.
    const uint32_t my_round = ++round;
    error = nullptr;
    finished.store(0, std::memory_order_relaxed);
    Slot& slot = slots[my_round & 1];
    slot.task.store(&task, std::memory_order_release);
    slot.count.store(count, std::memory_order_release);
    start_ranges(my_round, count);
    posted.store(my_round);
    wake_sleepers();
    work(0, my_round, count, task);  // the caller takes part, its own range first
    // The other threads' last tasks usually end within microseconds: spin before sleeping.
    const auto all_done = [&] { return finished.load() == count; };
    if (!spin_until(all_done)) {
        std::unique_lock<std::mutex> lock(mutex);
        caller_asleep.store(true);
        done.wait(lock, all_done);
        caller_asleep.store(false, std::memory_order_relaxed);
    }
    if (error) {
        std::exception_ptr e = error;
        error = nullptr;
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
