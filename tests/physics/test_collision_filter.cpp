// Collision filters: two bodies touch only if each one's category is in the other's mask; a
// scene checks only the pairs it asks for. Plus the contact query's buffer rules.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// A soft block dropped 2 mm onto a static floor, filtered as given; returns the contacts
// found and the block's lowest node after 0.2 s.
std::pair<uint32_t, double> drop(uint32_t block_category, uint32_t floor_mask) {
    World w;
    Mesh floor_mesh, block_mesh;
    make_box_mesh(floor_mesh, 0.4, 0.4, 0.1, 2, 2, 1, -0.2, -0.2, -0.1);
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    f.mask_bits = floor_mask;
    add_body(w, f, floor_mesh);
    make_box_mesh(block_mesh, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.002);
    lfem_body_def b = lfem_body_def_default();
    b.category_bits = block_category;
    const lfem_body block = add_body(w, b, block_mesh);
    uint32_t most = 0;
    for (int i = 0; i < 20; ++i) {
        EXPECT_EQ(lfem_world_step(w, 0.01), LFEM_OK) << lfem_last_error();
        most = std::max(most, stats(w).contact_count);
    }
    double lowest = 1;
    const std::vector<double> x = positions(w, block);
    for (size_t k = 2; k < x.size(); k += 3) lowest = std::fmin(lowest, x[k]);
    return {most, lowest};
}

}  // namespace

TEST(CollisionFilter, MasksDecideWhichPairsAreChecked) {
    const auto touching = drop(0x2u, 0x2u);  // the floor's mask includes the block's category
    EXPECT_GT(touching.first, 0u);
    EXPECT_GT(touching.second, -1e-6);  // it rests on the floor
    const auto ignored = drop(0x2u, 0x4u);  // it does not: the block falls through
    EXPECT_EQ(ignored.first, 0u);
    EXPECT_LT(ignored.second, -0.1);  // free fall for 0.2 s: about 0.2 m below the start
}

TEST(CollisionFilter, QueryReportsTheCountAndRefusesASmallBuffer) {
    World w;
    Mesh floor_mesh, block_mesh;
    make_box_mesh(floor_mesh, 0.4, 0.4, 0.1, 2, 2, 1, -0.2, -0.2, -0.1);
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    add_body(w, f, floor_mesh);
    make_box_mesh(block_mesh, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0);
    add_body(w, lfem_body_def_default(), block_mesh);
    ASSERT_EQ(lfem_world_step(w, 0.05), LFEM_OK) << lfem_last_error();
    uint32_t count = 0;
    ASSERT_EQ(lfem_world_query_contacts(w, nullptr, 0, &count), LFEM_BUFFER_TOO_SMALL);
    ASSERT_EQ(count, stats(w).contact_count);
    ASSERT_GT(count, 0u);
    std::vector<lfem_contact> c(count - 1);
    uint32_t again = 0;
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), uint32_t(c.size()), &again), LFEM_BUFFER_TOO_SMALL);
    EXPECT_EQ(again, count);
    c.resize(count);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), uint32_t(c.size()), &again), LFEM_OK);
    for (const lfem_contact& k : c) {
        EXPECT_EQ(k.shape, UINT32_MAX);  // mesh against mesh
        EXPECT_GT(k.force[2] * (k.body_a.index == 1 ? 1 : -1), 0.0);  // the floor pushes up
    }
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), uint32_t(c.size()), nullptr), LFEM_INVALID_ARGUMENT);
}
