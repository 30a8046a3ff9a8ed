// The element kernels of the 10-node tet (fem/quadratic_tet.h): at each of the 4 quadrature
// points of a tet, Ds_q from the ten nodes, F_q = Ds_q J_q^-1, the stress P_q of the body's
// model, and the nodal forces -V_q P_q J_q^-T dN_a/dxi; then one scatter per tet, in tet order.
// The composite element (composite_tet.h) runs the same loop with its own table in place of
// dN_a/dxi.
// Plain loops over small fixed arrays, no instruction-set variants: the compiler vectorises
// them for whatever it targets, and with -ffp-contract=off (CMakeLists.txt) every target rounds
// alike.
#include "fem/quadratic_forces.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "fem/block_result.h"
#include "fem/neo_hookean_tangent.h"
#include "fem/polar_rotation.h"
#include "fem/composite_tet.h"
#include "fem/tet_element.h"
#include "fem/volume_barrier.h"

namespace lfem {
namespace {

// The per-point steps inlined into the element loop (GCC and Clang keep them out of line).
#if defined(__GNUC__)
#define LFEM_QUADRATIC_INLINE __attribute__((always_inline)) inline
#else
#define LFEM_QUADRATIC_INLINE inline
#endif

// The stress of each model at one quadrature point (index k = 4 tet + q): P from F, the energy
// density into psi; a model with kTangent also raises `tangent` to its stiffness estimate.
// kBarrier: the loop adds the volume barrier (volume_barrier.h) at the point, as for linear
// tets; the neo-Hookean energy has it inside, and the reference stiffness is Hooke's law alone.
struct HookeStress {
    static constexpr bool kTangent = false, kBarrier = false;
    Lame lame;
    Mat3 operator()(const Mat3& H, std::size_t, double& psi, double&) const { return hooke_stress(H, lame, &psi); }
};
struct LinearStress : HookeStress {
    static constexpr bool kBarrier = true;
};

// Hooke's law in a rotated frame: P = R hooke(R^T F - I).
LFEM_QUADRATIC_INLINE Mat3 rotated_hooke(const Mat3& R, const Mat3& F, const Lame& lame, double& psi) {
    return R * hooke_stress(R.transpose() * F - Mat3::Identity(), lame, &psi);
}

struct PaperStress {
    static constexpr bool kTangent = false, kBarrier = true;
    Lame lame;
    Mat3 R;  // the body's floating frame
    Mat3 operator()(const Mat3& F, std::size_t, double& psi, double&) const { return rotated_hooke(R, F, lame, psi); }
};

// One rotation per quadrature point, the polar rotation of F_q: R^T F_q is then symmetric and
// the stress torque-free there, so the element keeps angular momentum as the linear one does.
struct CorotationalStress {
    static constexpr bool kTangent = false, kBarrier = true;
    Lame lame;
    float* rotations;  // 4 per quadrature point, warm start, updated
    Mat3 operator()(const Mat3& F, std::size_t k, double& psi, double&) const {
        double A[9], R[9];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) A[3 * r + c] = F(r, c);
        extract_rotation_fast(A, rotations + 4 * k, R);
        return rotated_hooke(load_row_major(R), F, lame, psi);
    }
};

struct NeoHookeanStress {
    static constexpr bool kTangent = true, kBarrier = false;
    Lame lame;
    Mat3 operator()(const Mat3& F, std::size_t, double& psi, double& tangent) const {
        const double t = neo_hookean_tangent_estimate(F(0, 0), F(1, 0), F(2, 0), F(0, 1), F(1, 1), F(2, 1), F(0, 2),
                                                      F(1, 2), F(2, 2), lame.mu, lame.lambda + lame.mu);
        tangent = std::max(tangent, t);  // drops a NaN
        return neo_hookean_stress(F, lame, &psi);
    }
};

struct QuadraticLoop {
    const double* x;
    const double* X;
    const uint32_t* tets;
    const double* Jq_inv;     // 9 per quadrature point, column-major
    const double* qp_volume;  // per quadrature point
    double* f;
    uint32_t tet_count;
    uint32_t block_size;
};

// The ten nodes of tet e relative to its first: displacements (small strains keep the digits
// that positions would cancel away) or positions. sum_a dN_a = 0, so the offset drops out.
template <bool displacement>
LFEM_QUADRATIC_INLINE void gather(const QuadraticLoop& d, uint32_t e, double u[kQuadraticTetNodes][3]) {
    const uint32_t* t = d.tets + kQuadraticTetNodes * std::size_t(e);
    for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
        for (int r = 0; r < 3; ++r) {
            const std::size_t i = 3 * std::size_t(t[a]) + r;
            u[a][r] = displacement ? d.x[i] - d.X[i] : d.x[i];
        }
    for (uint32_t a = kQuadraticTetNodes; a-- > 0;)
        for (int r = 0; r < 3; ++r) u[a][r] -= u[0][r];
}

// The barycentric coordinates of quadrature point q.
struct PointWeights {
    double L[4];
    explicit PointWeights(int q) : L{kQuadratureB, kQuadratureB, kQuadratureB, kQuadratureB} { L[q] = kQuadratureA; }
};

// Ds_q = sum_a u_a dN_a/dxi^T at quadrature point q, through the barycentric gradients: with
// dN_a/dxi = sum_i c_ai dL_i (c: 4 L_i - 1 for corner i; 4 L_j and 4 L_i for the mid-edge node
// of (i, j) on dL_i and dL_j), Ds = sum_i w_i dL_i^T with w_i = sum_a c_ai u_a, and since
// dL_0 = -(1, 1, 1), dL_c = e_c, its columns are w_c - w_0: the edge matrix of four virtual
// nodes, a third of the work of the full sum over 10 nodes x 3 directions.
LFEM_QUADRATIC_INLINE Mat3 natural_gradient(const double u[kQuadraticTetNodes][3], const PointWeights& p) {
    double w[4][3];
    for (int i = 0; i < 4; ++i)
        for (int r = 0; r < 3; ++r) w[i][r] = (4.0 * p.L[i] - 1.0) * u[i][r];
    for (int e = 0; e < 6; ++e) {
        const int i = kQuadraticTetEdges[e][0], j = kQuadraticTetEdges[e][1];
        for (int r = 0; r < 3; ++r) {
            w[i][r] += 4.0 * p.L[j] * u[4 + e][r];
            w[j][r] += 4.0 * p.L[i] * u[4 + e][r];
        }
    }
    Mat3 Ds;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) Ds(r, c) = w[c + 1][r] - w[0][r];
    return Ds;
}

