#include "fem/internal_forces.h"

#include <Eigen/Geometry>

#include "fem/polar_rotation.h"
#include "fem/tet_element.h"

namespace lfem {
namespace {

// The element loop shared by every model. `stress(e, F, H, psi)` returns the first
// Piola-Kirchhoff stress of tet e from its deformation gradient F and displacement gradient H
// (both given: the linear model needs only H, computed from displacements for precision).
template <bool needs_displacement_gradient, class Stress>
void element_loop(const Body& body, BodyState& state, Stress&& stress) {
    const BodyReference& ref = body.ref;
    const double* x = state.x.data();
    const double* X = ref.X.data();
    double* f = state.elastic.data();
    std::fill(state.elastic.begin(), state.elastic.end(), 0.0);
    double energy = 0.0;
    const uint32_t tet_count = ref.tet_count();
    for (uint32_t e = 0; e < tet_count; ++e) {
        const uint32_t* t = &ref.tets[4 * e];
        const Eigen::Map<const Mat3> Dm_inv(&ref.Dm_inv[9 * e]);
        Mat3 F, H;
        if (needs_displacement_gradient) {
            // Small strains: differences of displacements keep the digits that differences
            // of positions would cancel away.
            double u[4][3];
            for (int a = 0; a < 4; ++a)
                for (int r = 0; r < 3; ++r) u[a][r] = x[3 * t[a] + r] - X[3 * t[a] + r];
            H.noalias() = edge_matrix(u[0], u[1], u[2], u[3]) * Dm_inv;
        } else {
            F.noalias() = edge_matrix(x + 3 * t[0], x + 3 * t[1], x + 3 * t[2], x + 3 * t[3]) * Dm_inv;
        }
        double psi = 0.0;
        const Mat3 P = stress(e, F, H, psi);
        const double V = ref.volume[e];
        energy += V * psi;
        // f_int_a = V P grad N_a; the elastic force on the node is its negative.
        const Mat3 G = -V * P * Dm_inv.transpose();
        for (int r = 0; r < 3; ++r) {
            const double g1 = G(r, 0), g2 = G(r, 1), g3 = G(r, 2);
            f[3 * t[1] + r] += g1;
            f[3 * t[2] + r] += g2;
            f[3 * t[3] + r] += g3;
            f[3 * t[0] + r] -= g1 + g2 + g3;
        }
    }
    state.strain_energy = energy;
}

Eigen::Quaterniond load_quaternion(const double* q) { return {q[0], q[1], q[2], q[3]}; }
void store_quaternion(const Eigen::Quaterniond& q, double* out) {
    out[0] = q.w();
    out[1] = q.x();
    out[2] = q.y();
    out[3] = q.z();
}

}  // namespace

void compute_elastic_forces(const Body& body, BodyState& state) {
    const Lame lame = body.lame;
    switch (body.def.model) {
        case LFEM_MODEL_LINEAR:
            element_loop<true>(body, state, [&](uint32_t, const Mat3&, const Mat3& H, double& psi) {
                return hooke_stress(H, lame, &psi);
            });
            break;
        case LFEM_MODEL_PAPER: {
            // Floating frame: strain measured in the body's rotated frame, R^T F - I; the
            // translation of the frame drops out because the gradients of N sum to zero.
            const Mat3 R = load_quaternion(state.rotation).toRotationMatrix();
            element_loop<false>(body, state, [&](uint32_t, const Mat3& F, const Mat3&, double& psi) {
                return Mat3(R * hooke_stress(R.transpose() * F - Mat3::Identity(), lame, &psi));
            });
            break;
        }
        case LFEM_MODEL_COROTATIONAL:
            // One rotation per tet, the polar rotation of F: the stress R C:(S - I) is
            // torque-free for an isotropic material, so angular momentum is kept.
            element_loop<false>(body, state, [&](uint32_t e, const Mat3& F, const Mat3&, double& psi) {
                Eigen::Quaterniond q = load_quaternion(&state.tet_rotation[4 * e]);
                extract_rotation(F, q);
                store_quaternion(q, &state.tet_rotation[4 * e]);
                const Mat3 R = q.toRotationMatrix();
                return Mat3(R * hooke_stress(R.transpose() * F - Mat3::Identity(), lame, &psi));
            });
            break;
        case LFEM_MODEL_NEO_HOOKEAN:
        default:
            element_loop<false>(body, state, [&](uint32_t, const Mat3& F, const Mat3&, double& psi) {
                return neo_hookean_stress(F, lame, &psi);
            });
            break;
    }
}

void compute_von_mises(const Body& body, const BodyState& state, double* out) {
    const BodyReference& ref = body.ref;
    const double* x = state.x.data();
    const double* X = ref.X.data();
    const Mat3 R_body = load_quaternion(state.rotation).toRotationMatrix();
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
                Eigen::Quaterniond q = load_quaternion(&state.tet_rotation[4 * e]);
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
