// bench_strip_cases: the README's 60 cm self-contact strip cases (a soft strip 60 x 6 x 1 cm,
// 60 x 6 x 2 cells, standing on end 2 mm above a floor, falling at 0, 1 or 2 m/s and tipping
// over at 1 rad/s about y; E 1e4 or 1e5, neo-Hookean or corotational, self-contact on: twelve
// cases, 2 s each). After every 1/60 s call, measured from outside the library (tests/physics/
// lfem_test_util.h, inside_itself): the boundary nodes inside the strip's own tets deeper than
// 0.02 of its mean boundary edge l and the deepest, and the deepest of 7 points on each of its
// sharp edges; printed for the worst call and the last. A minute or two a case on one core: built
// and run on demand (cmake --build build --target bench_strip_cases), not by ctest or the
// default build. It fails (exit 1) when a node is left inside at the end.
#include <cstdio>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

class StripCases : public ::testing::TestWithParam<std::tuple<lfem_model, double, double>> {};

TEST_P(StripCases, Falls) {
    const auto [model, young, v0] = GetParam();
    World w;
    add_plane_floor(w);
    Mesh strip;
    make_box_mesh(strip, 0.01, 0.06, 0.6, 2, 6, 60, -0.005, -0.03, 0.002);
    lfem_body_def d = soft_def(model, young, 0.3, 2, 0.5, true);
    d.linear_velocity[2] = -v0;
    d.angular_velocity[1] = 1.0;
    const lfem_body b = add_body(w, d, strip);
    const std::vector<std::array<uint32_t, 2>> edges = sharp_edges(body_shape(w, b, strip));
    Inside worst, end;
    for (int call = 0; call < 120; ++call) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60.0), LFEM_OK) << lfem_last_error();
        end = inside_itself(w, b, strip, edges);
        worst.count = std::max(worst.count, end.count);
        worst.deepest = std::max(worst.deepest, end.deepest), worst.deepest_edge = std::max(worst.deepest_edge, end.deepest_edge);
    }
    std::printf("strip 60 cm, %-12s E %.0e, %.0f m/s: nodes inside at worst %d (deepest %.3f l), at the end %d "
                "(%.3f l); sharp edges at worst %.3f l, at the end %.3f l\n",
                model_name(model), young, v0, worst.count, worst.deepest, end.count, end.deepest, worst.deepest_edge,
                end.deepest_edge);
    EXPECT_EQ(end.count, 0);
}

INSTANTIATE_TEST_SUITE_P(Twelve, StripCases,
                         ::testing::Combine(::testing::Values(LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_COROTATIONAL),
                                            ::testing::Values(1e4, 1e5), ::testing::Values(0.0, 1.0, 2.0)));

}  // namespace
