#include "fem/lumped_mass.h"

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

void add_lumped_mass(const uint32_t* tets, const double* volume, uint32_t first, uint32_t end, double density,
                     double* mass) {
    for (uint32_t e = first; e < end; ++e)
        for (int a = 0; a < 4; ++a) mass[tets[4 * std::size_t(e) + a]] += density * volume[e] / 4.0;  // eq. (1)
}

}  // namespace lfem
