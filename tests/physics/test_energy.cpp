// Undamped free vibration: with no gravity, damping or contact, kinetic + strain energy is a
// constant of the motion. Central differences conserve a nearby "shadow" energy, so the
// measured total only oscillates, by O((omega h)^2) of the energy in the fastest modes.
#include <cmath>
#include <tuple>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

// (model, 10-node tets)
class FreeVibration : public ::testing::TestWithParam<std::tuple<lfem_model, bool>> {};

TEST_P(FreeVibration, TotalEnergyKeptOver1000Steps) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh mesh;
    // A slender bar (0.6 m, 18 cells along): its torsion and axial modes have omega h ~ 0.08 at
    // the automatic step, so the scheme's oscillation of the measured energy, about
    // (omega h)^2 / 4, is ~0.2 %. (A bar half as long doubled omega h and reached 0.8 %.)
    const lfem_model model = std::get<0>(GetParam());
    const bool quadratic = std::get<1>(GetParam());
    if (quadratic)  // as many nodes along: a node every 1/36 of the bar
        make_quadratic_box_mesh(mesh, 0.1, 0.1, 0.6, 1, 1, 18, -0.05, -0.05, 0.0);
    else
        make_box_mesh(mesh, 0.1, 0.1, 0.6, 3, 3, 18, -0.05, -0.05, 0.0);
    lfem_body_def def = lfem_body_def_default();
    def.model = model;
    def.young_modulus = 1e6;
    def.poisson_ratio = 0.3;
    const lfem_body b = add_body(w, def, mesh);
    // A twist growing along z plus a stretch: a mix of torsion and axial modes, about 1 %
    // strain at the peak, no net momentum.
    const std::vector<double> x = positions(w, b);
    std::vector<double> v(x.size());
    for (size_t i = 0; i < x.size() / 3; ++i) {
        const double z = x[3 * i + 2] / 0.6;
        v[3 * i + 0] = -1.0 * x[3 * i + 1] * (z - 0.5);
        v[3 * i + 1] = 1.0 * x[3 * i + 0] * (z - 0.5);
        v[3 * i + 2] = 0.05 * (z - 0.5);
    }
    ASSERT_EQ(lfem_body_set_velocities(w, b, v.data(), uint32_t(x.size() / 3)), LFEM_OK);
    const lfem_world_stats s0 = stats(w);
    const double E0 = s0.kinetic_energy + s0.strain_energy;
    ASSERT_GT(E0, 0);
    const double h = 0.9 * stable_step(w);
    double worst = 0, strain_peak = 0;
    for (int step = 0; step < 1000; ++step) {
        ASSERT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
        const lfem_world_stats s = stats(w);
        worst = std::fmax(worst, std::fabs(s.kinetic_energy + s.strain_energy - E0) / E0);
        strain_peak = std::fmax(strain_peak, s.strain_energy);
    }
    std::printf("free vibration (model %d, %s tets): largest relative energy change %.3g over 1000 steps "
                "(strain energy reached %.0f %% of the total)\n",
                int(model), quadratic ? "10-node" : "4-node", worst, 100 * strain_peak / E0);
    // The motion really exchanges energy between kinetic and strain forms.
    EXPECT_GT(strain_peak, 0.2 * E0);
    EXPECT_LT(worst, 0.005);  // the 0.5 %
}

INSTANTIATE_TEST_SUITE_P(Models, FreeVibration,
                         ::testing::Combine(::testing::Values(LFEM_MODEL_PAPER, LFEM_MODEL_COROTATIONAL,
                                                              LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_LINEAR),
                                            ::testing::Bool()));
