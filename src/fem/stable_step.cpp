#include "fem/stable_step.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Eigenvalues>

#include "common/thread_pool.h"
#include "fem/internal_forces.h"
#include "fem/lumped_mass.h"
#include "fem/composite_tet.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// The stiffness of tet e at rest, as blocks K_ab = sum_q V_q (lambda g_a g_b^T + mu g_b g_a^T +
// mu (g_a . g_b) I), g = grad N at quadrature point q: one point for a linear tet (g the rows of
// Dm^-1, node 0 minus their sum), four for a 10-node one (g = J_q^-T dN_a/dxi).
struct ElementStiffness {
    int nodes = 0;
    Mat3 K[kQuadraticTetNodes * kQuadraticTetNodes];  // K[nodes * a + b]
};

ElementStiffness element_stiffness(const ElementMesh& ref, const Lame& lame, uint32_t e) {
    ElementStiffness s;
    const bool quadratic = ref.nodes_per_tet == kQuadraticTetNodes;
    const QuadraticGradients& table = element_gradients(ref.composite);
    s.nodes = quadratic ? int(kQuadraticTetNodes) : 4;
    for (int q = 0; q < (quadratic ? kQuadraturePoints : 1); ++q) {
        Vec3 g[kQuadraticTetNodes];
        double V = ref.volume[e];
        if (quadratic) {
            const std::size_t k = kQuadraturePoints * std::size_t(e) + q;
            const Eigen::Map<const Mat3> Jq_inv(&ref.Dm_inv[9 * k]);
            for (uint32_t a = 0; a < kQuadraticTetNodes; ++a) g[a] = Jq_inv.transpose() * Vec3(table.g[q][a]);
            V = ref.qp_volume[k];
        } else {
            const Eigen::Map<const Mat3> Dm_inv(&ref.Dm_inv[9 * e]);
            for (int a = 1; a < 4; ++a) g[a] = Dm_inv.row(a - 1).transpose();
            g[0] = -(g[1] + g[2] + g[3]);
        }
        for (int a = 0; a < s.nodes; ++a)
            for (int b = 0; b < s.nodes; ++b) {
                const Mat3 Kq = V * (lame.lambda * g[a] * g[b].transpose() + lame.mu * g[b] * g[a].transpose() +
                                     lame.mu * g[a].dot(g[b]) * Mat3::Identity());
                s.K[s.nodes * a + b] = q == 0 ? Kq : Mat3(s.K[s.nodes * a + b] + Kq);
            }
    }
    return s;
}

// The absolute row sums of tet e's stiffness: visit(a, r, s) with s = sum_j |K_(3a+r) j| over
// the block K_ab, for b in order.
template <class Visit>
void for_each_row_sum(const ElementMesh& ref, const Lame& lame, uint32_t e, const Visit& visit) {
    const ElementStiffness s = element_stiffness(ref, lame, e);
    for (int a = 0; a < s.nodes; ++a)
        for (int b = 0; b < s.nodes; ++b)
            for (int r = 0; r < 3; ++r) visit(a, r, s.K[s.nodes * a + b].row(r).cwiseAbs().sum());
}

// Gershgorin: every eigenvalue of M^-1 K lies below max over rows of sum_j |K_ij| / m_i;
// summing |K_e| entries per row over-counts cancellations, so the bound is safe.
double gershgorin_bound(const ElementMesh& ref, const Lame& lame) {
    std::vector<double> row_sum(3 * ref.node_count(), 0.0);
    for (uint32_t e = 0; e < ref.tet_count(); ++e) {
        const uint32_t* t = &ref.tets[std::size_t(ref.nodes_per_tet) * e];
        for_each_row_sum(ref, lame, e, [&](int a, int r, double s) { row_sum[3 * t[a] + r] += s; });
    }
    double bound = 0.0;
    for (uint32_t i = 0; i < ref.node_count(); ++i)
        for (int r = 0; r < 3; ++r) bound = std::max(bound, row_sum[3 * i + r] / ref.mass[i]);
    return bound;
}

// The largest eigenvalue of a symmetric matrix. One dynamic-size solver serves the element
// matrices (12 x 12, 30 x 30, built only at set-up) and the Lanczos tridiagonal matrix: the
// fixed-size solvers compiled to much more code (the 30 x 30 one alone took a quarter of the
// library's build time) for no gain at set-up.
double largest_eigenvalue(const Eigen::MatrixXd& A) {
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
}

