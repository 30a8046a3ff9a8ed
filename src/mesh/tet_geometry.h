// Signed volume of one linear tet and the test for a tet too flat to be trusted. Shared by the
// mesh checker, the Gmsh reader and the builders so they agree on what "zero volume" means.
#pragma once

#include <algorithm>
#include <cmath>

namespace lfem::tet_geometry {

// 6 * signed volume = det[x1-x0, x2-x0, x3-x0] of the tet (x0, x1, x2, x3), each a pointer to
// 3 coordinates. Positive for the orientation every mesh in lfem uses.
inline double six_volume(const double* x0, const double* x1, const double* x2, const double* x3) {
    const double a[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
    const double b[3] = {x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]};
    const double c[3] = {x3[0] - x0[0], x3[1] - x0[1], x3[2] - x0[2]};
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

inline double squared_distance(const double* p, const double* q) {
    const double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

inline double longest_edge(const double* x0, const double* x1, const double* x2, const double* x3) {
    const double longest_squared =
        std::max({squared_distance(x0, x1), squared_distance(x0, x2), squared_distance(x0, x3),
                  squared_distance(x1, x2), squared_distance(x1, x3), squared_distance(x2, x3)});
    return std::sqrt(longest_squared);
}

// A tet counts as flat when |6V| <= kFlatness * L^3, L its longest edge.
// Why this number: 6V / L^3 is a scale-free shape measure, about 0.71 for the regular tet and
// tending to 0 as the tet flattens. The determinant of edge vectors of length ~L is computed
// with a rounding error of a few machine epsilons (2.2e-16) times L^3, so below ~1e-12 (about
// 5000 epsilons) even the sign of the volume is at the mercy of rounding. Such a tet would also
// make its stiffness ~1e12 times worse conditioned than its neighbours' and shrink the explicit
// stable time step accordingly, so refusing it is kinder than simulating it.
constexpr double kFlatness = 1e-12;

inline bool is_flat(double six_vol, double longest) {
    // Written so that an underflowing L^3 (tiny tets) or a zero L still counts as flat.
    const double l3 = longest * longest * longest;
    return !(std::abs(six_vol) > kFlatness * l3) || six_vol == 0.0;
}

}  // namespace lfem::tet_geometry
