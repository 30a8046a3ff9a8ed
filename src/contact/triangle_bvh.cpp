#include "contact/triangle_bvh.h"

namespace lfem {

void TriangleBvh::build(const double* x, const uint32_t* triangles, uint32_t triangle_count) {
    std::vector<double> centroid(3 * std::size_t(triangle_count));
    for (uint32_t t = 0; t < triangle_count; ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t* tri = &triangles[3 * std::size_t(t)];
            centroid[3 * std::size_t(t) + k] = (x[3 * tri[0] + k] + x[3 * tri[1] + k] + x[3 * tri[2] + k]) / 3.0;
        }
    tree_.build(centroid.data(), triangle_count);
    refit(x, triangles);
}

}  // namespace lfem
