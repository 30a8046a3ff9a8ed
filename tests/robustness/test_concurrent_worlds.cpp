// Separate worlds step at the same time in separate threads without interfering: each gives
// bitwise the result it gives alone. Run under ThreadSanitizer by tests/sanitize.sh, which
// reports any data race between them (shared caches, static scratch, the generation counter).
#include <thread>

#include "robustness/robustness_scene.h"

using namespace lfem_test;

namespace {

std::vector<unsigned char> run_alone(int steps) {
    RobustnessScene scene;
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
