// The explicit step stays inside its stability limit: automatic sub-stepping keeps any call
// bounded; a fixed step above the limit is refused up front; forced through anyway, the blow-up
// is caught and the world rolled back bit for bit.
#include <cmath>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// quadratic: of 10-node tets, on half the cells along each edge.
lfem_body soft_block(lfem_world* w, Mesh& mesh, bool quadratic = false) {
    if (quadratic)
        make_quadratic_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
    else
        make_box_mesh(mesh, 0.2, 0.1, 0.1, 8, 4, 4);
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    def.young_modulus = 1e6;
    def.linear_velocity[0] = 0.5;
    def.angular_velocity[1] = 3.0;
    return add_body(w, def, mesh);
}

}  // namespace

TEST(Stability, AutomaticStepSubstepsALargeDtAndStaysBounded) {
    World w;
    Mesh mesh;
    const lfem_body b = soft_block(w, mesh);
    const double limit = stable_step(w);
    ASSERT_TRUE(std::isfinite(limit) && limit > 0);
    // One call 100 times the stable step: at least 100 / 0.9 sub-steps, energy within what
    // gravity supplied.
    ASSERT_EQ(lfem_world_step(w, 100 * limit), LFEM_OK) << lfem_last_error();
    const lfem_world_stats s = stats(w);
    EXPECT_GE(s.substeps_last_call, uint32_t(std::ceil(100 / 0.9)));
    EXPECT_LE(s.step_size, 0.9 * limit * (1 + 1e-12));
    // Energy balance: nothing is dissipated (no damping), so kinetic + strain = initial +
    // work of gravity up to the scheme's O(h^2) error; 1 % of the energy is a generous bound.
    const double scale = s.kinetic_energy + s.strain_energy;
    EXPECT_LT(std::fabs(s.energy_error), 0.01 * scale);
    for (double x : positions(w, b)) ASSERT_TRUE(std::isfinite(x));
}

TEST(Stability, FixedStepAboveTheLimitIsRefusedUpFront) {
    World w;
    Mesh mesh;
    const lfem_body b = soft_block(w, mesh);
    const double limit = stable_step(w);
    ASSERT_EQ(lfem_world_set_time_step(w, 1.1 * limit), LFEM_OK);
    const auto before = fingerprint(w, {b});
    EXPECT_EQ(lfem_world_step(w, 0.01), LFEM_INVALID_ARGUMENT);
    const std::string message = lfem_last_error();
    EXPECT_NE(message.find("stable limit"), std::string::npos) << message;
    char limit_text[64];
    std::snprintf(limit_text, sizeof limit_text, "%.6g s", limit);
    EXPECT_NE(message.find(limit_text), std::string::npos) << message << " should name " << limit_text;
    EXPECT_EQ(before, fingerprint(w, {b}));
}

TEST(Stability, TheLimitIsTight) {
    // A fixed step at 0.95 of the estimated limit runs for 3000 steps; at 1.1 it blows up. So
    // the estimate is within 10 % of the true critical step, not merely safe. The same for a
    // block of 10-node tets: the estimate works on any element's operator.
    for (bool quadratic : {false, true})
    for (double factor : {0.95, 1.1}) {
        lfem_world_def wd = lfem_world_def_default();
        wd.allow_unstable_step = 1;
        World w(wd);
        Mesh mesh;
        soft_block(w, mesh, quadratic);
        const double limit = stable_step(w);
        ASSERT_EQ(lfem_world_set_time_step(w, factor * limit), LFEM_OK);
        lfem_status status = LFEM_OK;
        for (int call = 0; call < 300 && status == LFEM_OK; ++call)
            status = lfem_world_step(w, 10 * factor * limit);
        if (factor < 1)
            EXPECT_EQ(status, LFEM_OK) << "factor " << factor << (quadratic ? ", 10-node" : "") << ": "
                                       << lfem_last_error();
        else
            EXPECT_EQ(status, LFEM_UNSTABLE) << "factor " << factor << (quadratic ? ", 10-node" : "");
    }
}

TEST(Stability, BlowUpAtOneAndAHalfTheLimitIsCaughtAndRolledBackBitwise) {
    lfem_world_def wd = lfem_world_def_default();
    wd.allow_unstable_step = 1;  // skip the up-front refusal
    World w(wd);
    Mesh mesh;
    const lfem_body b = soft_block(w, mesh);
    const double limit = stable_step(w);
    ASSERT_EQ(lfem_world_set_time_step(w, 1.5 * limit), LFEM_OK);
    lfem_status status = LFEM_OK;
    std::vector<unsigned char> before;
    int calls = 0;
    while (status == LFEM_OK && calls < 100) {
        before = fingerprint(w, {b});
        status = lfem_world_step(w, 5 * 1.5 * limit);
        ++calls;
    }
    ASSERT_EQ(status, LFEM_UNSTABLE) << "no blow-up was detected in " << calls << " calls";
    EXPECT_NE(std::string(lfem_last_error()).find("rolled back"), std::string::npos);
    EXPECT_EQ(before, fingerprint(w, {b})) << "the failed call changed the world";
    for (double x : positions(w, b)) ASSERT_TRUE(std::isfinite(x));
    std::printf("blow-up at 1.5x the limit caught on call %d, world restored bitwise\n", calls);
}
