#include "fem/internal_forces.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "common/cpu_dispatch.h"
#include "fem/block_result.h"
#include "fem/neo_hookean_tangent.h"
#include "fem/polar_rotation.h"
#include "fem/quadratic_forces.h"
#include "fem/tet_element.h"
#include "fem/volume_barrier.h"

namespace lfem {
namespace {

// Tets are processed in batches of kLanes: every stage of the kernel is a loop over the lanes
// of one batch with the tets' numbers side by side (structure of arrays), which the compiler
// turns into SIMD instructions. The gather of node positions and the scatter of forces stay
// in tet order, so every node sums its contributions in the same order as a plain loop would.
constexpr int kLanes = 8;

struct Batch {
    int n;                    // live lanes (the rest are padding with zero volume)
    double D[9][kLanes];      // edge matrix, row-major
    double m[9][kLanes];      // Dm^-1, column-major as stored
    double V[kLanes];
    double F[9][kLanes];      // D Dm^-1
    double P[9][kLanes];      // first Piola-Kirchhoff stress, row-major
    double psi[kLanes];       // energy density
    double tangent[kLanes];   // neo-Hookean: the tangent estimate (neo_hookean_tangent.h)
    double J[kLanes];         // det F, the tet's volume ratio (<= 0: turned inside out)
};

// J = det F of every lane; with displacement edges the batch holds grad u, and F = I + grad u.
template <bool displacement_edges>
LFEM_INLINE void volume_ratios(Batch& b) {
    for (int l = 0; l < kLanes; ++l) {
        const double i = displacement_edges ? 1.0 : 0.0;
        const double f00 = b.F[0][l] + i, f11 = b.F[4][l] + i, f22 = b.F[8][l] + i;
        b.J[l] = f00 * (f11 * f22 - b.F[5][l] * b.F[7][l]) - b.F[1][l] * (b.F[3][l] * f22 - b.F[5][l] * b.F[6][l]) +
                 b.F[2][l] * (b.F[3][l] * b.F[7][l] - f11 * b.F[6][l]);
    }
}

// Gradient of the motion: F = D Dm^-1 (Dm_inv column-major: M[k][c] = m[k + 3c]).
LFEM_INLINE void deformation_gradient(Batch& b) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            for (int l = 0; l < kLanes; ++l)
                b.F[3 * r + c][l] = b.D[3 * r][l] * b.m[3 * c][l] + b.D[3 * r + 1][l] * b.m[1 + 3 * c][l] +
                                    b.D[3 * r + 2][l] * b.m[2 + 3 * c][l];
}

// Small-strain (Hooke) stress of sym(H) and psi = mu eps:eps + lambda/2 tr(eps)^2, one lane
// (as hooke_stress in tet_element.h). H and P row-major, indexed [component][lane].
LFEM_INLINE void hooke_lane(const double (*H)[kLanes], const Lame& lm, double (*P)[kLanes], double* psi, int l) {
    const double e00 = H[0][l], e11 = H[4][l], e22 = H[8][l];
    const double e01 = 0.5 * (H[1][l] + H[3][l]), e02 = 0.5 * (H[2][l] + H[6][l]),
                 e12 = 0.5 * (H[5][l] + H[7][l]);
    const double tr = e00 + e11 + e22;
    psi[l] = lm.mu * (e00 * e00 + e11 * e11 + e22 * e22 + 2.0 * (e01 * e01 + e02 * e02 + e12 * e12)) +
             0.5 * lm.lambda * tr * tr;
    const double two_mu = 2.0 * lm.mu, lt = lm.lambda * tr;
    P[0][l] = two_mu * e00 + lt, P[4][l] = two_mu * e11 + lt, P[8][l] = two_mu * e22 + lt;
    P[1][l] = P[3][l] = two_mu * e01;
    P[2][l] = P[6][l] = two_mu * e02;
    P[5][l] = P[7][l] = two_mu * e12;
}

// P = R hooke(R^T F - I) for one lane: Hooke's law in a rotated frame (R row-major).
LFEM_INLINE void rotated_hooke_lane(const double* R, const double (*F)[kLanes], const Lame& lm,
                               double (*P)[kLanes], double* psi, int l) {
    double H[9][kLanes], S[9][kLanes];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            H[3 * r + c][l] = R[r] * F[c][l] + R[3 + r] * F[3 + c][l] + R[6 + r] * F[6 + c][l] - (r == c);
    hooke_lane(H, lm, S, psi, l);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            P[3 * r + c][l] = R[3 * r] * S[c][l] + R[3 * r + 1] * S[3 + c][l] + R[3 * r + 2] * S[6 + c][l];
}

// Stable neo-Hookean (tet_element.h), one lane: P = mu F + (lambda' (J - 1) - mu) cof(F).
LFEM_INLINE void neo_hookean_lane(const double (*F)[kLanes], double mu, double lam, double (*P)[kLanes],
                             double* psi, int l) {
    // Columns of F: a, b, c; cofactor columns b x c, c x a, a x b.
    const double a0 = F[0][l], a1 = F[3][l], a2 = F[6][l];
    const double b0 = F[1][l], b1 = F[4][l], b2 = F[7][l];
    const double c0 = F[2][l], c1 = F[5][l], c2 = F[8][l];
    const double k00 = b1 * c2 - b2 * c1, k10 = b2 * c0 - b0 * c2, k20 = b0 * c1 - b1 * c0;
    const double k01 = c1 * a2 - c2 * a1, k11 = c2 * a0 - c0 * a2, k21 = c0 * a1 - c1 * a0;
    const double k02 = a1 * b2 - a2 * b1, k12 = a2 * b0 - a0 * b2, k22 = a0 * b1 - a1 * b0;
    const double J = a0 * k00 + a1 * k10 + a2 * k20;
    const double sq = a0 * a0 + a1 * a1 + a2 * a2 + b0 * b0 + b1 * b1 + b2 * b2 + c0 * c0 +
                      c1 * c1 + c2 * c2;
    double barrier, barrier_d1, barrier_d2;  // volume_barrier.h: only below J_b
    volume_barrier(J, lam, barrier, barrier_d1, barrier_d2);
    psi[l] = 0.5 * mu * (sq - 3.0) - mu * (J - 1.0) + 0.5 * lam * (J - 1.0) * (J - 1.0) + barrier;
    const double s = lam * (J - 1.0) - mu + barrier_d1;
    P[0][l] = mu * a0 + s * k00, P[1][l] = mu * b0 + s * k01, P[2][l] = mu * c0 + s * k02;
    P[3][l] = mu * a1 + s * k10, P[4][l] = mu * b1 + s * k11, P[5][l] = mu * c1 + s * k12;
    P[6][l] = mu * a2 + s * k20, P[7][l] = mu * b2 + s * k21, P[8][l] = mu * c2 + s * k22;
}

// What a material model computes per batch: P and psi from F (and the tets' indices).
// kTangent: the model also estimates each tet's tangent stiffness, whose largest value the
// loop keeps (the stable step follows it). kBarrier: the loop adds the volume barrier
// (volume_barrier.h) to P and psi, and keeps the largest stiffness it adds in tangent; the
// neo-Hookean energy has it inside, and the reference stiffness K (apply_reference_stiffness)
// is Hooke's law alone.
struct HookeModel {
    static constexpr bool kTangent = false, kBarrier = false;
    Lame lame;
    LFEM_INLINE void operator()(Batch& b, uint32_t) const {
        for (int l = 0; l < kLanes; ++l) hooke_lane(b.F, lame, b.P, b.psi, l);
    }
};
struct LinearModel : HookeModel {
    static constexpr bool kBarrier = true;
};
struct PaperModel {
    static constexpr bool kTangent = false, kBarrier = true;
    Lame lame;
    double R[9];  // the body's global rotation, row-major
    LFEM_INLINE void operator()(Batch& b, uint32_t) const {
        for (int l = 0; l < kLanes; ++l) rotated_hooke_lane(R, b.F, lame, b.P, b.psi, l);
    }
};
struct NeoHookeanModel {
    static constexpr bool kTangent = true, kBarrier = false;
    double mu, lam;
    LFEM_INLINE void operator()(Batch& b, uint32_t) const {
        for (int l = 0; l < kLanes; ++l) neo_hookean_lane(b.F, mu, lam, b.P, b.psi, l);
        // Here, where F is at hand, rather than in a pass of its own over the mesh.
        for (int l = 0; l < kLanes; ++l)
            b.tangent[l] = neo_hookean_tangent_estimate(b.F[0][l], b.F[3][l], b.F[6][l], b.F[1][l],
                                                        b.F[4][l], b.F[7][l], b.F[2][l], b.F[5][l],
                                                        b.F[8][l], mu, lam);
    }
};
struct CorotationalModel {
    static constexpr bool kTangent = false, kBarrier = true;
    Lame lame;
    float* rotations;  // 4 per tet, warm start, updated
    // The Newton step of extract_rotation_fast (polar_rotation.h), once, for every lane at the
    // same time; lanes that need more (a step above 1e-4 rad, or none possible) are redone by
    // the scalar function from their warm start. Then Hooke's law in each tet's frame.
    LFEM_INLINE void operator()(Batch& b, uint32_t e0) const {
        double q[4][kLanes], R[9][kLanes], angle2[kLanes];
        for (int l = 0; l < kLanes; ++l)
            for (int k = 0; k < 4; ++k)
                q[k][l] = l < b.n ? double(rotations[4 * std::size_t(e0 + l) + k]) : double(k == 0);
        for (int l = 0; l < kLanes; ++l) {
            double A[9], Rl[9];
            for (int i = 0; i < 9; ++i) A[i] = b.F[i][l];
            const double norm = 1.0 / std::sqrt(q[0][l] * q[0][l] + q[1][l] * q[1][l] +
                                                q[2][l] * q[2][l] + q[3][l] * q[3][l]);
            double w = q[0][l] * norm, x = q[1][l] * norm, y = q[2][l] * norm, z = q[3][l] * norm;
            // Lanes with an indefinite H (-1) are redone by the scalar code below.
            angle2[l] = polar_newton_step(A, w, x, y, z, false);
            q[0][l] = w, q[1][l] = x, q[2][l] = y, q[3][l] = z;
            rotation_matrix(w, x, y, z, Rl);
            for (int i = 0; i < 9; ++i) R[i][l] = Rl[i];
        }
        for (int l = 0; l < b.n; ++l) {
            float* stored = rotations + 4 * std::size_t(e0 + l);
            if (angle2[l] > 0.0 && angle2[l] < 1e-8) {
                for (int k = 0; k < 4; ++k) stored[k] = float(q[k][l]);
            } else {
                double A[9], Rl[9];
                for (int i = 0; i < 9; ++i) A[i] = b.F[i][l];
                extract_rotation_fast(A, stored, Rl);
                for (int i = 0; i < 9; ++i) R[i][l] = Rl[i];
            }
        }
        for (int l = 0; l < kLanes; ++l) {
            double Rl[9];
            for (int i = 0; i < 9; ++i) Rl[i] = R[i][l];
            rotated_hooke_lane(Rl, b.F, lame, b.P, b.psi, l);
        }
    }
};

// The volume barrier of every lane that is crushed below J_b (rare: a branch, not SIMD);
// tangent: the stiffness it adds, 0 in the others.
template <bool displacement_edges>
LFEM_INLINE void volume_barrier_lanes(Batch& b, const Lame& lame) {
    for (int l = 0; l < kLanes; ++l) {
        b.tangent[l] = 0.0;
        if (!(b.J[l] < kBarrierJ)) continue;
        double F[9], P[9];
        for (int i = 0; i < 9; ++i) F[i] = b.F[i][l] + (displacement_edges && i % 4 == 0 ? 1.0 : 0.0), P[i] = b.P[i][l];
        b.tangent[l] = add_volume_barrier(F, lame.lambda + lame.mu, P, b.psi[l]);
        for (int i = 0; i < 9; ++i) b.P[i][l] = P[i];
    }
}

struct LoopData {
    const double* x;
    const double* X;
    const uint32_t* tets;
    const double* Dm_inv;
    const double* volume;
    double* f;
    uint32_t tet_count;
    uint32_t block_size;
};

// One block of tets: gather, kernel, scatter; returns the block's strain energy, its inverted
// tets and smallest volume ratio (and, for a model with kTangent, its largest tangent
// estimate). The loop calls it through cpu_variant (common/cpu_dispatch.h): compiled for
// AVX-512, AVX2 and the baseline, chosen by the CPU. The results are bitwise the same on each:
// this file is built with -ffp-contract=off (no a*b+c fused into one rounding), so every
// variant rounds alike.
template <bool displacement_edges, class Model>
LFEM_INLINE BlockResult element_block(const LoopData& d, uint32_t block, const Model& model) {
    Batch b;
    BlockResult out;
    double energy = 0.0, worst = 0.0;
    const uint32_t e_end = std::min(d.tet_count, (block + 1) * d.block_size);
    for (uint32_t e0 = block * d.block_size; e0 < e_end; e0 += kLanes) {
        b.n = int(std::min<uint32_t>(kLanes, e_end - e0));
        for (int l = 0; l < kLanes; ++l) {
            if (l >= b.n) {  // padding lanes: an empty tet
                for (int i = 0; i < 9; ++i) b.D[i][l] = b.m[i][l] = 0.0;
                b.V[l] = 0.0;
                continue;
            }
            const uint32_t e = e0 + l;
            const uint32_t* t = d.tets + 4 * std::size_t(e);
            const double* p0 = d.x + 3 * std::size_t(t[0]);
            const double* p1 = d.x + 3 * std::size_t(t[1]);
            const double* p2 = d.x + 3 * std::size_t(t[2]);
            const double* p3 = d.x + 3 * std::size_t(t[3]);
            for (int r = 0; r < 3; ++r) {
                if (displacement_edges) {
                    // Small strains: differences of displacements keep the digits that
                    // differences of positions would cancel away.
                    const double u0 = p0[r] - d.X[3 * std::size_t(t[0]) + r];
                    b.D[3 * r + 0][l] = (p1[r] - d.X[3 * std::size_t(t[1]) + r]) - u0;
                    b.D[3 * r + 1][l] = (p2[r] - d.X[3 * std::size_t(t[2]) + r]) - u0;
                    b.D[3 * r + 2][l] = (p3[r] - d.X[3 * std::size_t(t[3]) + r]) - u0;
                } else {
                    b.D[3 * r + 0][l] = p1[r] - p0[r];
                    b.D[3 * r + 1][l] = p2[r] - p0[r];
                    b.D[3 * r + 2][l] = p3[r] - p0[r];
                }
            }
            const double* m = d.Dm_inv + 9 * std::size_t(e);
            for (int i = 0; i < 9; ++i) b.m[i][l] = m[i];
            b.V[l] = d.volume[e];
        }
        deformation_gradient(b);
        volume_ratios<displacement_edges>(b);
        model(b, e0);
        if constexpr (Model::kBarrier) volume_barrier_lanes<displacement_edges>(b, model.lame);
        // f_int_a = V P grad N_a with grad N_a the rows of Dm^-1 (a = 1..3) and node 0 the
        // negative sum; the elastic force is its negative.
        double G[9][kLanes];  // G[3r + a-1]: force component r on node a
        for (int r = 0; r < 3; ++r)
            for (int l = 0; l < kLanes; ++l) {
                const double q0 = -b.V[l] * b.P[3 * r][l], q1 = -b.V[l] * b.P[3 * r + 1][l],
                             q2 = -b.V[l] * b.P[3 * r + 2][l];
                G[3 * r + 0][l] = q0 * b.m[0][l] + q1 * b.m[3][l] + q2 * b.m[6][l];
                G[3 * r + 1][l] = q0 * b.m[1][l] + q1 * b.m[4][l] + q2 * b.m[7][l];
                G[3 * r + 2][l] = q0 * b.m[2][l] + q1 * b.m[5][l] + q2 * b.m[8][l];
            }
        for (int l = 0; l < b.n; ++l) {
            const uint32_t* t = d.tets + 4 * std::size_t(e0 + l);
            energy += b.V[l] * b.psi[l];
            if constexpr (Model::kTangent || Model::kBarrier) worst = std::max(worst, b.tangent[l]);  // drops a NaN
            out.inverted += !(b.J[l] > 0.0);
            out.min_J = std::min(out.min_J, b.J[l]);
            for (int r = 0; r < 3; ++r) {
                const double g1 = G[3 * r][l], g2 = G[3 * r + 1][l], g3 = G[3 * r + 2][l];
                d.f[3 * std::size_t(t[1]) + r] += g1;
                d.f[3 * std::size_t(t[2]) + r] += g2;
                d.f[3 * std::size_t(t[3]) + r] += g3;
                d.f[3 * std::size_t(t[0]) + r] -= g1 + g2 + g3;
            }
        }
    }
    out.energy = energy;
    out.tangent = worst;
    return out;
}

// The element loop shared by every model, parallel over the colours of element blocks (see
// element_colouring.h): the blocks of one colour share no node, so they scatter at once, and
// each node sums its contributions in the same order for any thread count. The strain energy
// is summed per block, then over the blocks in index order, for the same reason. A model with
// kTangent also gives its largest tangent estimate over the tets (a maximum: exact in any
// order), and every model its inverted tets and smallest volume ratio.
template <bool displacement_edges, class Model>
BlockResult element_loop(const ElementMesh& mesh, const double* x, double* f, ThreadPool* pool,
                         const Model& model) {
    std::fill(f, f + 3 * std::size_t(mesh.node_count()), 0.0);
    const ElementColouring& colouring = *mesh.colouring;
    const LoopData d{x, mesh.X.data(), mesh.tets.data(), mesh.Dm_inv.data(), mesh.volume.data(),
                     f, mesh.tet_count(), colouring.block_size};
    BlockResults per_block(colouring.block_count());
    const auto block_forces = cpu_variant<&element_block<displacement_edges, Model>>(cpu_level());
    for (uint32_t c = 0; c < colouring.colour_count(); ++c) {
        const uint32_t* blocks = colouring.blocks.data() + colouring.colour_start[c];
        parallel_for(pool, colouring.colour_start[c + 1] - colouring.colour_start[c], [&](uint32_t i) {
            per_block[blocks[i]] = block_forces(d, blocks[i], model);
        });
    }
    return sum_blocks(per_block);
}

// The forces of one body's state: strain energy and (a model with kTangent) the stiffening of
// its stiffest tet relative to the undeformed one, F = I.
template <bool displacement_edges, class Model>
ElasticResult elastic_forces(const ElementMesh& mesh, const ElasticState& state, ThreadPool* pool,
                             const Model& model) {
    const BlockResult r = element_loop<displacement_edges>(mesh, state.x.data(), state.force.data(), pool, model);
    ElasticResult out = elastic_result(r);
    if constexpr (Model::kTangent) out.stiffening = stiffening<Model>(r.tangent, model.mu, model.lam);
    else if constexpr (Model::kBarrier)
        out.stiffening = stiffening<Model>(r.tangent, model.lame.mu, model.lame.lambda + model.lame.mu);
    return out;
}

}  // namespace

