#include "fem/stable_step.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fem/internal_forces.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// Gershgorin: every eigenvalue of M^-1 K lies below max over rows of sum_j |K_ij| / m_i. The
// element blocks are K_ab = V (lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I), g = grad N;
// summing |K_e| entries per row over-counts cancellations, so the bound is safe.
double gershgorin_bound(const BodyReference& ref, const Lame& lame) {
    std::vector<double> row_sum(3 * ref.node_count(), 0.0);
    for (uint32_t e = 0; e < ref.tet_count(); ++e) {
        const uint32_t* t = &ref.tets[4 * e];
        const Eigen::Map<const Mat3> Dm_inv(&ref.Dm_inv[9 * e]);
        Vec3 g[4];
        for (int a = 1; a < 4; ++a) g[a] = Dm_inv.row(a - 1).transpose();
        g[0] = -(g[1] + g[2] + g[3]);
        const double V = ref.volume[e];
        for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 4; ++b) {
                const Mat3 K = V * (lame.lambda * g[a] * g[b].transpose() +
                                    lame.mu * g[b] * g[a].transpose() +
                                    lame.mu * g[a].dot(g[b]) * Mat3::Identity());
                for (int r = 0; r < 3; ++r) row_sum[3 * t[a] + r] += K.row(r).cwiseAbs().sum();
            }
    }
    double bound = 0.0;
    for (uint32_t i = 0; i < ref.node_count(); ++i)
        for (int r = 0; r < 3; ++r) bound = std::max(bound, row_sum[3 * i + r] / ref.mass[i]);
    return bound;
}

}  // namespace

StableStepEstimate estimate_stable_step(const BodyReference& ref, const Lame& lame, ThreadPool* pool) {
    StableStepEstimate out;
    const double lambda_g = gershgorin_bound(ref, lame);
    out.omega_gershgorin = std::sqrt(lambda_g);

    // Power iteration on the symmetric form M^-1/2 K M^-1/2 (same eigenvalues as M^-1 K),
    // from a fixed pseudo-random start so the answer is reproducible. The Rayleigh quotient
    // approaches lambda_max from below.
    const std::size_t n = 3 * std::size_t(ref.node_count());
    std::vector<double> w(n), u(n), y(n);
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    for (std::size_t i = 0; i < n; ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        w[i] = double(seed >> 11) / double(1ull << 53) - 0.5;
    }
    double rq = 0.0, rq_before = 0.0;
    constexpr int max_iterations = 400;
    for (int it = 0; it < max_iterations; ++it) {
        double norm = 0.0;
        for (double v : w) norm += v * v;
        norm = std::sqrt(norm);
        if (!(norm > 0.0)) break;
        for (std::size_t i = 0; i < n; ++i) u[i] = w[i] / norm / std::sqrt(ref.mass[i / 3]);
        apply_reference_stiffness(ref, lame, u.data(), y.data(), pool);
        rq = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            w[i] = y[i] / std::sqrt(ref.mass[i / 3]);
            rq += w[i] * u[i] * std::sqrt(ref.mass[i / 3]);
        }
        out.iterations = it + 1;
        // Stop when the quotient has settled to 1e-6 over ten iterations.
        if (it % 10 == 9) {
            if (std::fabs(rq - rq_before) <= 1e-6 * rq) break;
            rq_before = rq;
        }
    }
    out.omega_power = std::sqrt(std::max(rq, 0.0));
    // The quotient is a lower bound; 2 % margin covers what the last iterations would add
    // (they move it by < 1e-6 relative, but clustered top eigenvalues converge slowly in the
    // vector, not the value). Never above the proven Gershgorin bound.
    const double lambda_used = std::min(rq * 1.02, lambda_g);
    out.omega_max = std::sqrt(lambda_used);
    return out;
}

}  // namespace lfem
