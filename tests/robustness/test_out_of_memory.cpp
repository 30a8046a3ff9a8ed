// Out of memory anywhere inside a call: the call returns LFEM_OUT_OF_MEMORY and the world is
// exactly as before (bit for bit), and usable afterwards. The allocation that fails is chosen
// by a replacement of the global operator new in this test program, which the shared library
// uses too: the test fails the 1st, 2nd, ... allocation of a call in turn, until the call
// needs no more than that.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "robustness/robustness_scene.h"

namespace {

// -1: no failure planned. Otherwise the number of allocations still allowed to succeed; the
// next one fails (once: the error handling itself must be able to allocate its message).
std::atomic<long> g_allow{-1};
std::atomic<long> g_count{0};

void* allocate(std::size_t n) {
    g_count.fetch_add(1, std::memory_order_relaxed);
    // One compare-and-swap per allocation: the worker threads of a step allocate at the same
    // time, and exactly the planned allocation must fail, once.
    long left = g_allow.load(std::memory_order_relaxed);
    while (left >= 0 && !g_allow.compare_exchange_weak(left, left == 0 ? -1 : left - 1,
                                                       std::memory_order_relaxed)) {
    }
    if (left == 0) throw std::bad_alloc();
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}

}  // namespace

// The replacements allocate with malloc, so their deletes free. GCC at -O1 (the sanitizer
// builds) inlines allocate() into callers and then takes free() of operator new's memory for a
// mismatch; here it is the pair working as designed.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

using namespace lfem_test;

namespace {

// Runs `call` with its k-th allocation failing, for k = 0, 1, ... until a run succeeds.
// Returns how many failure points were tried.
template <class Call, class Check>
long fail_each_allocation(Call&& call, Check&& check_unchanged) {
    for (long k = 0;; ++k) {
        g_allow.store(k);
        const lfem_status s = call();
        const bool failed_inside = g_allow.load() == -1;  // the planned failure happened
        g_allow.store(-1);
        if (!failed_inside) {
            EXPECT_EQ(s, LFEM_OK) << lfem_last_error();
            return k;
        }
        EXPECT_EQ(s, LFEM_OUT_OF_MEMORY) << "allocation " << k << ": " << lfem_last_error();
        check_unchanged(k);
        if (k > 100000) {
            ADD_FAILURE() << "the call never stopped allocating";
            return k;
        }
    }
}

}  // namespace

// On one thread, and on two worker threads with a body large enough (3072 tets) to split the
// element loop (the failing allocation may then be a worker's: the pool hands the exception
// back to the stepping thread).
TEST(OutOfMemory, FailedStepLeavesTheWorldUnchanged) {
    for (uint32_t threads : {1u, 2u}) {
        RobustnessScene scene(threads, threads == 1 ? 3 : 8);
        EXPECT_GT(scene.run(30), 5u);  // in contact: detection and the solve allocate too
        // Each failing call is compared against the state before it; a successful one moves on.
        std::vector<unsigned char> before = scene.state();
        const long points = fail_each_allocation(
            [&] { return lfem_world_step(scene.w, 0.005); },
            [&](long k) { ASSERT_EQ(before, scene.state()) << "allocation " << k << " changed the world"; });
        EXPECT_GT(points, 10) << "the step allocates: the replacement operator new must be in use";
        std::printf("step on %u thread(s): failed at each of its %ld allocations in turn, world "
                    "unchanged each time\n", threads, points);
        // The world steps on normally.
        EXPECT_GT(scene.run(5), 0u);
    }
}

TEST(OutOfMemory, FailedCreateAddMeshSaveAndLoadChangeNothing) {
    RobustnessScene scene;
    scene.run(5);
    const std::vector<unsigned char> before = scene.state();
    const lfem_body_def def = lfem_body_def_default();
    lfem_body body{};
    fail_each_allocation([&] { return lfem_body_create(scene.w, &def, &body); },
                         [&](long k) { ASSERT_EQ(before, scene.state()) << "allocation " << k; });
    // The new body has no mesh yet (nothing to read back): its node count stands for it.
    std::vector<lfem_body> all = scene.bodies;
    auto state = [&] {
        std::vector<unsigned char> f = fingerprint(scene.w, all);
        f.push_back(uint8_t(node_count(scene.w, body)));
        return f;
    };
    const std::vector<unsigned char> with_empty_body = state();
    Mesh mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 2, 2, 2, 0.0, 0.3, 0.3);
    fail_each_allocation(
        [&] {
            return lfem_body_add_mesh(scene.w, body, lfem_mesh_get_positions(mesh.m), mesh.nodes(),
                                      lfem_mesh_get_tets(mesh.m), mesh.tets());
        },
        [&](long k) { ASSERT_EQ(with_empty_body, state()) << "allocation " << k; });

    if (!LFEM_WITH_IO) return;  // no checkpoint files in this build
    const std::string path = std::string(::testing::TempDir()) + "lfem_oom.ckpt";
    all.push_back(body);  // now with its mesh
    const std::vector<unsigned char> saved = fingerprint(scene.w, all);
    fail_each_allocation([&] { return lfem_world_save(scene.w, path.c_str()); },
                         [&](long k) { ASSERT_EQ(saved, fingerprint(scene.w, all)) << "allocation " << k; });
    lfem_world* loaded = nullptr;
    fail_each_allocation([&] { return lfem_world_load(path.c_str(), &loaded); },
                         [&](long) { ASSERT_EQ(loaded, nullptr); });
    ASSERT_NE(loaded, nullptr);
    EXPECT_EQ(saved, fingerprint(loaded, all));
    lfem_world_destroy(loaded);
    std::remove(path.c_str());
}

