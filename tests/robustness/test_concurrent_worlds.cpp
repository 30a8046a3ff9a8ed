// Separate worlds step at the same time in separate threads without interfering: each gives
// bitwise the result it gives alone; and one world on its own worker threads (thread_count)
// gives bitwise the result of one thread. Run under ThreadSanitizer by tests/sanitize.sh, which
// reports any data race (shared caches, static scratch, the generation counter, the pool).
#include <thread>

#include "robustness/robustness_scene.h"

using namespace lfem_test;

namespace {

std::vector<unsigned char> run_alone(int steps, uint32_t thread_count = 1, uint32_t cells = 3) {
    RobustnessScene scene(thread_count, cells);
    scene.run(steps);
    return scene.state();
}

}  // namespace

TEST(ConcurrentWorlds, TwoThreadsTwoWorldsMatchSequentialRuns) {
    const int steps = 30;
    const std::vector<unsigned char> reference = run_alone(steps);
    std::vector<unsigned char> results[2];
    std::string errors[2];
    std::thread threads[2];
    for (int t = 0; t < 2; ++t)
        threads[t] = std::thread([&, t] {
            // Scenes are built inside the thread, so creation, stepping, queries and
            // destruction all overlap with the other thread's.
            RobustnessScene scene;
            for (int i = 0; i < steps; ++i)
                if (lfem_world_step(scene.w, 0.005) != LFEM_OK) errors[t] = lfem_last_error();
            results[t] = scene.state();
        });
    for (std::thread& t : threads) t.join();
    for (int t = 0; t < 2; ++t) {
        EXPECT_EQ(errors[t], "");
        // Handles carry process-wide generations: the fingerprint holds none of them, so the
        // three runs are comparable byte for byte.
        EXPECT_EQ(results[t], reference) << "thread " << t;
    }
}

// Every body type in contact, with a body large enough to split every parallel loop, stepped
// on 2 and 3 worker threads: the element loop runs over coloured blocks and every sum over
// fixed blocks in block order, so the thread count must not change a single bit.
TEST(ConcurrentWorlds, OneWorldOnWorkerThreadsMatchesOneThreadBitwise) {
    const int steps = 10;
    const std::vector<unsigned char> reference = run_alone(steps, 1, 10);
    EXPECT_EQ(run_alone(steps, 2, 10), reference) << "2 threads";
    EXPECT_EQ(run_alone(steps, 3, 10), reference) << "3 threads";
}

// Two worlds, each on two worker threads, stepped at the same time from two threads.
TEST(ConcurrentWorlds, TwoWorldsWithWorkerThreadsStepConcurrently) {
    const int steps = 10;
    const std::vector<unsigned char> reference = run_alone(steps, 1, 10);
    std::vector<unsigned char> results[2];
    std::thread threads[2];
    for (int t = 0; t < 2; ++t)
        threads[t] = std::thread([&, t] { results[t] = run_alone(steps, 2, 10); });
    for (std::thread& t : threads) t.join();
    for (int t = 0; t < 2; ++t) EXPECT_EQ(results[t], reference) << "thread " << t;
}
