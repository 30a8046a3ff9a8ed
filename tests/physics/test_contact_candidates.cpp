// Contact detection looks for candidate faces only now and then and re-tests them exactly at
// every sub-step (src/contact/contact_candidates.h): the contacts, and so every result, must be
// bitwise those of a search at every step. A far-away marker body that receives a shape before
// every call changes the world's geometry, which throws the candidates away: that run searches
// at every call, the other only when a budget of motion runs out, and both must agree bit for
// bit (the marker's shapes touch nothing: they lie 100 m away). Between searches the narrow
// phase also skips the faces a node lies clear of (src/contact/detect_node_triangle.cpp); a
// search starts every pair afresh, so with calls of one sub-step each the searching run tests
// every pair at every sub-step, and the skipping run must agree with it bit for bit.
#include <algorithm>
#include <cstdio>
#include <cstring>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// The scene on a static floor of floor_cells^2 cells, `calls` calls of dt.
std::vector<unsigned char> run_scene(bool search_every_call, uint32_t* contacts_seen, lfem_profile* profile,
                                     uint32_t floor_cells = 6, int calls = 50, double dt = 0.004) {
    lfem_world_def wd = lfem_world_def_default();
    World w(wd);
    Mesh floor_mesh, a, b, c;
    make_box_mesh(floor_mesh, 0.8, 0.8, 0.1, floor_cells, floor_cells, 1, -0.4, -0.4, -0.1);
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    std::vector<lfem_body> bodies{add_body(w, f, floor_mesh)};
    lfem_body marker;
    EXPECT_EQ(lfem_body_create(w, &f, &marker), LFEM_OK);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 2e5;
    d.linear_velocity[0] = 0.6;  // sliding: candidates run out of budget and come back
    d.angular_velocity[2] = 2.0;
    make_box_mesh(a, 0.1, 0.1, 0.1, 3, 3, 3, -0.2, -0.05, 0.002);
    bodies.push_back(add_body(w, d, a));
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    d.linear_velocity[0] = -0.3;
    make_box_mesh(b, 0.08, 0.08, 0.08, 2, 2, 2, 0.05, -0.04, 0.002);
    bodies.push_back(add_body(w, d, b));
    d.type = LFEM_BODY_RIGID;
    d.linear_velocity[0] = 0.0;
    d.linear_velocity[2] = -1.0;
    make_box_mesh(c, 0.05, 0.05, 0.05, 1, 1, 1, -0.18, -0.03, 0.15);  // lands on the first block
    bodies.push_back(add_body(w, d, c));
    *contacts_seen = 0;
    for (int call = 0; call < calls; ++call) {
        if (search_every_call) {
            lfem_shape_def s = lfem_shape_def_default();
            s.type = LFEM_SHAPE_SPHERE;
            s.radius = 0.01;
            s.center[0] = 100.0 + call;
            EXPECT_EQ(lfem_body_add_shape(w, marker, &s, nullptr), LFEM_OK) << lfem_last_error();
        }
        EXPECT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
        *contacts_seen = std::max(*contacts_seen, stats(w).contact_count);
    }
    EXPECT_EQ(lfem_world_get_profile(w, profile), LFEM_OK);
    std::vector<unsigned char> out = fingerprint(w, bodies);
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> list(count);
    lfem_world_query_contacts(w, list.data(), count, &count);
    for (lfem_contact& k : list) k.body_a.generation = k.body_b.generation = 0;  // per world
    const unsigned char* p = reinterpret_cast<const unsigned char*>(list.data());
    out.insert(out.end(), p, p + count * sizeof(lfem_contact));
    return out;
}

}  // namespace

TEST(ContactCandidates, CachedCandidatesGiveBitwiseTheContactsOfASearchAtEveryCall) {
    uint32_t seen_cached = 0, seen_searched = 0;
    lfem_profile cached_profile{}, searched_profile{};
    const std::vector<unsigned char> cached = run_scene(false, &seen_cached, &cached_profile);
    const std::vector<unsigned char> searched = run_scene(true, &seen_searched, &searched_profile);
    EXPECT_GT(seen_cached, 20u);  // the scene does exercise contact
    // The marker makes the second run search at every call; the first searches less often,
    // but more than once (the sliding and falling bodies run out of budget).
    EXPECT_GE(searched_profile.candidate_searches, 50u);
    EXPECT_GT(cached_profile.candidate_searches, 1u);
    EXPECT_LT(cached_profile.candidate_searches, searched_profile.candidate_searches);
    std::printf("candidate searches: %llu for %llu sub-steps (a search at every call: %llu)\n",
                (unsigned long long)cached_profile.candidate_searches, (unsigned long long)cached_profile.substeps,
                (unsigned long long)searched_profile.candidate_searches);
    EXPECT_EQ(seen_cached, seen_searched);
    ASSERT_EQ(cached.size(), searched.size());
    EXPECT_EQ(0, std::memcmp(cached.data(), searched.data(), cached.size()));
}

// On a fine floor (3.3 cm cells, as fine as the blocks' own) a resting or sliding node has
// several candidate faces and lies clear of most of them, which are skipped; calls of one
// sub-step each (2.5e-4 s, below the stable step), so that the searching run tests every pair at
// every sub-step. The blocks slide over several floor cells (0.6 m/s for 0.1 s), so skips run out
// and faces are tested again.
TEST(ContactCandidates, SkippedFacesGiveBitwiseTheContactsOfTestingEveryFace) {
    uint32_t seen_skipping = 0, seen_testing = 0;
    lfem_profile skipping_profile{}, testing_profile{};
    const std::vector<unsigned char> skipping = run_scene(false, &seen_skipping, &skipping_profile, 24, 400, 2.5e-4);
    const std::vector<unsigned char> testing = run_scene(true, &seen_testing, &testing_profile, 24, 400, 2.5e-4);
    EXPECT_GT(seen_skipping, 20u);
    EXPECT_EQ(skipping_profile.substeps, 400u);  // one sub-step a call
    EXPECT_EQ(testing_profile.candidate_searches, 400u);
    EXPECT_LT(skipping_profile.candidate_searches, 100u);
    std::printf("fine floor: candidate searches %llu for %llu sub-steps (testing every pair: %llu)\n",
                (unsigned long long)skipping_profile.candidate_searches,
                (unsigned long long)skipping_profile.substeps,
                (unsigned long long)testing_profile.candidate_searches);
    EXPECT_EQ(seen_skipping, seen_testing);
    ASSERT_EQ(skipping.size(), testing.size());
    EXPECT_EQ(0, std::memcmp(skipping.data(), testing.data(), skipping.size()));
}
