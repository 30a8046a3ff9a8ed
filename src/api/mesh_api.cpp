// C entry points of the "Meshes" section of lfem.h: builders, Gmsh import, the conversion to
// 10-node tets, read-only views and rigid motions of a caller-owned mesh. Each function checks its arguments, builds its
// result on the side and touches the caller's mesh or *out only as its last step, so a failed
// call changes nothing.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "api/guard.h"
#include "lfem.h"
#if LFEM_WITH_IO
#include "mesh/gmsh_reader.h"
#endif
#include "mesh/mesh_builders.h"
#include "mesh/quadratic_mesh.h"
#include "mesh/tet_mesh.h"

struct lfem_mesh {
    lfem::TetMesh mesh;
};

namespace {

using lfem::api::require;
using lfem::api::require_finite;
using lfem::api::require_pointer;

void require_finite_value(double v, const char* name) {
    require(std::isfinite(v), std::string(name) + " is not finite");
}

// Moved positions are committed only if every coordinate is still finite (a huge offset
// could overflow).
void commit_positions(lfem_mesh* mesh, std::vector<double>&& moved) {
    for (double x : moved) require(std::isfinite(x), "the moved mesh has non-finite coordinates");
    mesh->mesh.positions = std::move(moved);
}

}  // namespace

extern "C" {

LFEM_API lfem_status lfem_mesh_create_box(const double size[3], const uint32_t cells[3],
                                          lfem_mesh** out) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(size, "size");
        require_pointer(cells, "cells");
        require_pointer(out, "out");
        require_finite(size, 3, "size");
        lfem::TetMesh m = lfem::build_box(size, cells);
        *out = new lfem_mesh{std::move(m)};
    });
}

LFEM_API lfem_status lfem_mesh_create_cylinder(double radius, double height, uint32_t segments,
                                               uint32_t rings, uint32_t layers, lfem_mesh** out) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(out, "out");
        require_finite_value(radius, "radius");
        require_finite_value(height, "height");
        lfem::TetMesh m = lfem::build_cylinder(radius, height, segments, rings, layers);
        *out = new lfem_mesh{std::move(m)};
    });
}

LFEM_API lfem_status lfem_mesh_create_cup(double outer_radius, double height, double wall,
                                          double bottom, uint32_t segments, uint32_t layers,
                                          lfem_mesh** out) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(out, "out");
        require_finite_value(outer_radius, "outer_radius");
        require_finite_value(height, "height");
        require_finite_value(wall, "wall");
        require_finite_value(bottom, "bottom");
        lfem::TetMesh m = lfem::build_cup(outer_radius, height, wall, bottom, segments, layers);
        *out = new lfem_mesh{std::move(m)};
    });
}

LFEM_API lfem_status lfem_mesh_create_hammer(double handle_length, double handle_width,
                                             double head_length, double head_width,
                                             double cell_size, lfem_mesh** out) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(out, "out");
        require_finite_value(handle_length, "handle_length");
        require_finite_value(handle_width, "handle_width");
        require_finite_value(head_length, "head_length");
        require_finite_value(head_width, "head_width");
        require_finite_value(cell_size, "cell_size");
        lfem::TetMesh m =
            lfem::build_hammer(handle_length, handle_width, head_length, head_width, cell_size);
        *out = new lfem_mesh{std::move(m)};
    });
}

LFEM_API lfem_status lfem_mesh_load_gmsh(const char* path, lfem_mesh** out) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(path, "path");
        require_pointer(out, "out");
#if LFEM_WITH_IO
        lfem::TetMesh m = lfem::read_gmsh(path);
        *out = new lfem_mesh{std::move(m)};
#else
        lfem::api::unsupported("the Gmsh reader", "LFEM_WITH_IO");
#endif
    });
}

LFEM_API lfem_status lfem_mesh_make_quadratic(lfem_mesh* mesh) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(mesh, "mesh");
        lfem::TetMesh quadratic = lfem::make_quadratic(mesh->mesh);
        mesh->mesh = std::move(quadratic);
    });
}

LFEM_API void lfem_mesh_destroy(lfem_mesh* mesh) { delete mesh; }

LFEM_API uint32_t lfem_mesh_get_node_count(const lfem_mesh* mesh) {
    return mesh ? mesh->mesh.node_count() : 0;
}

LFEM_API uint32_t lfem_mesh_get_tet_count(const lfem_mesh* mesh) {
    return mesh ? mesh->mesh.tet_count() : 0;
}

LFEM_API uint32_t lfem_mesh_get_nodes_per_tet(const lfem_mesh* mesh) {
    return mesh ? mesh->mesh.nodes_per_tet : 0;
}

LFEM_API const double* lfem_mesh_get_positions(const lfem_mesh* mesh) {
    return mesh && !mesh->mesh.positions.empty() ? mesh->mesh.positions.data() : nullptr;
}

LFEM_API const uint32_t* lfem_mesh_get_tets(const lfem_mesh* mesh) {
    return mesh && !mesh->mesh.tets.empty() ? mesh->mesh.tets.data() : nullptr;
}

LFEM_API lfem_status lfem_mesh_translate(lfem_mesh* mesh, const double offset[3]) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(mesh, "mesh");
        require_pointer(offset, "offset");
        require_finite(offset, 3, "offset");
        std::vector<double> moved = mesh->mesh.positions;
        for (std::size_t i = 0; i < moved.size(); ++i) moved[i] += offset[i % 3];
        commit_positions(mesh, std::move(moved));
    });
}

LFEM_API lfem_status lfem_mesh_rotate(lfem_mesh* mesh, const double axis[3], double angle) {
    return lfem::api::guard(__func__, [&] {
        require_pointer(mesh, "mesh");
        require_pointer(axis, "axis");
        require_finite(axis, 3, "axis");
        require_finite_value(angle, "angle");
        // Unit axis. Scaling by the largest component first keeps the squares from
        // overflowing (axis 1e200) or underflowing (axis 1e-200) on the way.
        const double largest =
            std::fmax(std::fabs(axis[0]), std::fmax(std::fabs(axis[1]), std::fabs(axis[2])));
        require(largest > 0.0, "axis is the zero vector");
        double u[3] = {axis[0] / largest, axis[1] / largest, axis[2] / largest};
        const double length = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (double& c : u) c /= length;

        // Rodrigues: R = cos(a) I + sin(a) [u]x + (1 - cos(a)) u u^T.
        const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
        const double r[3][3] = {
            {c + t * u[0] * u[0], t * u[0] * u[1] - s * u[2], t * u[0] * u[2] + s * u[1]},
            {t * u[1] * u[0] + s * u[2], c + t * u[1] * u[1], t * u[1] * u[2] - s * u[0]},
            {t * u[2] * u[0] - s * u[1], t * u[2] * u[1] + s * u[0], c + t * u[2] * u[2]}};
        std::vector<double> moved = mesh->mesh.positions;
        for (std::size_t n = 0; n < moved.size(); n += 3) {
            const double x[3] = {moved[n], moved[n + 1], moved[n + 2]};
            for (int i = 0; i < 3; ++i)
                moved[n + i] = r[i][0] * x[0] + r[i][1] * x[1] + r[i][2] * x[2];
        }
        commit_positions(mesh, std::move(moved));
    });
}

}  // extern "C"
