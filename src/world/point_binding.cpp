#include "world/point_binding.h"

#include <cstdio>

#include "common/error.h"

namespace lfem {

Skin bind_points(const Body& body, const double* points, uint32_t count, double reach, const char* what) {
    SkinTets tets;
    tets.X = body.state.x;
    tets.tets = body.ref.tets;
    tets.nodes_per_tet = body.ref.nodes_per_tet;
    try {
        return bind_skin(tets, points, count, nullptr, 0, reach);
    } catch (const Error& e) {
        if (e.status() != Status::invalid_argument) throw;
        // Which point: the first beyond reach (the binding stops there).
        uint32_t k = 0;
        for (; k + 1 < count; ++k) {
            try {
                bind_skin(tets, points + 3 * std::size_t(k), 1, nullptr, 0, reach);
            } catch (const Error&) {
                break;
            }
        }
        const double* p = points + 3 * std::size_t(k);
        char where[200];
        if (count == 1)
            std::snprintf(where, sizeof where, "%s (%.6g, %.6g, %.6g) m lies farther than %.3g m (one edge) from the body",
                          what, p[0], p[1], p[2], reach);
        else
            std::snprintf(where, sizeof where,
                          "%s: point %u at (%.6g, %.6g, %.6g) m lies farther than %.3g m (one edge) from the body", what, k,
                          p[0], p[1], p[2], reach);
        throw Error(Status::invalid_argument, where);
    }
}

}  // namespace lfem
