// The thread pool's loops (src/common/thread_pool.h): every task runs exactly once whatever the
// number of threads and tasks (each thread starts with its own range of the tasks, then takes
// what is left of the others' from their backs; a loop longer than a round's 65,535 tasks runs
// as several rounds), also when the threads had fallen asleep between rounds or while
// waiting for a long task, an exception reaches the caller only after every other task
// has finished, and blocked_sum gives the same bits for any number of threads.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/thread_pool.h"

namespace {

TEST(ThreadPool, EveryTaskRunsExactlyOnceForAnyCountAndThreads) {
    for (uint32_t threads = 1; threads <= 4; ++threads) {
        lfem::ThreadPool pool(threads);
        // Counts below, at and above the thread count, and uneven splits; many rounds back to
        // back, as a step runs them.
        for (int round = 0; round < 50; ++round)
            for (uint32_t count : {0u, 1u, 2u, 3u, 5u, 7u, 64u, 1001u}) {
                std::vector<std::atomic<int>> runs(count);
                for (auto& r : runs) r.store(0);
                lfem::parallel_for(&pool, count, [&](uint32_t i) { runs[i].fetch_add(1); });
                for (uint32_t i = 0; i < count; ++i)
                    ASSERT_EQ(runs[i].load(), 1) << "task " << i << " of " << count << ", " << threads << " threads";
            }
    }
}

TEST(ThreadPool, LoopsLongerThanOneRoundRunEveryTaskOnce) {
    // A round's ranges hold 16-bit offsets: 65,535 tasks at most; longer loops are split.
    for (uint32_t threads = 2; threads <= 3; ++threads) {
        lfem::ThreadPool pool(threads);
        for (uint32_t count : {65535u, 65536u, 131071u, 200003u}) {
            std::vector<std::atomic<uint8_t>> runs(count);
            for (auto& r : runs) r.store(0);
            lfem::parallel_for(&pool, count, [&](uint32_t i) { runs[i].fetch_add(1); });
            uint32_t wrong = 0;
            for (uint32_t i = 0; i < count; ++i) wrong += runs[i].load() != 1;
            EXPECT_EQ(wrong, 0u) << count << " tasks, " << threads << " threads";
        }
        // An exception in one part: every other task of every part still runs, then it comes back.
        std::atomic<uint32_t> ran{0};
        EXPECT_THROW(lfem::parallel_for(&pool, 140000u,
                                        [&](uint32_t i) {
                                            if (i == 70000) throw std::runtime_error("task 70000");
                                            ran.fetch_add(1);
                                        }),
                     std::runtime_error);
        EXPECT_EQ(ran.load(), pool.size() > 1 ? 139999u : 70000u);  // inline, it stops at the throw
    }
}

TEST(ThreadPool, RoundsAfterTheThreadsFellAsleepStillRunEveryTask) {
    // The threads spin for 50 us, then sleep: a pause longer than that between two rounds puts
    // the workers to sleep (the next round must wake them), and a task longer than that puts the
    // caller to sleep while it waits (the last task must wake it). Neither wake-up may be lost
    // (a lost one hangs the loop) nor a task run twice.
    for (uint32_t threads = 2; threads <= 4; ++threads) {
        lfem::ThreadPool pool(threads);
        for (int round = 0; round < 60; ++round) {
            const uint32_t count = 3 + uint32_t(round % 7);
            std::vector<std::atomic<int>> runs(count);
            for (auto& r : runs) r.store(0);
            lfem::parallel_for(&pool, count, [&](uint32_t i) {
                runs[i].fetch_add(1);
                if (round % 3 == 1 && i == count - 1) std::this_thread::sleep_for(std::chrono::microseconds(200));
            });
            for (uint32_t i = 0; i < count; ++i) ASSERT_EQ(runs[i].load(), 1) << "task " << i << ", round " << round;
            if (round % 2 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    }
}

TEST(ThreadPool, AnExceptionComesBackAfterTheOtherTasksFinished) {
    lfem::ThreadPool pool(3);
    std::atomic<int> finished{0};
    EXPECT_THROW(lfem::parallel_for(&pool, 40,
                                    [&](uint32_t i) {
                                        if (i == 17) throw std::runtime_error("task 17");
                                        finished.fetch_add(1);
                                    }),
                 std::runtime_error);
    // On the pool all the others ran to their end before the rethrow; without workers (a build
    // without threads) the loop runs inline and stops at the throw.
    EXPECT_EQ(finished.load(), pool.size() > 1 ? 39 : 17);
    // The pool is usable afterwards.
    std::atomic<int> again{0};
    lfem::parallel_for(&pool, 10, [&](uint32_t) { again.fetch_add(1); });
    EXPECT_EQ(again.load(), 10);
}

TEST(ThreadPool, BlockedSumIsBitwiseTheSameOnAnyNumberOfThreads) {
    // Terms of very different sizes, so that a different order of addition would change bits.
    const uint32_t n = 5 * lfem::kNodeBlock + 123;
    std::vector<double> term(n);
    for (uint32_t i = 0; i < n; ++i) term[i] = std::pow(10.0, double(i % 17) - 8.0) * (i % 3 ? 1.0 : -0.7);
    double sums[4];
    for (uint32_t threads = 1; threads <= 4; ++threads) {
        lfem::ThreadPool pool(threads);
        lfem::Sums<1> s;
        lfem::blocked_sum(n, &pool, s, [&](uint32_t i, lfem::Sums<1>& out) { out.v[0] += term[i]; });
        sums[threads - 1] = s.v[0];
    }
    for (int t = 1; t < 4; ++t) EXPECT_EQ(0, std::memcmp(&sums[0], &sums[t], sizeof(double))) << t + 1 << " threads";
}

}  // namespace
