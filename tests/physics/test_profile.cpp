// "Leave out what a scene does not need" (src/DESIGN.md section 7), shown by counts: the per-phase
// profile (lfem_world_get_profile) says which phases ran how often, and the bytes the library
// holds are counted by replacing the global operator new in this program (its own executable,
// like tests/robustness). Never wall-clock: only counts and byte totals are asserted.
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include "physics/lfem_test_util.h"

namespace {

// Live bytes allocated through operator new: each block carries its size in a 16-byte header
// (16 keeps the alignment malloc gives).
std::atomic<long long> g_live{0};

void* allocate(std::size_t n) {
    void* p = std::malloc(n + 16);
    if (!p) throw std::bad_alloc();
    std::memcpy(p, &n, sizeof n);
    g_live.fetch_add((long long)n, std::memory_order_relaxed);
    return static_cast<char*>(p) + 16;
}
void release(void* q) noexcept {
    if (!q) return;
    char* p = static_cast<char*>(q) - 16;
    std::size_t n;
    std::memcpy(&n, p, sizeof n);
    g_live.fetch_sub((long long)n, std::memory_order_relaxed);
    std::free(p);
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }

using namespace lfem_test;

namespace {

lfem_profile profile(lfem_world* w) {
    lfem_profile p{};
    EXPECT_EQ(lfem_world_get_profile(w, &p), LFEM_OK) << lfem_last_error();
    return p;
}

lfem_body static_floor(lfem_world* w, Mesh& m) {
    // 0.4 x 0.4 x 0.1 m slab with its top at z = 0.
    make_box_mesh(m, 0.4, 0.4, 0.1, 4, 4, 1, -0.2, -0.2, -0.1);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    return add_body(w, d, m);
}

// A soft 0.1 m block of 3 x 3 x 3 cells, bottom at z = 0.
lfem_body block(lfem_world* w, Mesh& m, double friction, lfem_model model = LFEM_MODEL_PAPER) {
    make_box_mesh(m, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.damping = 20.0;
    d.friction = friction;
    d.model = model;
    return add_body(w, d, m);
}

void run(lfem_world* w, int calls) {
    for (int i = 0; i < calls; ++i) ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
}

}  // namespace

TEST(Profile, RejectsNullPointers) {
    World w;
    lfem_profile p{};
    EXPECT_EQ(lfem_world_get_profile(nullptr, &p), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_get_profile(w, nullptr), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(lfem_world_reset_profile(nullptr), LFEM_INVALID_ARGUMENT);
}

TEST(Profile, EveryPhaseOfAContactSceneRunsOncePerSubstepAndResetClearsIt) {
    World w;
    Mesh fm, bm;
    static_floor(w, fm);
    block(w, bm, 0.5);
    run(w, 10);
    const lfem_world_stats s = stats(w);
    const lfem_profile p = profile(w);
    ASSERT_GT(s.contact_count, 0u) << "the block must rest on the floor";
    // One deformable body, one static body: the dynamic phases run once per sub-step for the
    // one moving body; detection and the solve once per sub-step for the world.
    EXPECT_EQ(p.substeps, s.steps);
    EXPECT_EQ(p.predictor.calls, s.steps);
    EXPECT_EQ(p.internal_forces.calls, s.steps);
    EXPECT_EQ(p.commit.calls, s.steps);
    EXPECT_EQ(p.global_rotation.calls, s.steps);  // "paper" model
    EXPECT_EQ(p.broad_phase.calls, s.steps);
    EXPECT_EQ(p.narrow_phase.calls, s.steps);
    EXPECT_EQ(p.normal_solve.calls, s.steps);
    EXPECT_EQ(p.friction.calls, s.steps);
    EXPECT_EQ(p.kinematic_motion.calls, 0u);
    EXPECT_GT(p.internal_forces.seconds, 0.0);
    EXPECT_GT(p.narrow_phase.seconds, 0.0);
    ASSERT_EQ(lfem_world_reset_profile(w), LFEM_OK);
    const lfem_profile z = profile(w);
    EXPECT_EQ(z.substeps, 0u);
    EXPECT_EQ(z.predictor.calls, 0u);
    EXPECT_EQ(z.predictor.seconds, 0.0);
    EXPECT_EQ(z.friction.calls, 0u);
}

TEST(Profile, FrictionlessSceneSpendsNothingOnFriction) {
    World w;
    Mesh fm, bm;
    static_floor(w, fm);
    block(w, bm, 0.0);  // mu = 0 on the block makes every pair it is in frictionless
    run(w, 10);
    const lfem_profile p = profile(w);
    ASSERT_GT(stats(w).contact_count, 0u);
    EXPECT_GT(p.normal_solve.calls, 0u);
    EXPECT_EQ(p.friction.calls, 0u);
    EXPECT_EQ(p.friction.seconds, 0.0);
}

TEST(Profile, SceneWithoutRigidShapesMakesNoShapeQueries) {
    World w;
    Mesh fm, bm;
    static_floor(w, fm);
    block(w, bm, 0.5);
    run(w, 10);
    const lfem_profile p = profile(w);
    ASSERT_GT(p.narrow_phase.calls, 0u);
    EXPECT_EQ(p.shape_queries.calls, 0u);
    EXPECT_EQ(p.shape_queries.seconds, 0.0);
    EXPECT_EQ(p.shape_tests, 0u);
    EXPECT_EQ(p.ccd_queries, 0u);
}

TEST(Profile, ClosedFormShapesNeverCallLibccd) {
    // A block on a plane shape: shape queries run, none through libccd (the plane has a closed
    // form); only a convex hull goes to libccd.
    World w;
    lfem_body_def gd = lfem_body_def_default();
    gd.type = LFEM_BODY_STATIC;
    lfem_body ground{};
    ASSERT_EQ(lfem_body_create(w, &gd, &ground), LFEM_OK);
    const lfem_shape_def plane = lfem_shape_def_default();
    ASSERT_EQ(lfem_body_add_shape(w, ground, &plane, NULL), LFEM_OK) << lfem_last_error();
    Mesh bm;
    block(w, bm, 0.5);
    run(w, 10);
    const lfem_profile p = profile(w);
    ASSERT_GT(stats(w).contact_count, 0u);
    EXPECT_EQ(p.shape_queries.calls, p.substeps);
    EXPECT_GT(p.shape_tests, 0u);
    EXPECT_EQ(p.ccd_queries, 0u);
}

TEST(Profile, ConvexHullGoesThroughLibccd) {
    World w;
    lfem_body_def gd = lfem_body_def_default();
    gd.type = LFEM_BODY_STATIC;
    lfem_body ground{};
    ASSERT_EQ(lfem_body_create(w, &gd, &ground), LFEM_OK);
    const double pts[] = {-0.15, -0.15, 0,    0.15, -0.15, 0,    0.15, 0.15, 0,    -0.15, 0.15, 0,
                          -0.25, -0.25, -0.2, 0.25, -0.25, -0.2, 0.25, 0.25, -0.2, -0.25, 0.25, -0.2};
    lfem_shape_def hull = lfem_shape_def_default();
    hull.type = LFEM_SHAPE_CONVEX_HULL;
    hull.points = pts;
    hull.point_count = 8;
    const lfem_status added = lfem_body_add_shape(w, ground, &hull, NULL);
    if (added == LFEM_UNSUPPORTED) GTEST_SKIP() << "built without libccd (LFEM_WITH_CCD=OFF)";
    ASSERT_EQ(added, LFEM_OK) << lfem_last_error();
    Mesh bm;
    block(w, bm, 0.5);
    run(w, 5);
    const lfem_profile p = profile(w);
    EXPECT_GT(p.ccd_queries, 0u);
    EXPECT_EQ(p.ccd_queries, p.shape_tests);  // the hull is the only shape
}

TEST(Profile, SceneWithoutContactMakesNoDetection) {
    World w;
    Mesh bm;
    block(w, bm, 0.5);  // alone, falling
    run(w, 10);
    const lfem_profile p = profile(w);
    ASSERT_GT(p.substeps, 0u);
    EXPECT_EQ(p.predictor.calls, p.substeps);
    EXPECT_EQ(p.broad_phase.calls, 0u);
    EXPECT_EQ(p.narrow_phase.calls, 0u);
    EXPECT_EQ(p.shape_queries.calls, 0u);
    EXPECT_EQ(p.normal_solve.calls, 0u);
    EXPECT_EQ(p.friction.calls, 0u);
    EXPECT_EQ(p.broad_phase.seconds + p.narrow_phase.seconds + p.normal_solve.seconds, 0.0);
}

TEST(Profile, StaticBodiesCostNothingInIntegration) {
    // Three static slabs beside one falling block: the integration phases count the block only.
    World w;
    Mesh m1, m2, m3, bm;
    for (Mesh* m : {&m1, &m2, &m3}) {
        const double dx = m == &m1 ? 1.0 : m == &m2 ? 2.0 : 3.0;
        make_box_mesh(*m, 0.4, 0.4, 0.1, 4, 4, 1, dx, 0.0, -0.1);
        lfem_body_def d = lfem_body_def_default();
        d.type = LFEM_BODY_STATIC;
        add_body(w, d, *m);
    }
    block(w, bm, 0.5, LFEM_MODEL_COROTATIONAL);
    run(w, 10);
    const lfem_profile p = profile(w);
    ASSERT_GT(p.substeps, 0u);
    EXPECT_EQ(p.predictor.calls, p.substeps);
    EXPECT_EQ(p.internal_forces.calls, p.substeps);
    EXPECT_EQ(p.commit.calls, p.substeps);
    EXPECT_EQ(p.kinematic_motion.calls, 0u);
    // No "paper" body: no eq. (2), no re-fit.
    EXPECT_EQ(p.global_rotation.calls, 0u);
    EXPECT_EQ(p.global_rotation.seconds, 0.0);
}

TEST(Profile, KinematicBodiesAreMovedNotIntegrated) {
    World w;
    Mesh km, bm;
    make_box_mesh(km, 0.4, 0.4, 0.1, 4, 4, 1, 2.0, 0.0, -0.1);
    lfem_body_def kd = lfem_body_def_default();
    kd.type = LFEM_BODY_KINEMATIC;
    kd.linear_velocity[0] = 1.0;
    add_body(w, kd, km);
    block(w, bm, 0.5);
    run(w, 10);
    const lfem_profile p = profile(w);
    EXPECT_EQ(p.kinematic_motion.calls, p.substeps);
    EXPECT_EQ(p.predictor.calls, p.substeps);  // the block only
}

TEST(Profile, UnusedFeaturesAllocateNothing) {
    // A lone block (n nodes) that touches nothing. What stepping adds to the memory the world
    // holds is the predictor's scratch of the one moving body: x^n, v^{n-1/2} and 1/mhat per
    // node, 7 doubles = 56 bytes a node (x3 for positions and velocities, x1 for 1/mhat), plus
    // per-world bookkeeping of a few hundred bytes independent of n (slot scratch headers, one
    // contact-body record). No contact forces (24 bytes a node), no detection boxes (48 bytes
    // a boundary triangle), no shape or friction buffers: the bound 56 n + 1024 bytes would be
    // exceeded by any of them.
    World w;
    Mesh bm;
    make_box_mesh(bm, 0.1, 0.1, 0.1, 6, 6, 6, 0, 0, 0);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e6;
    d.friction = 0.5;
    const lfem_body b = add_body(w, d, bm);
    const long long n = node_count(w, b);
    const long long before = g_live.load();
    for (int i = 0; i < 20; ++i) ASSERT_EQ(lfem_world_step(w, 0.005), LFEM_OK) << lfem_last_error();
    const long long held = g_live.load() - before;
    std::printf("a lone block of %lld nodes: stepping holds %lld bytes (%.1f per node)\n", n, held,
                double(held) / double(n));
    EXPECT_GE(held, 56 * n);  // the predictor scratch itself is there (the counter works)
    EXPECT_LE(held, 56 * n + 1024);
}

TEST(Profile, StaticBodiesAllocateNoStepScratch) {
    // A lone static slab: nothing moves, so stepping holds no per-node arrays at all, only
    // per-world bookkeeping independent of its size (bounded by 1024 bytes).
    World w;
    Mesh m;
    make_box_mesh(m, 1.0, 1.0, 0.1, 20, 20, 2, 0, 0, 0);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    add_body(w, d, m);
    const long long before = g_live.load();
    for (int i = 0; i < 5; ++i) ASSERT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
    const long long held = g_live.load() - before;
    std::printf("a lone static slab of %u nodes: stepping holds %lld bytes\n", m.nodes(), held);
    EXPECT_LE(held, 1024);
    const lfem_profile p = profile(w);
    EXPECT_EQ(p.predictor.calls + p.internal_forces.calls + p.commit.calls, 0u);
}