namespace {

// Everything a fixed set of rays and boxes answers, as bytes (generations left out: they are
// process-wide).
std::vector<unsigned char> query_answers(lfem_world* w) {
    std::vector<unsigned char> out;
    const lfem_query_filter f = lfem_query_filter_default();
    for (int i = 0; i < 6; ++i) {
        const double o[3] = {-0.3 + 0.1 * i, -0.02, 0.4}, d[3] = {0.05 * i - 0.1, 0.03, -1.0};
        lfem_ray_hit hits[32];
        uint32_t n = 0;
        EXPECT_EQ(lfem_world_cast_ray_all(w, o, d, HUGE_VAL, f, hits, 32, &n), LFEM_OK) << lfem_last_error();
        for (uint32_t k = 0; k < n; ++k) {
            hits[k].body.generation = 0;
            const unsigned char* p = reinterpret_cast<const unsigned char*>(&hits[k]);
            out.insert(out.end(), p, p + sizeof hits[k]);
        }
        const double lo[3] = {-0.3 + 0.1 * i, -0.1, 0.0}, hi[3] = {-0.2 + 0.1 * i, 0.1, 0.2};
        lfem_body found[16];
        EXPECT_EQ(lfem_world_overlap_box(w, lo, hi, f, found, 16, &n), LFEM_OK) << lfem_last_error();
        for (uint32_t k = 0; k < n; ++k) out.push_back(uint8_t(found[k].index));
    }
    return out;
}

}  // namespace

// A skin added, a step taken with the queries' cache in use (the step keeps its boxes), and
// the queries themselves, each failing at every allocation in turn: each failure leaves the
// world as it was, and the answers afterwards are those of a twin world that never failed.
TEST(OutOfMemory, FailedSkinsStepsAndQueriesChangeNothing) {
    RobustnessScene scene, twin;
    scene.run(5), twin.run(5);
    EXPECT_EQ(query_answers(scene.w), query_answers(twin.w));  // both now in use
    std::vector<unsigned char> before = scene.state();
    const lfem_body soft = scene.bodies[4];  // the neo-Hookean body
    long points = fail_each_allocation(
        [&] {
            const double p[9] = {0.0, -0.02, 0.18, 0.03, -0.02, 0.18, 0.0, 0.01, 0.2};
            const uint32_t t[3] = {0, 1, 2};
            return lfem_body_add_skin(scene.w, soft, p, 3, t, 1, nullptr);
        },
        [&](long k) { ASSERT_EQ(before, scene.state()) << "add_skin, allocation " << k; });
    EXPECT_GT(points, 2);
    {
        const double p[9] = {0.0, -0.02, 0.18, 0.03, -0.02, 0.18, 0.0, 0.01, 0.2};
        const uint32_t t[3] = {0, 1, 2};
        ASSERT_EQ(lfem_body_add_skin(twin.w, twin.bodies[4], p, 3, t, 1, nullptr), LFEM_OK);
    }
    EXPECT_EQ(scene.state(), twin.state());
    before = scene.state();
    points = fail_each_allocation([&] { return lfem_world_step(scene.w, 0.005); },
                                  [&](long k) { ASSERT_EQ(before, scene.state()) << "step, allocation " << k; });
    ASSERT_EQ(lfem_world_step(twin.w, 0.005), LFEM_OK);
    EXPECT_EQ(scene.state(), twin.state());
    EXPECT_EQ(query_answers(scene.w), query_answers(twin.w));
    // A new body makes the cache stale: the query itself then boxes the bodies and builds trees.
    Mesh extra;
    make_box_mesh(extra, 0.05, 0.05, 0.05, 1, 1, 1, -0.28, -0.02, 0.0);
    for (lfem_world* w : {scene.w.w, twin.w.w}) {
        lfem_body_def d = lfem_body_def_default();
        d.type = LFEM_BODY_STATIC;
        add_body(w, d, extra);
    }
    before = scene.state();
    points = fail_each_allocation(
        [&] {
            const double o[3] = {-0.3, 0.0, 0.5}, d[3] = {0.0, 0.0, -1.0};
            lfem_ray_hit hits[16];
            uint32_t n = 0;
            return lfem_world_cast_ray_all(scene.w, o, d, HUGE_VAL, lfem_query_filter_default(), hits, 16, &n);
        },
        [&](long k) { ASSERT_EQ(before, scene.state()) << "cast_ray_all, allocation " << k; });
    EXPECT_GT(points, 2);
    EXPECT_EQ(query_answers(scene.w), query_answers(twin.w));
    std::printf("add_skin, a step with queries in use and a ray cast into a stale cache failed at each of "
                "their allocations in turn, world and answers unchanged\n");
}
