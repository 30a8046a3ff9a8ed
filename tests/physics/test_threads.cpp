// The step's parallel loops (element forces by coloured blocks, predictor and commit by node
// blocks, or small bodies side by side, one per task) give results bitwise independent of
// lfem_world_def.thread_count: every node sums its contributions, and every energy its blocks,
// in an order fixed by the mesh alone.
#include <cstring>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// Spinning blocks dropped onto a plate of the given model lying on a static floor: contact
// with the floor and between the bodies. With one block the plate holds most of the tets and
// runs its own loops on the pool (and so does the block, the only other body): the plate has
// enough tets (6 * 20 * 20 * 4 = 9600) and nodes (2205) for many element blocks and colours and
// for two node blocks, so every parallel loop really splits. With four blocks (3072 tets each)
// no body holds half of the tets, so on two threads all five bodies are stepped side by side,
// one per task (on three, the plate again on the pool beside the four). Without the plate the
// four blocks fall on the static floor side by side: four contact groups, which the multiplier
// solve runs side by side as well.
// quadratic: the plate and the blocks of 10-node tets, of half the cells along each edge (as
// many nodes, an eighth of the tets).
std::vector<unsigned char> run_scene(lfem_model model, uint32_t threads, uint32_t blocks, bool plate = true,
                                     bool quadratic = false) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.contact_iterations = 20;  // a short test: equality, not accuracy, is the point
    World w(wd);
    Mesh floor_mesh, plate_mesh;
    make_box_mesh(floor_mesh, 0.6, 0.6, 0.05, 2, 2, 1, -0.3, -0.3, -0.05);
    lfem_body_def f = lfem_body_def_default();
    f.young_modulus = 1e7;
    f.friction = 0.4;
    lfem_body_def fixed = f;
    fixed.type = LFEM_BODY_STATIC;
    std::vector<lfem_body> bodies{add_body(w, fixed, floor_mesh)};
    lfem_body_def d = lfem_body_def_default();
    d.model = model;
    d.young_modulus = 3e5;
    d.friction = 0.4;
    const uint32_t coarser = quadratic ? 2 : 1;  // cells are this much larger
    const auto box = [&](Mesh& m, double sx, double sy, double sz, uint32_t nx, uint32_t ny, uint32_t nz, double ox,
                         double oy, double oz) {
        if (quadratic)
            make_quadratic_box_mesh(m, sx, sy, sz, nx / coarser, ny / coarser, nz / coarser, ox, oy, oz);
        else
            make_box_mesh(m, sx, sy, sz, nx, ny, nz, ox, oy, oz);
    };
    if (plate) {
        box(plate_mesh, 0.1, 0.1, 0.02, 20, 20, 4, -0.05, -0.05, 0.0);
        bodies.push_back(add_body(w, d, plate_mesh));
    }
    d.angular_velocity[0] = 3.0;
    d.linear_velocity[2] = -1.0;
    for (uint32_t k = 0; k < blocks; ++k) {
        Mesh block;
        if (blocks == 1) {
            box(block, 0.06, 0.06, 0.06, 8, 8, 8, -0.03, -0.02, 0.021);
        } else {  // a 2 x 2 grid of 4 cm blocks, 1 cm apart
            const double x0 = k % 2 ? 0.005 : -0.045, y0 = k / 2 ? 0.005 : -0.045;
            box(block, 0.04, 0.04, 0.04, 8, 8, 8, x0, y0, plate ? 0.021 : 0.001);
        }
        bodies.push_back(add_body(w, d, block));
    }
    uint32_t most = 0;  // the scene must exercise contact
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(lfem_world_step(w, 0.002), LFEM_OK) << lfem_last_error();
        most = std::max(most, stats(w).contact_count);
    }
    EXPECT_GT(most, 100u);
    std::vector<unsigned char> out = fingerprint(w, bodies);
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    lfem_world_query_contacts(w, c.data(), count, &count);
    for (lfem_contact& k : c) k.body_a.generation = k.body_b.generation = 0;  // per world
    const unsigned char* p = reinterpret_cast<const unsigned char*>(c.data());
    out.insert(out.end(), p, p + count * sizeof(lfem_contact));
    return out;
}

}  // namespace

TEST(Threads, OneTwoAndThreeThreadsGiveBitwiseIdenticalResults) {
    for (lfem_model model : {LFEM_MODEL_LINEAR, LFEM_MODEL_PAPER, LFEM_MODEL_NEO_HOOKEAN,
                             LFEM_MODEL_COROTATIONAL}) {
        for (int scene = 0; scene < 3; ++scene) {
            const uint32_t blocks = scene == 0 ? 1 : 4;
            const bool plate = scene < 2;
            const std::vector<unsigned char> one = run_scene(model, 1, blocks, plate);
            for (uint32_t threads : {2u, 3u}) {
                const std::vector<unsigned char> many = run_scene(model, threads, blocks, plate);
                ASSERT_EQ(one.size(), many.size());
                EXPECT_EQ(0, std::memcmp(one.data(), many.data(), one.size()))
                    << "model " << model << ", " << threads << " threads, " << blocks
                    << " block(s)" << (plate ? " on the plate" : " on the floor");
            }
        }
    }
}

// The same with 10-node tets: their element loop has blocks and colours of its own (blocks of
// 64 tets), and the plate still splits into two node blocks. One block with the corotational
// model (its rotation per quadrature point), four with the neo-Hookean one.
TEST(Threads, QuadraticTetsGiveBitwiseIdenticalResults) {
    for (lfem_model model : {LFEM_MODEL_COROTATIONAL, LFEM_MODEL_NEO_HOOKEAN}) {
        {
            const uint32_t blocks = model == LFEM_MODEL_COROTATIONAL ? 1 : 4;
            const std::vector<unsigned char> one = run_scene(model, 1, blocks, true, true);
            for (uint32_t threads : {2u, 3u}) {
                const std::vector<unsigned char> many = run_scene(model, threads, blocks, true, true);
                ASSERT_EQ(one.size(), many.size());
                EXPECT_EQ(0, std::memcmp(one.data(), many.data(), one.size()))
                    << "model " << model << ", " << threads << " threads, " << blocks << " block(s)";
            }
        }
    }
}

TEST(Threads, ThreadCountIsCheckedAndDefaultsToOne) {
    lfem_world_def def = lfem_world_def_default();
    EXPECT_EQ(def.thread_count, 1u);
    lfem_world* w = nullptr;
    for (uint32_t bad : {0u, 65u, 1000u}) {
        def.thread_count = bad;
        EXPECT_EQ(lfem_world_create(&def, &w), LFEM_INVALID_ARGUMENT);
        EXPECT_EQ(w, nullptr);
        EXPECT_NE(std::strstr(lfem_last_error(), "thread_count"), nullptr) << lfem_last_error();
    }
    def.thread_count = 64;
    ASSERT_EQ(lfem_world_create(&def, &w), LFEM_OK) << lfem_last_error();
    lfem_world_destroy(w);
}
