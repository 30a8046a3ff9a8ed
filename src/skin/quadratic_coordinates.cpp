#include "skin/quadratic_coordinates.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lfem {

bool quadratic_coordinates(const Vec3 X[kQuadraticTetNodes], const Vec3& p, double L[4]) {
    // Relative to corner 0, so that the rounding scales with the element, not with where it is.
    Vec3 d[kQuadraticTetNodes];
    const double* rows[kQuadraticTetNodes];
    double scale = (p - X[0]).norm();
    for (uint32_t a = 0; a < kQuadraticTetNodes; ++a) {
        d[a] = X[a] - X[0];
        rows[a] = d[a].data();
        scale = std::max(scale, d[a].norm());
    }
    const Vec3 q = p - X[0];
    Vec3 xi(L[1], L[2], L[3]), best_xi = xi;
    double best = HUGE_VAL;
    for (int iteration = 0; iteration < 40; ++iteration) {
        const double l[4] = {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
        double N[kQuadraticTetNodes];
        quadratic_shape_values_at(l, N);
        Vec3 r = -q;
        for (uint32_t a = 0; a < kQuadraticTetNodes; ++a) r += N[a] * d[a];
        const double miss = r.norm();
        // Newton converges quadratically near the answer: once an iteration no longer gets
        // closer, the rounding floor (or a divergence) is reached.
        if (!(miss < best)) break;
        best = miss, best_xi = xi;
        if (miss <= 4.0 * std::numeric_limits<double>::epsilon() * scale) break;
        double g[kQuadraticTetNodes][3], J[9];
        quadratic_gradients_at(l, g);
        natural_jacobian(rows, g, J);
        const Mat3 Jm = load_row_major(J);
        if (!(std::fabs(Jm.determinant()) > 0.0)) break;
        xi -= Jm.inverse() * r;
    }
    if (!(best <= 1e-12 * scale)) return false;
    L[0] = 1.0 - best_xi[0] - best_xi[1] - best_xi[2], L[1] = best_xi[0], L[2] = best_xi[1], L[3] = best_xi[2];
    return true;
}

}  // namespace lfem