ElasticResult compute_elastic_forces(const ElementMesh& mesh, const Material& material,
                                     const ElasticState& state, ThreadPool* pool) {
    if (mesh.nodes_per_tet == kQuadraticTetNodes) return compute_quadratic_elastic_forces(mesh, material, state, pool);
    const Lame lame = material.lame;
    switch (material.model) {
        case Model::linear:
            return elastic_forces<true>(mesh, state, pool, LinearModel{{lame}});
        case Model::paper: {
            // Floating frame: strain measured in the body's rotated frame, R^T F - I; the
            // translation of the frame drops out because the gradients of N sum to zero.
            const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Rm = load_quaternion(state.frame).toRotationMatrix();
            PaperModel model{lame, {}};
            for (int i = 0; i < 9; ++i) model.R[i] = Rm.data()[i];
            return elastic_forces<false>(mesh, state, pool, model);
        }
        case Model::corotational:
            // One rotation per tet, the polar rotation of F (warm-started from the last step):
            // the stress R C:(R^T F - I) is torque-free for an isotropic material, so angular
            // momentum is kept.
            return elastic_forces<false>(mesh, state, pool, CorotationalModel{lame, state.tet_rotation.data()});
        case Model::neo_hookean:
        default:
            return elastic_forces<false>(mesh, state, pool, NeoHookeanModel{lame.mu, lame.lambda + lame.mu});
    }
}