// f_a += G dN_a/dxi for the ten nodes, through the same split: G dL_c is column c of G and
// G dL_0 minus their sum.
LFEM_QUADRATIC_INLINE void add_nodal_forces(const Mat3& G, const PointWeights& p, double f[kQuadraticTetNodes][3]) {
    double gamma[4][3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) gamma[c + 1][r] = G(r, c);
        gamma[0][r] = -(G(r, 0) + G(r, 1) + G(r, 2));
    }
    for (int i = 0; i < 4; ++i)
        for (int r = 0; r < 3; ++r) f[i][r] += (4.0 * p.L[i] - 1.0) * gamma[i][r];
    for (int e = 0; e < 6; ++e) {
        const int i = kQuadraticTetEdges[e][0], j = kQuadraticTetEdges[e][1];
        for (int r = 0; r < 3; ++r) f[4 + e][r] += 4.0 * (p.L[j] * gamma[i][r] + p.L[i] * gamma[j][r]);
    }
}

// The quadratic shape functions' gradients at the quadrature points, through the barycentric
// split above.
struct QuadraticShape {
    LFEM_QUADRATIC_INLINE static Mat3 gradient(const double u[kQuadraticTetNodes][3], int q) {
        return natural_gradient(u, PointWeights(q));
    }
    LFEM_QUADRATIC_INLINE static void add_forces(const Mat3& G, int q, double f[kQuadraticTetNodes][3]) {
        add_nodal_forces(G, PointWeights(q), f);
    }
};

