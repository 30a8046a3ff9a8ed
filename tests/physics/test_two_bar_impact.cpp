// Two-bar impact, the paper's Fig. 3: steel bars of 0.254 m, sections 0.0254 x 0.0254 and
// 0.0254 x 0.0224 m, approaching at 5.1359 m/s each across a gap of 2.54e-4 m. With nu = 0 the
// 1-D wave solution is the limit of the 3-D model (src/DESIGN.md section 11):
//   c = sqrt(E/rho) = 5134.85 m/s; contact from 24.73 us for 2L/c = 98.93 us;
//   plateau F = Z1 Z2/(Z1 + Z2) * 2v = 125.08 kN (Z = rho c A); impulse 12.375 N s;
//   final velocities -4.491 and +5.781 m/s.
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

constexpr double L = 0.254, b = 0.0254, h1 = 0.0254, h2 = 0.0224, gap = 2.54e-4;
constexpr double v0 = 5.1359, rho = 7844.0, E = 206.82e9;

struct Impact {
    double impulse_forces = 0;   // N s, contact forces summed over time (on bar 2)
    double impulse_momentum = 0; // N s, bar 2's momentum change
    double impulse_bar1 = 0;     // N s, minus bar 1's momentum change
    double plateau = 0;          // N, mean force over 40 to 110 us
    double duration = 0;         // s
    double v1 = 0, v2 = 0;       // m/s, final mean velocities
    double momentum_drift = 0;   // relative to m1 v0 + m2 v0
    double max_penetration = 0;  // m, over every step
    double energy_change = 0;    // relative
};

// kind: 0 = 4-node tets, 1 = 10-node tets, 2 = 10-node composite tets.
Impact run(uint32_t nx, uint32_t ny, double nu, int kind = 0) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh m1, m2;
    make_box_mesh(m1, L, b, h1, nx, ny, ny, -L - gap / 2, -b / 2, -h1 / 2);
    make_box_mesh(m2, L, b, h2, nx, ny, ny, gap / 2, -b / 2, -h2 / 2);
    if (kind > 0) {
        for (Mesh* m : {&m1, &m2}) {
            EXPECT_EQ(lfem_mesh_make_quadratic(m->m), LFEM_OK);
        }
    }
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_PAPER;
    def.young_modulus = E;
    def.poisson_ratio = nu;
    def.density = rho;
    def.friction = 0.0;
    def.linear_velocity[0] = v0;
    def.composite_tets = kind == 2;
    const lfem_body bar1 = add_body(w, def, m1);
    def.linear_velocity[0] = -v0;
    const lfem_body bar2 = add_body(w, def, m2);
    double mass1 = 0, mass2 = 0, P1[3], P2[3], P10[3], P20[3];
    lfem_body_get_mass(w, bar1, &mass1);
    lfem_body_get_mass(w, bar2, &mass2);
    lfem_body_get_momentum(w, bar1, P10, nullptr);
    lfem_body_get_momentum(w, bar2, P20, nullptr);
    const lfem_world_stats s0 = stats(w);

    Impact r;
    const double h = 0.9 * stable_step(w);
    double first = -1, last = -1, plateau_sum = 0, plateau_time = 0;
    std::vector<lfem_contact> contacts;
    while (stats(w).time < 200e-6) {
        EXPECT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
        const lfem_world_stats s = stats(w);
        r.max_penetration = std::fmax(r.max_penetration, s.max_penetration);
        uint32_t count = 0;
        lfem_world_query_contacts(w, nullptr, 0, &count);
        contacts.resize(count);
        EXPECT_EQ(lfem_world_query_contacts(w, contacts.data(), count, &count), LFEM_OK);
        double force = 0;  // on bar 2, along +x
        for (const lfem_contact& c : contacts)
            force += (c.body_a.index == bar2.index ? 1.0 : -1.0) * c.force[0];
        // The force of a step acts over that step (forward increment: lambda^n h is the
        // impulse between x^n and x^{n+1}); its interval is [t - h, t].
        r.impulse_forces += force * h;
        if (force > 0) {
            if (first < 0) first = s.time - h;
            last = s.time;
        }
        if (s.time - h >= 40e-6 && s.time <= 110e-6) plateau_sum += force * h, plateau_time += h;
    }
    lfem_body_get_momentum(w, bar1, P1, nullptr);
    lfem_body_get_momentum(w, bar2, P2, nullptr);
    r.impulse_momentum = P2[0] - P20[0];
    r.impulse_bar1 = P10[0] - P1[0];
    r.plateau = plateau_sum / plateau_time;
    r.duration = last - first;
    r.v1 = P1[0] / mass1;
    r.v2 = P2[0] / mass2;
    r.momentum_drift = std::fabs(P1[0] + P2[0] - P10[0] - P20[0]) / ((mass1 + mass2) * v0);
    const lfem_world_stats s = stats(w);
    r.energy_change = (s.kinetic_energy + s.strain_energy) / (s0.kinetic_energy + s0.strain_energy) - 1;
    std::printf("two bars %ux%ux%u%s nu=%.1f: impulse %.5f N s (%+.2f %%), momentum %.5f / %.5f, plateau "
                "%.2f kN (%+.2f %%), duration %.2f us (%+.2f %%), v1 %.4f v2 %.4f m/s, momentum drift "
                "%.1e, max penetration %.2e m, energy %+.2f %%\n",
                nx, ny, ny, kind == 2 ? " composite" : kind == 1 ? " 10-node" : "", nu, r.impulse_forces, 100 * (r.impulse_forces / 12.375 - 1), r.impulse_momentum,
                r.impulse_bar1, r.plateau / 1e3, 100 * (r.plateau / 125.08e3 - 1), r.duration * 1e6,
                100 * (r.duration / 98.93e-6 - 1), r.v1, r.v2, r.momentum_drift, r.max_penetration,
                100 * r.energy_change);
    return r;
}

}  // namespace

