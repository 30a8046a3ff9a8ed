#include "fem/stable_step.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Eigenvalues>

#include "common/thread_pool.h"
#include "fem/internal_forces.h"
#include "fem/quadratic_tet.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// The gradients g_a = grad N_a of tet e's nodes at its quadrature point q and the point's
// volume: for a linear tet one point, the rows of Dm^-1 (node 0 minus their sum) and V; for a
// quadratic one J_q^-T dN_a/dxi and w_q det J_q. Returns the number of nodes.
int point_gradients(const ElementMesh& ref, uint32_t e, int q, Vec3 g[kQuadraticTetNodes], double& V) {
    if (ref.nodes_per_tet == kQuadraticTetNodes) {
        const std::size_t k = kQuadraturePoints * std::size_t(e) + q;
        const Eigen::Map<const Mat3> Jq_inv(&ref.Dm_inv[9 * k]);
        for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
            g[a] = Jq_inv.transpose() * Vec3(kQuadraticGradients.g[q][a]);
        V = ref.qp_volume[k];
        return kQuadraticTetNodes;
    }
    const Eigen::Map<const Mat3> Dm_inv(&ref.Dm_inv[9 * e]);
    for (int a = 1; a < 4; ++a) g[a] = Dm_inv.row(a - 1).transpose();
    g[0] = -(g[1] + g[2] + g[3]);
    V = ref.volume[e];
    return 4;
}

// Gershgorin: every eigenvalue of M^-1 K lies below max over rows of sum_j |K_ij| / m_i. The
// element blocks are K_ab = sum_q V_q (lambda g_a g_b^T + mu g_b g_a^T + mu (g_a . g_b) I),
// g = grad N at quadrature point q (one point for a linear tet); summing |K_e| entries per row
// over-counts cancellations, so the bound is safe.
double gershgorin_bound(const ElementMesh& ref, const Lame& lame) {
    std::vector<double> row_sum(3 * ref.node_count(), 0.0);
    const int points = ref.nodes_per_tet == kQuadraticTetNodes ? kQuadraturePoints : 1;
    std::vector<Mat3> K(std::size_t(ref.nodes_per_tet) * ref.nodes_per_tet);
    for (uint32_t e = 0; e < ref.tet_count(); ++e) {
        const uint32_t* t = &ref.tets[std::size_t(ref.nodes_per_tet) * e];
        std::fill(K.begin(), K.end(), Mat3::Zero());
        int nodes = 0;
        for (int q = 0; q < points; ++q) {
            Vec3 g[kQuadraticTetNodes];
            double V = 0.0;
            nodes = point_gradients(ref, e, q, g, V);
            for (int a = 0; a < nodes; ++a)
                for (int b = 0; b < nodes; ++b)
                    K[nodes * a + b] += V * (lame.lambda * g[a] * g[b].transpose() + lame.mu * g[b] * g[a].transpose() +
                                             lame.mu * g[a].dot(g[b]) * Mat3::Identity());
        }
        for (int a = 0; a < nodes; ++a)
            for (int b = 0; b < nodes; ++b)
                for (int r = 0; r < 3; ++r) row_sum[3 * t[a] + r] += K[nodes * a + b].row(r).cwiseAbs().sum();
    }
    double bound = 0.0;
    for (uint32_t i = 0; i < ref.node_count(); ++i)
        for (int r = 0; r < 3; ++r) bound = std::max(bound, row_sum[3 * i + r] / ref.mass[i]);
    return bound;
}

}  // namespace

StableStepEstimate estimate_stable_step(const ElementMesh& ref, const Lame& lame, ThreadPool* pool) {
    StableStepEstimate out;
    const double lambda_g = gershgorin_bound(ref, lame);
    out.omega_gershgorin = std::sqrt(lambda_g);

    // Lanczos on the symmetric form A = M^-1/2 K M^-1/2 (same eigenvalues as M^-1 K), from a
    // fixed pseudo-random start so the answer is reproducible. The largest eigenvalue of the
    // tridiagonal matrix T_j (a Ritz value) approaches lambda_max from below, much faster than
    // plain power iteration when the top of the spectrum is clustered (a structured mesh has
    // many nearly equal highest modes: power iteration had not settled after 400 products).
    // No reorthogonalisation: its loss only adds copies of converged Ritz values, which do not
    // change the largest one.
    const std::size_t n = 3 * std::size_t(ref.node_count());
    std::vector<double> q(n), q_prev(n, 0.0), u(n), y(n), sqrt_mass(ref.node_count());
    for (uint32_t i = 0; i < ref.node_count(); ++i) sqrt_mass[i] = std::sqrt(ref.mass[i]);
    uint64_t seed = 0x9E3779B97F4A7C15ull;
    double norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        seed = seed * 6364136223846793005ull + 1442695040888963407ull;
        q[i] = double(seed >> 11) / double(1ull << 53) - 0.5;
        norm += q[i] * q[i];
    }
    norm = std::sqrt(norm);
    for (double& v : q) v /= norm;
    std::vector<double> alpha, beta;
    double ritz = 0.0, ritz_before = 0.0;
    constexpr int max_iterations = 300;
    for (int it = 0; it < max_iterations && n > 0; ++it) {
        for (std::size_t i = 0; i < n; ++i) u[i] = q[i] / sqrt_mass[i / 3];
        apply_reference_stiffness(ref, lame, u.data(), y.data(), pool);
        double a = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            y[i] /= sqrt_mass[i / 3];  // y = A q
            a += q[i] * y[i];
        }
        const double b_prev = beta.empty() ? 0.0 : beta.back();
        double b = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            y[i] -= a * q[i] + b_prev * q_prev[i];
            b += y[i] * y[i];
        }
        b = std::sqrt(b);
        alpha.push_back(a);
        out.iterations = it + 1;
        const bool exhausted = !(b > 1e-12 * std::fabs(a));  // an invariant subspace: exact
        if (it % 5 == 4 || exhausted || it + 1 == max_iterations) {
            const int k = int(alpha.size());
            Eigen::MatrixXd T = Eigen::MatrixXd::Zero(k, k);
            for (int j = 0; j < k; ++j) T(j, j) = alpha[j];
            for (int j = 0; j + 1 < k; ++j) T(j, j + 1) = T(j + 1, j) = beta[j];
            ritz = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(T, Eigen::EigenvaluesOnly)
                       .eigenvalues()
                       .maxCoeff();
            // Settled to 1e-6 over five products.
            if (exhausted || std::fabs(ritz - ritz_before) <= 1e-6 * ritz) break;
            ritz_before = ritz;
        }
        beta.push_back(b);
        q_prev.swap(q);
        for (std::size_t i = 0; i < n; ++i) q[i] = y[i] / b;
    }
    out.omega_power = std::sqrt(std::max(ritz, 0.0));
    // The Ritz value is a lower bound; 2 % margin covers what further iterations would add.
    // Never above the proven Gershgorin bound.
    const double lambda_used = std::min(ritz * 1.02, lambda_g);
    out.omega_max = std::sqrt(lambda_used);
    return out;
}

}  // namespace lfem