// The largest eigenvalue of tet e's M_e^-1 K_e at rest, M_e its lumped shares (share[a] at its
// node a): of K_e over the equal share for a linear tet (12 x 12), of M_e^-1/2 K_e M_e^-1/2 for a
// 10-node one (30 x 30).
double element_frequency2(const ElementMesh& ref, const Lame& lame, uint32_t e, const double* share) {
    const ElementStiffness s = element_stiffness(ref, lame, e);
    const bool linear = s.nodes == 4;
    Eigen::MatrixXd A(3 * s.nodes, 3 * s.nodes);
    for (int a = 0; a < s.nodes; ++a)
        for (int b = 0; b < s.nodes; ++b) {
            const double scale = linear ? 1.0 : 1.0 / std::sqrt(share[a] * share[b]);
            A.block<3, 3>(3 * a, 3 * b) = scale * s.K[s.nodes * a + b];
        }
    return linear ? largest_eigenvalue(A) / share[0] : largest_eigenvalue(A);
}

}  // namespace

double add_scaling_mass(const ElementMesh& ref, const Lame& lame, double density, double omega_target, double* added) {
    double total = 0.0;
    const double target2 = omega_target * omega_target;
    const uint32_t nodes = ref.nodes_per_tet;
    for (uint32_t e = 0; e < ref.tet_count(); ++e) {
        // The tet's own lumped shares at its nodes (rho V / 4 each for a linear tet). Its
        // Gershgorin bound is cheap and at least its eigenvalue: only where it exceeds the
        // target is the eigenvalue needed.
        double share[kQuadraticTetNodes];
        for (uint32_t a = 0; a < nodes; ++a)
            share[a] = nodes == 4 ? density * ref.volume[e] / 4.0 : density * ref.volume[e] * lumped_share(nodes, a);
        double rows[kQuadraticTetNodes][3] = {};
        for_each_row_sum(ref, lame, e, [&](int a, int r, double s) { rows[a][r] += s; });
        double gershgorin = 0.0;
        for (uint32_t a = 0; a < nodes; ++a)
            for (double s : rows[a]) gershgorin = std::max(gershgorin, s / share[a]);
        if (!(gershgorin > target2)) continue;
        const double bound = element_frequency2(ref, lame, e, share);
        if (!(bound > target2)) continue;
        // Its density times bound / target2: its own highest frequency becomes the target.
        const uint32_t* t = &ref.tets[std::size_t(nodes) * e];
        if (nodes == 4) {
            const double extra = (bound / target2 - 1.0) * share[0];
            for (int a = 0; a < 4; ++a) added[t[a]] += extra;
            total += 4.0 * extra;
            continue;
        }
        for (uint32_t a = 0; a < nodes; ++a) {
            const double extra = (bound / target2 - 1.0) * share[a];
            added[t[a]] += extra;
            total += extra;
        }
    }
    return total;
}

StableStepEstimate scale_masses_for_step(const ElementMesh& mesh, const Lame& lame, double density,
                                         double omega_target, double* scaled, ThreadPool* pool) {
    const std::size_t n = mesh.node_count();
    std::vector<double> trial(n);
    ElementMesh with_trial = mesh;
    with_trial.mass = Span<const double>(trial.data(), n);
    const auto attempt = [&](double theta) {
        std::copy(mesh.mass.begin(), mesh.mass.end(), trial.begin());
        add_scaling_mass(mesh, lame, density, theta, trial.data());
        return estimate_stable_step(with_trial, lame, pool);
    };
    // The proven target: the estimate adds at most a 2 % margin on omega^2 to a true value.
    double good = omega_target / std::sqrt(1.02), bad = HUGE_VAL;
    StableStepEstimate best = attempt(good);
    std::copy(trial.begin(), trial.end(), scaled);
    for (int i = 0; i < 4 && best.omega_max < 0.99 * omega_target; ++i) {
        // The element target grows in proportion to the slack (secant), or halfway towards
        // the last one that overshot.
        const double theta = std::isfinite(bad) ? 0.5 * (good + bad) : good * omega_target / best.omega_max;
        const StableStepEstimate e = attempt(theta);
        if (e.omega_max <= omega_target) {
            good = theta, best = e;
            std::copy(trial.begin(), trial.end(), scaled);
        } else {
            bad = theta;
        }
    }
    return best;
}

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
            ritz = largest_eigenvalue(T);
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
