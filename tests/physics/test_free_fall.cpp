// Free fall: with no deformation the central difference scheme integrates a constant
// acceleration exactly, so every node follows x0 + v0 t + g t^2/2 to round-off.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

class FreeFall : public ::testing::TestWithParam<lfem_model> {};

TEST_P(FreeFall, MatchesClosedFormToRoundOff) {
    World w;
    Mesh mesh;
    make_box_mesh(mesh, 0.1, 0.1, 0.1, 2, 2, 2);
    lfem_body_def def = lfem_body_def_default();
    def.model = GetParam();
    def.young_modulus = 1e5;
    def.linear_velocity[0] = 1.0;
    def.linear_velocity[2] = 2.0;
    const lfem_body b = add_body(w, def, mesh);
    const std::vector<double> x0 = positions(w, b);

    // Calls of different length, so sub-step sizes change between calls.
    double t = 0;
    for (int call = 0; call < 60; ++call) {
        const double dt = (call % 3 == 0) ? 0.004 : 0.0123;
        ASSERT_EQ(lfem_world_step(w, dt), LFEM_OK) << lfem_last_error();
        t += dt;
    }
    const std::vector<double> x = positions(w, b), v = velocities(w, b);
    const double v0[3] = {1.0, 0.0, 2.0}, g[3] = {0.0, 0.0, -9.81};
    double worst_x = 0, worst_v = 0;
    for (size_t i = 0; i < x.size() / 3; ++i)
        for (int k = 0; k < 3; ++k) {
            const double exact = x0[3 * i + k] + v0[k] * t + 0.5 * g[k] * t * t;
            worst_x = std::fmax(worst_x, std::fabs(x[3 * i + k] - exact));
            worst_v = std::fmax(worst_v, std::fabs(v[3 * i + k] - (v0[k] + g[k] * t)));
        }
    // Round-off: positions of ~2 m carry ~4e-16 m of error per step over a few hundred steps,
    // and node differences over 0.05 m elements give strains of ~1e-14, whose forces move the
    // nodes by far less than 1e-10 m over the run. 1e-10 m (and 1e-9 m/s) is round-off level
    // against a fall of ~2 m, and far below any integration error (a first-order scheme would
    // be off by ~g h t / 2 ~ 1e-2 m).
    EXPECT_LT(worst_x, 1e-10);
    EXPECT_LT(worst_v, 1e-9);
    RecordProperty("max_position_error_m", std::to_string(worst_x));
    std::printf("free fall (%d): max position error %.3g m, velocity error %.3g m/s after %.3f s\n",
                int(GetParam()), worst_x, worst_v, t);
}

INSTANTIATE_TEST_SUITE_P(Models, FreeFall,
                         ::testing::Values(LFEM_MODEL_PAPER, LFEM_MODEL_COROTATIONAL,
                                           LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_LINEAR));