TEST(TwoBarImpact, MatchesTheOneDimensionalWaveSolution) {
    const Impact r = run(40, 4, 0.0);
    // Tolerances: the issue's. Mesh dispersion rounds the force's rise and fall over a few
    // elements (40 along each bar), which costs ~1 % of impulse at this resolution.
    EXPECT_NEAR(r.impulse_forces, 12.375, 0.02 * 12.375);
    // Forces and momenta are the same multipliers seen twice: equal to round-off.
    EXPECT_NEAR(r.impulse_forces, r.impulse_momentum, 1e-9 * 12.375);
    EXPECT_NEAR(r.impulse_forces, r.impulse_bar1, 1e-9 * 12.375);
    EXPECT_NEAR(r.plateau, 125.08e3, 0.01 * 125.08e3);
    EXPECT_NEAR(r.duration, 98.93e-6, 0.03 * 98.93e-6);
    EXPECT_NEAR(r.v1, -4.491, 0.03 * 4.491);
    EXPECT_NEAR(r.v2, 5.781, 0.03 * 5.781);
    EXPECT_LT(r.momentum_drift, 1e-10);
    EXPECT_LT(r.max_penetration, 1e-7);
    // A frictionless impact never creates energy (the method's impact loss is O(h)).
    EXPECT_LE(r.energy_change, 1e-9);
}

TEST(TwoBarImpact, ImpulseErrorShrinksWithRefinement) {
    const double coarse = std::fabs(run(20, 2, 0.0).impulse_forces / 12.375 - 1);
    const double fine = std::fabs(run(80, 4, 0.0).impulse_forces / 12.375 - 1);
    EXPECT_LT(fine, coarse);
}

TEST(TwoBarImpact, PoissonRatioPointThreeStaysWithinTwoAndAHalfPercent) {
    // With nu = 0.3 lateral inertia makes the 3-D bar converge about 1.9 % below the 1-D
    // impulse (src/DESIGN.md section 11); the bound is 2.5 %.
    const Impact r = run(40, 4, 0.3);
    EXPECT_NEAR(r.impulse_forces, 12.375, 0.025 * 12.375);
    EXPECT_LT(r.max_penetration, 1e-7);
}

// 10-node tets with the quadratic shape functions load a section's corners against its
// mid-edge nodes and lose 2.3 % of the impulse on one cell across however fine along (README,
// known issues). The composite element loads them as it lumps them, so the bars' impulse
// converges as with 4-node tets: on 20 and 40 cells along it lies within 25 % of the error of
// 4-node tets of the same node spacing (40 and 80 cells; the error is set by that spacing, the
// force's rounding by mesh dispersion and the O(h) impact loss, which the two elements share
// only to leading order), and it shrinks with refinement at least as O(h) allows (to below
// 0.65 of the coarser's: 0.5 for O(h), with room for the leading order's share).
TEST(TwoBarImpact, CompositeTetsCarryThePlaneWaveAsLinearTetsDo) {
    double previous = 0;
    for (uint32_t nx : {20u, 40u}) {
        const Impact composite = run(nx, 1, 0.0, 2), linear = run(2 * nx, 1, 0.0, 0);
        const double error = std::fabs(composite.impulse_forces / 12.375 - 1);
        EXPECT_LT(error, 1.25 * std::fabs(linear.impulse_forces / 12.375 - 1)) << nx;
        if (previous > 0) {
            EXPECT_LT(error, 0.65 * previous);
        }
        previous = error;
        // Against the 1-D solution itself: the 2 % the 4-node tets are held to at 40 cells along
        // (mesh dispersion), which the default 10-node tets, at -2.4 % on any mesh, miss.
        EXPECT_NEAR(composite.impulse_forces, 12.375, 0.02 * 12.375);
        EXPECT_NEAR(composite.plateau, 125.08e3, 0.01 * 125.08e3);  // as for 4-node tets
        EXPECT_NEAR(composite.impulse_forces, composite.impulse_momentum, 1e-9 * 12.375);
        EXPECT_LT(composite.momentum_drift, 1e-10);
        EXPECT_LT(composite.max_penetration, 1e-7);
        EXPECT_LE(composite.energy_change, 1e-9);
    }
}
