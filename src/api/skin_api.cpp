// C shim of skins: the render mesh checked here (pointers, finite positions, triangle indices)
// before the world binds it; reads copy into the caller's buffers all or nothing.
#include <string>
#include <vector>

#include "api/handles.h"

using namespace lfem;
using namespace lfem::api;

namespace {

const Skin& skin_of(const Body& b, uint32_t skin) {
    require(skin < b.skins.size(), "skin " + std::to_string(skin) + " is out of range (the body has " +
                                       std::to_string(b.skins.size()) + " skins)");
    return b.skins[skin];
}

void require_vertex_capacity(const Skin& s, uint32_t capacity) {
    if (capacity < s.vertex_count())
        throw Error(Status::buffer_too_small, "vertex_capacity " + std::to_string(capacity) + " is below the skin's " +
                                               std::to_string(s.vertex_count()) + " vertices");
}

// The deformed skin at the body's current positions (normals only when asked for).
void deformed(const Body& b, const Skin& s, std::vector<double>& positions, std::vector<double>* normals) {
    deform_skin(s, b.positions(), positions, normals);
}

}  // namespace

extern "C" {

LFEM_API lfem_status lfem_body_add_skin(lfem_world* world, lfem_body body, const double* positions,
                                        uint32_t vertex_count, const uint32_t* triangles, uint32_t triangle_count,
                                        uint32_t* skin_index) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        require_pointer(positions, "positions");
        require_pointer(triangles, "triangles");
        require(vertex_count >= 1, "vertex_count must be >= 1");
        require(triangle_count >= 1, "triangle_count must be >= 1");
        require_finite(positions, 3 * std::size_t(vertex_count), "positions");
        const uint32_t index = w.add_skin(from_c(body), positions, vertex_count, triangles, triangle_count);
        if (skin_index) *skin_index = index;
    });
}

LFEM_API lfem_status lfem_body_remove_skin(lfem_world* world, lfem_body body, uint32_t skin) {
    return guard(__func__, [&] {
        World& w = world_of(world);
        w.body(from_c(body));  // the handle first
        w.remove_skin(from_c(body), skin);
    });
}

LFEM_API lfem_status lfem_body_get_skin_count(const lfem_world* world, lfem_body body, uint32_t* out) {
    return guard(__func__, [&] {
        const Body& b = world_of(world).body(from_c(body));
        require_pointer(out, "out");
        *out = uint32_t(b.skins.size());
    });
}

LFEM_API lfem_status lfem_body_get_skin_sizes(const lfem_world* world, lfem_body body, uint32_t skin,
                                              uint32_t* vertex_count, uint32_t* triangle_count) {
    return guard(__func__, [&] {
        const Skin& s = skin_of(world_of(world).body(from_c(body)), skin);
        if (vertex_count) *vertex_count = s.vertex_count();
        if (triangle_count) *triangle_count = s.triangle_count();
    });
}

LFEM_API lfem_status lfem_body_get_skin_triangles(const lfem_world* world, lfem_body body, uint32_t skin,
                                                  uint32_t* out, uint32_t triangle_capacity) {
    return guard(__func__, [&] {
        const Skin& s = skin_of(world_of(world).body(from_c(body)), skin);
        require_pointer(out, "out");
        if (triangle_capacity < s.triangle_count())
            throw Error(Status::buffer_too_small, "triangle_capacity " + std::to_string(triangle_capacity) +
                                                   " is below the skin's " + std::to_string(s.triangle_count()) +
                                                   " triangles");
        std::copy(s.triangles.begin(), s.triangles.end(), out);
    });
}

LFEM_API lfem_status lfem_body_get_skin_vertices(const lfem_world* world, lfem_body body, uint32_t skin,
                                                 double* positions, double* normals, uint32_t vertex_capacity) {
    return guard(__func__, [&] {
        const Body& b = world_of(world).body(from_c(body));
        const Skin& s = skin_of(b, skin);
        require_pointer(positions, "positions");
        require_vertex_capacity(s, vertex_capacity);
        std::vector<double> p, n;
        deformed(b, s, p, normals ? &n : nullptr);
        std::copy(p.begin(), p.end(), positions);
        if (normals) std::copy(n.begin(), n.end(), normals);
    });
}

LFEM_API lfem_status lfem_body_get_skin_vertices_f32(const lfem_world* world, lfem_body body, uint32_t skin,
                                                     float* positions, uint32_t position_stride, float* normals,
                                                     uint32_t normal_stride, uint32_t vertex_capacity) {
    return guard(__func__, [&] {
        const Body& b = world_of(world).body(from_c(body));
        const Skin& s = skin_of(b, skin);
        require_pointer(positions, "positions");
        require(position_stride >= 3, "position_stride must be >= 3 floats, got " + std::to_string(position_stride));
        require(!normals || normal_stride >= 3, "normal_stride must be >= 3 floats, got " + std::to_string(normal_stride));
        require_vertex_capacity(s, vertex_capacity);
        std::vector<double> p, n;
        deformed(b, s, p, normals ? &n : nullptr);
        for (std::size_t v = 0; v < s.vertex_count(); ++v)
            for (int k = 0; k < 3; ++k) {
                positions[v * position_stride + k] = float(p[3 * v + k]);
                if (normals) normals[v * normal_stride + k] = float(n[3 * v + k]);
            }
    });
}

}  // extern "C"
