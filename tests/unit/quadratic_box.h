// A box of 10-node tets with everything the element kernels read, and the helpers the
// element tests share (test_quadratic_element.cpp, test_composite_element.cpp): the forces at
// given positions, the largest of them, a displacement field applied.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "fem/element_colouring.h"
#include "fem/internal_forces.h"
#include "fem/lumped_mass.h"
#include "fem/quadratic_tet.h"
#include "mesh/boundary.h"
#include "mesh/mesh_builders.h"
#include "mesh/quadratic_mesh.h"

namespace lfem {
namespace test {

constexpr double kRho = 1000.0;
inline const double kSize[3] = {0.4, 0.3, 0.5};

inline TetMesh quadratic_box_mesh(uint32_t nx, uint32_t ny, uint32_t nz) {
    const uint32_t cells[3] = {nx, ny, nz};
    return make_quadratic(build_box(kSize, cells));
}

// A box of 10-node tets with everything the kernels read.
struct QuadraticBox {
    TetMesh mesh;
    std::vector<double> Jq_inv, qp_volume, volume, mass;
    ElementColouring colouring;
    std::vector<uint8_t> boundary;  // per node

    bool composite = false;  // the composite element (fem/composite_tet.h)

    explicit QuadraticBox(uint32_t nx, uint32_t ny, uint32_t nz, uint32_t block = 64, bool composite_tets = false)
        : QuadraticBox(quadratic_box_mesh(nx, ny, nz), block, composite_tets) {}
    // Any mesh of 10-node tets.
    QuadraticBox(TetMesh quadratic_mesh, uint32_t block, bool composite_tets) : composite(composite_tets) {
        mesh = std::move(quadratic_mesh);
        const uint32_t t = mesh.tet_count();
        Jq_inv.resize(36 * std::size_t(t)), qp_volume.resize(4 * std::size_t(t)), volume.resize(t);
        mass.assign(mesh.node_count(), 0.0);
        add_quadratic_reference_tets(mesh.positions.data(), mesh.tets.data(), 0, t, composite, Jq_inv.data(),
                                     qp_volume.data(), volume.data());
        add_lumped_mass(mesh.tets.data(), volume.data(), 0, t, kRho, mass.data(), 10);
        colouring = colour_element_blocks(mesh.tets.data(), t, mesh.node_count(), block, 10);
        boundary.assign(mesh.node_count(), 0);
        for (uint32_t i : extract_quadratic_boundary(mesh.tets.data(), t)) boundary[i] = 1;
    }
    ElementMesh view() const {
        ElementMesh m;
        m.X = mesh.positions, m.tets = mesh.tets, m.Dm_inv = Jq_inv, m.volume = volume, m.qp_volume = qp_volume;
        m.mass = mass, m.colouring = &colouring, m.nodes_per_tet = 10, m.composite = composite;
        return m;
    }
    uint32_t nodes() const { return mesh.node_count(); }
    const double* X(uint32_t i) const { return &mesh.positions[3 * std::size_t(i)]; }
};

struct Forces {
    std::vector<double> f;
    ElasticResult result;
};

// Elastic forces at positions x; the corotational warm start starts at identity, the paper
// model's frame is `frame`.
inline Forces forces_at(const QuadraticBox& box, Model model, const Lame& lame, const std::vector<double>& x,
                        const double frame[4] = nullptr) {
    static const double identity[4] = {1, 0, 0, 0};
    Forces out;
    out.f.assign(x.size(), 0.0);
    std::vector<float> rotations(16 * std::size_t(box.mesh.tet_count()), 0.0f);
    for (std::size_t k = 0; k < rotations.size(); k += 4) rotations[k] = 1.0f;
    ElasticState s;
    s.x = x, s.force = out.f, s.tet_rotation = rotations, s.frame = frame ? frame : identity;
    out.result = compute_elastic_forces(box.view(), Material{model, lame}, s);
    return out;
}

// The largest |f| over the interior nodes and over all nodes.
inline void largest_forces(const QuadraticBox& box, const std::vector<double>& f, double& interior, double& any) {
    interior = any = 0.0;
    for (uint32_t i = 0; i < box.nodes(); ++i) {
        const double n = std::sqrt(f[3 * i] * f[3 * i] + f[3 * i + 1] * f[3 * i + 1] + f[3 * i + 2] * f[3 * i + 2]);
        any = std::max(any, n);
        if (!box.boundary[i]) interior = std::max(interior, n);
    }
}

template <class Field>
std::vector<double> deformed(const QuadraticBox& box, const Field& u) {
    std::vector<double> x(box.mesh.positions);
    for (uint32_t i = 0; i < box.nodes(); ++i) {
        double d[3];
        u(box.X(i), d);
        for (int k = 0; k < 3; ++k) x[3 * i + k] += d[k];
    }
    return x;
}

}  // namespace test
}  // namespace lfem
