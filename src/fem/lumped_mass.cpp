#include "fem/lumped_mass.h"

#include "fem/composite_tet.h"
#include "fem/tet_element.h"

namespace lfem {

void add_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end, double* Dm_inv,
                        double* volume) {
    for (uint32_t e = first; e < end; ++e) {
        const uint32_t* t = &tets[4 * std::size_t(e)];
        const Mat3 Dm = edge_matrix(X + 3 * t[0], X + 3 * t[1], X + 3 * t[2], X + 3 * t[3]);
        Eigen::Map<Mat3> inverse(Dm_inv + 9 * std::size_t(e));
        inverse = Dm.inverse();
        volume[e] = Dm.determinant() / 6.0;
    }
}

void add_quadratic_reference_tets(const double* X, const uint32_t* tets, uint32_t first, uint32_t end,
                                  bool composite, double* Jq_inv, double* qp_volume, double* volume) {
    for (uint32_t e = first; e < end; ++e) {
        const uint32_t* t = &tets[kQuadraticTetNodes * std::size_t(e)];
        const double* p[kQuadraticTetNodes];
        for (uint32_t a = 0; a < kQuadraticTetNodes; ++a) p[a] = X + 3 * std::size_t(t[a]);
        double V = 0.0;
        for (int q = 0; q < kQuadraturePoints; ++q) {
            double J[9];
            natural_jacobian(p, kQuadraticGradients.g[q], J);
            const Mat3 Jm = load_row_major(J);
            const std::size_t k = kQuadraturePoints * std::size_t(e) + q;
            Eigen::Map<Mat3> inverse(Jq_inv + 9 * k);
            if (composite) {
                double Jc[9];
                natural_jacobian(p, kCompositeGradients.g[q], Jc);
                inverse = load_row_major(Jc).inverse();
            } else {
                inverse = Jm.inverse();
            }
            qp_volume[k] = kQuadratureWeight * Jm.determinant();
            V += qp_volume[k];
        }
        volume[e] = V;
    }
}

void add_lumped_mass(const uint32_t* tets, const double* volume, uint32_t first, uint32_t end, double density,
                     double* mass, uint32_t nodes_per_tet) {
    if (nodes_per_tet == kQuadraticTetNodes) {
        for (uint32_t e = first; e < end; ++e)  // eq. (1), the sub-tet lumping
            for (uint32_t a = 0; a < kQuadraticTetNodes; ++a)
                mass[tets[kQuadraticTetNodes * std::size_t(e) + a]] += density * volume[e] * lumped_share(nodes_per_tet, a);
        return;
    }
    for (uint32_t e = first; e < end; ++e)
        for (int a = 0; a < 4; ++a) mass[tets[4 * std::size_t(e) + a]] += density * volume[e] / 4.0;  // eq. (1)
}

}  // namespace lfem
