#include "fem/internal_forces.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "fem/polar_rotation.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// The element loop shared by every model, parallel over the colours of element blocks (see
// element_colouring.h): the blocks of one colour share no node, so they scatter at once, and
// each node sums its contributions in the same order for any thread count. The strain energy
// is summed per block, then over the blocks in index order, for the same reason.
//
// `kernel(e, D, P)` receives tet e's edge matrix D (row-major, D[3r+k] = column k of
// [x1-x0, x2-x0, x3-x0] in row r; for the linear model the displacements' edges instead, which
// keep the digits that differences of positions would cancel away) and returns the first
// Piola-Kirchhoff stress P (row-major) and the energy density.
template <bool displacement_edges, class Kernel>
void element_loop(const Body& body, BodyState& state, ThreadPool* pool, const Kernel& kernel) {
    const BodyReference& ref = body.ref;
    const double* __restrict x = state.x.data();
    const double* __restrict X = ref.X.data();
    const uint32_t* __restrict tets = ref.tets.data();
    const double* __restrict Dm_inv = ref.Dm_inv.data();
    const double* __restrict volume = ref.volume.data();
    double* __restrict f = state.elastic.data();
    std::fill(state.elastic.begin(), state.elastic.end(), 0.0);
    const ElementColouring& colouring = ref.colouring;
    const uint32_t tet_count = ref.tet_count(), B = colouring.block_size;
    std::vector<double> block_energy(colouring.block_count(), 0.0);

    auto run_block = [&](uint32_t b) {
        double energy = 0.0;
        const uint32_t e1 = std::min(tet_count, (b + 1) * B);
        for (uint32_t e = b * B; e < e1; ++e) {
            const uint32_t* t = tets + 4 * e;
            const double* p0 = x + 3 * t[0];
            const double* p1 = x + 3 * t[1];
            const double* p2 = x + 3 * t[2];
            const double* p3 = x + 3 * t[3];
            double D[9];
            for (int r = 0; r < 3; ++r) {
                if (displacement_edges) {
                    const double u0 = p0[r] - X[3 * t[0] + r];
                    D[3 * r + 0] = (p1[r] - X[3 * t[1] + r]) - u0;
                    D[3 * r + 1] = (p2[r] - X[3 * t[2] + r]) - u0;
                    D[3 * r + 2] = (p3[r] - X[3 * t[3] + r]) - u0;
                } else {
                    D[3 * r + 0] = p1[r] - p0[r];
                    D[3 * r + 1] = p2[r] - p0[r];
                    D[3 * r + 2] = p3[r] - p0[r];
                }
            }
            // Gradient of the motion: D Dm^-1 (Dm_inv stored column-major: M[k][c] = m[k+3c]).
            const double* m = Dm_inv + 9 * e;
            double F[9];
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    F[3 * r + c] = D[3 * r] * m[3 * c] + D[3 * r + 1] * m[1 + 3 * c] +
                                   D[3 * r + 2] * m[2 + 3 * c];
            double P[9], psi;
            kernel(e, F, P, psi);
            const double V = volume[e];
            energy += V * psi;
            // f_int_a = V P grad N_a with grad N_a the rows of Dm^-1 (a = 1..3) and node 0
            // the negative sum; the elastic force is its negative.
            for (int r = 0; r < 3; ++r) {
                const double q0 = -V * P[3 * r], q1 = -V * P[3 * r + 1], q2 = -V * P[3 * r + 2];
                const double g1 = q0 * m[0] + q1 * m[3] + q2 * m[6];
                const double g2 = q0 * m[1] + q1 * m[4] + q2 * m[7];
                const double g3 = q0 * m[2] + q1 * m[5] + q2 * m[8];
                f[3 * t[1] + r] += g1;
                f[3 * t[2] + r] += g2;
                f[3 * t[3] + r] += g3;
                f[3 * t[0] + r] -= g1 + g2 + g3;
            }
        }
        block_energy[b] = energy;
    };
    for (uint32_t c = 0; c < colouring.colour_count(); ++c) {
        const uint32_t* blocks = colouring.blocks.data() + colouring.colour_start[c];
        parallel_for(pool, colouring.colour_start[c + 1] - colouring.colour_start[c],
                     [&](uint32_t i) { run_block(blocks[i]); });
    }
    double energy = 0.0;
    for (double e : block_energy) energy += e;
    state.strain_energy = energy;
}