// The composite element's (composite_tet.h): Ds_q = sum_a u_a bhat_qa^T and f_a += G bhat_qa,
// the table having no structure to exploit.
struct CompositeShape {
    LFEM_QUADRATIC_INLINE static Mat3 gradient(const double u[kQuadraticTetNodes][3], int q) {
        const double(&b)[kQuadraticTetNodes][3] = kCompositeGradients.g[q];
        Mat3 Ds = Mat3::Zero();
        for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) Ds(r, c) += u[a][r] * b[a][c];
        return Ds;
    }
    LFEM_QUADRATIC_INLINE static void add_forces(const Mat3& G, int q, double f[kQuadraticTetNodes][3]) {
        const double(&b)[kQuadraticTetNodes][3] = kCompositeGradients.g[q];
        for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
            for (int r = 0; r < 3; ++r) f[a][r] += G(r, 0) * b[a][0] + G(r, 1) * b[a][1] + G(r, 2) * b[a][2];
    }
};

// The volume barrier at one quadrature point of deformation F, added to P and psi (rare: only
// below J_b); returns the stiffness it adds, 0 above J_b.
LFEM_QUADRATIC_INLINE double add_barrier(const Mat3& F, double J, const Lame& lame, Mat3& P, double& psi) {
    if (!(J < kBarrierJ)) return 0.0;
    double f[9], p[9];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) f[3 * r + c] = F(r, c), p[3 * r + c] = P(r, c);
    const double t = add_volume_barrier(f, lame.lambda + lame.mu, p, psi);
    P = load_row_major(p);
    return t;
}

// One block of tets: its strain energy, inverted tets, smallest volume ratio and (a model with
// kTangent or kBarrier) largest tangent estimate.
template <bool displacement, class Shape, class Model>
BlockResult quadratic_block(const QuadraticLoop& d, uint32_t block, const Model& model) {
    BlockResult out;
    double energy = 0.0, worst = 0.0;
    const uint32_t e_end = std::min(d.tet_count, (block + 1) * d.block_size);
    for (uint32_t e = block * d.block_size; e < e_end; ++e) {
        double u[kQuadraticTetNodes][3], f[kQuadraticTetNodes][3] = {};
        gather<displacement>(d, e, u);
        double tet_J = HUGE_VAL;
        for (int q = 0; q < kQuadraturePoints; ++q) {
            const std::size_t k = kQuadraturePoints * std::size_t(e) + q;
            const Eigen::Map<const Mat3> Jinv(d.Jq_inv + 9 * k);
            double psi = 0.0;
            const Mat3 G = Shape::gradient(u, q) * Jinv;  // F, or grad u with displacements
            const Mat3 F = displacement ? Mat3(G + Mat3::Identity()) : G;
            const double J = F.determinant();
            tet_J = std::min(tet_J, J);
            Mat3 P = model(G, k, psi, worst);
            if constexpr (Model::kBarrier) worst = std::max(worst, add_barrier(F, J, model.lame, P, psi));
            const double V = d.qp_volume[k];
            energy += V * psi;
            Shape::add_forces(-V * (P * Jinv.transpose()), q, f);  // the elastic force is -f_int
        }
        out.inverted += !(tet_J > 0.0);
        out.min_J = std::min(out.min_J, tet_J);
        const uint32_t* t = d.tets + kQuadraticTetNodes * std::size_t(e);
        for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
            for (int r = 0; r < 3; ++r) d.f[3 * std::size_t(t[a]) + r] += f[a][r];
    }
    out.energy = energy;
    out.tangent = worst;
    return out;
}

// The element loop, colour by colour (element_colouring.h), the blocks' results then summed
// over the blocks in index order: bitwise the same for any thread count.
template <bool displacement, class Model>
BlockResult quadratic_loop(const ElementMesh& mesh, const double* x, double* f, ThreadPool* pool, const Model& model) {
    std::fill(f, f + 3 * std::size_t(mesh.node_count()), 0.0);
    const ElementColouring& colouring = *mesh.colouring;
    const QuadraticLoop d{x, mesh.X.data(), mesh.tets.data(), mesh.Dm_inv.data(), mesh.qp_volume.data(),
                          f, mesh.tet_count(), colouring.block_size};
    BlockResults per_block(colouring.block_count());
    if (mesh.composite)
        for_each_block_by_colour(colouring, pool, [&](uint32_t b) {
            per_block[b] = quadratic_block<displacement, CompositeShape>(d, b, model);
        });
    else
        for_each_block_by_colour(colouring, pool, [&](uint32_t b) {
            per_block[b] = quadratic_block<displacement, QuadraticShape>(d, b, model);
        });
    return sum_blocks(per_block);
}