void apply_reference_stiffness(const ElementMesh& mesh, const Lame& lame, const double* u,
                               double* y, ThreadPool* pool) {
    if (mesh.nodes_per_tet == kQuadraticTetNodes) return apply_quadratic_reference_stiffness(mesh, lame, u, y, pool);
    // The linear kernel on the edges of u gives -K u.
    element_loop<false>(mesh, u, y, pool, HookeModel{lame});
    for (std::size_t i = 0; i < 3 * std::size_t(mesh.node_count()); ++i) y[i] = -y[i];
}

void compute_von_mises(const ElementMesh& mesh, const Material& material, const double* x,
                       const float* tet_rotation, const double* frame, double* out) {
    if (mesh.nodes_per_tet == kQuadraticTetNodes)
        return compute_quadratic_von_mises(mesh, material, x, tet_rotation, frame, out);
    const double* X = mesh.X.data();
    const Mat3 R_body = material.model == Model::paper ? Mat3(load_quaternion(frame).toRotationMatrix())
                                                           : Mat3::Identity();
    for (uint32_t e = 0; e < mesh.tet_count(); ++e) {
        const uint32_t* t = &mesh.tets[4 * e];
        const Eigen::Map<const Mat3> Dm_inv(&mesh.Dm_inv[9 * e]);
        const Mat3 F = edge_matrix(x + 3 * t[0], x + 3 * t[1], x + 3 * t[2], x + 3 * t[3]) * Dm_inv;
        Mat3 sigma;
        switch (material.model) {
            case Model::linear: {
                double u[4][3];
                for (int a = 0; a < 4; ++a)
                    for (int r = 0; r < 3; ++r) u[a][r] = x[3 * t[a] + r] - X[3 * t[a] + r];
                sigma = hooke_stress(edge_matrix(u[0], u[1], u[2], u[3]) * Dm_inv, material.lame,
                                     nullptr);
                break;
            }
            case Model::paper:
                // Von Mises is invariant under rotation: the stress in the frame is enough.
                sigma = hooke_stress(R_body.transpose() * F - Mat3::Identity(), material.lame, nullptr);
                break;
            case Model::corotational: {
                const float* s = &tet_rotation[4 * std::size_t(e)];
                Eigen::Quaterniond q(s[0], s[1], s[2], s[3]);
                q.normalize();
                extract_rotation(F, q);
                const Mat3 R = q.toRotationMatrix();
                sigma = hooke_stress(R.transpose() * F - Mat3::Identity(), material.lame, nullptr);
                break;
            }
            default: {
                // Cauchy stress P F^T / J; an inverted tet (J <= 0) reports its Kirchhoff
                // stress instead of dividing by a vanishing or negative volume ratio.
                const Mat3 P = neo_hookean_stress(F, material.lame, nullptr);
                const double J = F.determinant();
                sigma = P * F.transpose() / (J > 1e-6 ? J : 1.0);
                break;
            }
        }
        out[e] = von_mises(sigma);
    }
}

}  // namespace lfem