// Small-strain (Hooke) stress of the symmetric part of H, row-major, and its energy density
// psi = mu eps:eps + lambda/2 tr(eps)^2 (as hooke_stress in tet_element.h).
inline void hooke(const double* H, const Lame& l, double* P, double& psi) {
    const double e00 = H[0], e11 = H[4], e22 = H[8];
    const double e01 = 0.5 * (H[1] + H[3]), e02 = 0.5 * (H[2] + H[6]), e12 = 0.5 * (H[5] + H[7]);
    const double tr = e00 + e11 + e22;
    psi = l.mu * (e00 * e00 + e11 * e11 + e22 * e22 + 2.0 * (e01 * e01 + e02 * e02 + e12 * e12)) +
          0.5 * l.lambda * tr * tr;
    const double two_mu = 2.0 * l.mu, lt = l.lambda * tr;
    P[0] = two_mu * e00 + lt, P[4] = two_mu * e11 + lt, P[8] = two_mu * e22 + lt;
    P[1] = P[3] = two_mu * e01;
    P[2] = P[6] = two_mu * e02;
    P[5] = P[7] = two_mu * e12;
}

// P = R hooke(R^T F - I): Hooke's law in a rotated frame (R row-major).
inline void rotated_hooke(const double* R, const double* F, const Lame& l, double* P, double& psi) {
    double H[9], S[9];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            H[3 * r + c] = R[r] * F[c] + R[3 + r] * F[3 + c] + R[6 + r] * F[6 + c] - (r == c);
    hooke(H, l, S, psi);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            P[3 * r + c] = R[3 * r] * S[c] + R[3 * r + 1] * S[3 + c] + R[3 * r + 2] * S[6 + c];
}

}  // namespace

void compute_elastic_forces(const Body& body, BodyState& state, ThreadPool* pool) {
    const Lame lame = body.lame;
    switch (body.def.model) {
        case LFEM_MODEL_LINEAR:
            element_loop<true>(body, state, pool, [&](uint32_t, const double* H, double* P, double& psi) {
                hooke(H, lame, P, psi);
            });
            break;
        case LFEM_MODEL_PAPER: {
            // Floating frame: strain measured in the body's rotated frame, R^T F - I; the
            // translation of the frame drops out because the gradients of N sum to zero.
            const Eigen::Quaterniond q(state.rotation[0], state.rotation[1], state.rotation[2],
                                       state.rotation[3]);
            const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Rm = q.toRotationMatrix();
            double R[9];
            for (int i = 0; i < 9; ++i) R[i] = Rm.data()[i];
            element_loop<false>(body, state, pool, [&](uint32_t, const double* F, double* P, double& psi) {
                rotated_hooke(R, F, lame, P, psi);
            });
            break;
        }
        case LFEM_MODEL_COROTATIONAL: {
            // One rotation per tet, the polar rotation of F (warm-started from the last step):
            // the stress R C:(R^T F - I) is torque-free for an isotropic material, so angular
            // momentum is kept.
            float* rotations = state.tet_rotation.data();
            element_loop<false>(body, state, pool, [&](uint32_t e, const double* F, double* P, double& psi) {
                double R[9];
                extract_rotation_fast(F, rotations + 4 * e, R);
                rotated_hooke(R, F, lame, P, psi);
            });
            break;
        }
        case LFEM_MODEL_NEO_HOOKEAN:
        default: {
            // Stable neo-Hookean (tet_element.h): P = mu F + (lambda' (J - 1) - mu) cof(F).
            const double mu = lame.mu, lam = lame.lambda + lame.mu;
            element_loop<false>(body, state, pool, [&](uint32_t, const double* F, double* P, double& psi) {
                // Columns of F: a = F(:,0), b = F(:,1), c = F(:,2); cof columns b x c, c x a, a x b.
                const double a0 = F[0], a1 = F[3], a2 = F[6];
                const double b0 = F[1], b1 = F[4], b2 = F[7];
                const double c0 = F[2], c1 = F[5], c2 = F[8];
                const double k00 = b1 * c2 - b2 * c1, k10 = b2 * c0 - b0 * c2, k20 = b0 * c1 - b1 * c0;
                const double k01 = c1 * a2 - c2 * a1, k11 = c2 * a0 - c0 * a2, k21 = c0 * a1 - c1 * a0;
                const double k02 = a1 * b2 - a2 * b1, k12 = a2 * b0 - a0 * b2, k22 = a0 * b1 - a1 * b0;
                const double J = a0 * k00 + a1 * k10 + a2 * k20;
                double sq = 0.0;
                for (int i = 0; i < 9; ++i) sq += F[i] * F[i];
                psi = 0.5 * mu * (sq - 3.0) - mu * (J - 1.0) + 0.5 * lam * (J - 1.0) * (J - 1.0);
                const double s = lam * (J - 1.0) - mu;
                P[0] = mu * F[0] + s * k00, P[1] = mu * F[1] + s * k01, P[2] = mu * F[2] + s * k02;
                P[3] = mu * F[3] + s * k10, P[4] = mu * F[4] + s * k11, P[5] = mu * F[5] + s * k12;
                P[6] = mu * F[6] + s * k20, P[7] = mu * F[7] + s * k21, P[8] = mu * F[8] + s * k22;
            });
            break;
        }
    }
}