template <bool displacement, class Model>
ElasticResult quadratic_forces(const ElementMesh& mesh, const ElasticState& state, ThreadPool* pool,
                               const Model& model) {
    const BlockResult r = quadratic_loop<displacement>(mesh, state.x.data(), state.force.data(), pool, model);
    ElasticResult out = elastic_result(r);
    const Lame& l = model.lame;
    out.stiffening = stiffening<Model>(r.tangent, l.mu, l.lambda + l.mu);
    return out;
}

Mat3 frame_rotation(const double* frame) { return load_quaternion(frame).toRotationMatrix(); }

// The Cauchy stress of quadrature point k (index 4 tet + q) at deformation gradient F (the
// displacement gradient for the linear model).
Mat3 cauchy_stress(const Material& material, const Mat3& F, const Mat3& R_body, const float* tet_rotation,
                   std::size_t k) {
    const Lame& lame = material.lame;
    switch (material.model) {
        case Model::linear:
            return hooke_stress(F, lame, nullptr);
        case Model::paper:
            return R_body * hooke_stress(R_body.transpose() * F - Mat3::Identity(), lame, nullptr) * R_body.transpose();
        case Model::corotational: {
            const float* s = tet_rotation + 4 * k;
            Eigen::Quaterniond q(s[0], s[1], s[2], s[3]);
            q.normalize();
            extract_rotation(F, q);
            const Mat3 R = q.toRotationMatrix();
            return R * hooke_stress(R.transpose() * F - Mat3::Identity(), lame, nullptr) * R.transpose();
        }
        default: {
            // As for linear tets: an inverted point reports its Kirchhoff stress.
            const double J = F.determinant();
            return neo_hookean_stress(F, lame, nullptr) * F.transpose() / (J > 1e-6 ? J : 1.0);
        }
    }
}

}  // namespace

ElasticResult compute_quadratic_elastic_forces(const ElementMesh& mesh, const Material& material,
                                               const ElasticState& state, ThreadPool* pool) {
    const Lame lame = material.lame;
    switch (material.model) {
        case Model::linear:
            return quadratic_forces<true>(mesh, state, pool, LinearStress{{lame}});
        case Model::paper:
            return quadratic_forces<false>(mesh, state, pool, PaperStress{lame, frame_rotation(state.frame)});
        case Model::corotational:
            return quadratic_forces<false>(mesh, state, pool, CorotationalStress{lame, state.tet_rotation.data()});
        case Model::neo_hookean:
        default:
            return quadratic_forces<false>(mesh, state, pool, NeoHookeanStress{lame});
    }
}

void apply_quadratic_reference_stiffness(const ElementMesh& mesh, const Lame& lame, const double* u, double* y,
                                         ThreadPool* pool) {
    // The linear kernel on the nodes' u (their differences are u's) gives -K u.
    quadratic_loop<false>(mesh, u, y, pool, HookeStress{lame});
    for (std::size_t i = 0; i < 3 * std::size_t(mesh.node_count()); ++i) y[i] = -y[i];
}

void compute_quadratic_von_mises(const ElementMesh& mesh, const Material& material, const double* x,
                                 const float* tet_rotation, const double* frame, double* out) {
    const Mat3 R_body = material.model == Model::paper ? frame_rotation(frame) : Mat3::Identity();
    const bool displacement = material.model == Model::linear;
    const QuadraticLoop d{x, mesh.X.data(), mesh.tets.data(), mesh.Dm_inv.data(), mesh.qp_volume.data(),
                          nullptr, mesh.tet_count(), 0};
    for (uint32_t e = 0; e < mesh.tet_count(); ++e) {
        double u[kQuadraticTetNodes][3];
        displacement ? gather<true>(d, e, u) : gather<false>(d, e, u);
        Mat3 mean = Mat3::Zero();
        for (int q = 0; q < kQuadraturePoints; ++q) {
            const std::size_t k = kQuadraturePoints * std::size_t(e) + q;
            const Mat3 Ds = mesh.composite ? CompositeShape::gradient(u, q) : QuadraticShape::gradient(u, q);
            const Mat3 F = Ds * Eigen::Map<const Mat3>(d.Jq_inv + 9 * k);
            mean += d.qp_volume[k] * cauchy_stress(material, F, R_body, tet_rotation, k);
        }
        out[e] = von_mises(mean / mesh.volume[e]);
    }
}

}  // namespace lfem