void compute_von_mises(const Body& body, const BodyState& state, double* out) {
    const BodyReference& ref = body.ref;
    const double* x = state.x.data();
    const double* X = ref.X.data();
    const Eigen::Quaterniond q_body(state.rotation[0], state.rotation[1], state.rotation[2],
                                    state.rotation[3]);
    const Mat3 R_body = q_body.toRotationMatrix();
    for (uint32_t e = 0; e < ref.tet_count(); ++e) {
        const uint32_t* t = &ref.tets[4 * e];
        const Eigen::Map<const Mat3> Dm_inv(&ref.Dm_inv[9 * e]);
        const Mat3 F = edge_matrix(x + 3 * t[0], x + 3 * t[1], x + 3 * t[2], x + 3 * t[3]) * Dm_inv;
        Mat3 sigma;
        switch (body.def.model) {
            case LFEM_MODEL_LINEAR: {
                double u[4][3];
                for (int a = 0; a < 4; ++a)
                    for (int r = 0; r < 3; ++r) u[a][r] = x[3 * t[a] + r] - X[3 * t[a] + r];
                sigma = hooke_stress(edge_matrix(u[0], u[1], u[2], u[3]) * Dm_inv, body.lame,
                                     nullptr);
                break;
            }
            case LFEM_MODEL_PAPER:
                // Von Mises is invariant under rotation: the stress in the frame is enough.
                sigma = hooke_stress(R_body.transpose() * F - Mat3::Identity(), body.lame, nullptr);
                break;
            case LFEM_MODEL_COROTATIONAL: {
                const float* s = &state.tet_rotation[4 * e];
                Eigen::Quaterniond q(s[0], s[1], s[2], s[3]);
                q.normalize();
                extract_rotation(F, q);
                const Mat3 R = q.toRotationMatrix();
                sigma = hooke_stress(R.transpose() * F - Mat3::Identity(), body.lame, nullptr);
                break;
            }
            default: {
                // Cauchy stress P F^T / J; an inverted tet (J <= 0) reports its Kirchhoff
                // stress instead of dividing by a vanishing or negative volume ratio.
                const Mat3 P = neo_hookean_stress(F, body.lame, nullptr);
                const double J = F.determinant();
                sigma = P * F.transpose() / (J > 1e-6 ? J : 1.0);
                break;
            }
        }
        out[e] = von_mises(sigma);
    }
}

}  // namespace lfem
