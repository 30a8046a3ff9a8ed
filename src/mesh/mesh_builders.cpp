// Structured tet meshes of a box, a cylinder, a cup and a hammer.
//
// Two ways of cutting cells into tets keep neighbouring cells conforming:
// - hexahedra of a tensor grid (box, hammer): the Kuhn split into 6 tets around the diagonal
//   from the cell's lowest corner to its highest. Every cell uses the same diagonal direction,
//   so the two cells on either side of a quad face cut it along the same diagonal.
// - triangular prisms (cylinder, cup: a triangulated polar cross-section extruded along z):
//   each quad side face is cut along the diagonal through its lowest global node index. The
//   choice depends only on the face's four nodes, so both prisms sharing the face agree, and a
//   global order never gives the cyclic diagonal pattern that a prism cannot be split with.
// Every builder finally runs the full mesh check, so parameters that are valid one by one but
// produce degenerate tets (e.g. absurd aspect ratios) are refused instead of returned.
#include "mesh/mesh_builders.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "common/error.h"
#include "common/format.h"
#include "mesh/mesh_check.h"
#include "mesh/tet_geometry.h"

namespace lfem {
namespace {

// Beyond this many tets a builder refuses: ~1.6 GB of tets and positions is no longer "a
// scene", and the limit keeps every node and face index far from 32-bit overflow.
constexpr double kMaxTets = 50e6;
constexpr double kPi = 3.14159265358979323846;

std::string number(double v) { return format_number(v, 9); }

[[noreturn]] void invalid(const std::string& what) { throw Error(Status::invalid_argument, what); }

void require_length(double value, const std::string& name) {
    if (!(std::isfinite(value) && value > 0.0))
        invalid(name + " must be finite and > 0 (got " + number(value) + ")");
}

void require_count(uint32_t value, uint32_t minimum, const std::string& name) {
    if (value < minimum)
        invalid(name + " must be >= " + std::to_string(minimum) + " (got " + std::to_string(value) +
                ")");
}

// tets: the count the parameters would produce, computed in floating point so the check
// itself cannot overflow.
void require_tet_budget(double tets, const char* shape) {
    if (!(tets <= kMaxTets))
        invalid(std::string("the ") + shape + " would have " + number(tets) +
                " tets, more than the limit of " + number(kMaxTets));
}

uint32_t add_node(TetMesh& m, double x, double y, double z) {
    const uint32_t index = m.node_count();
    m.positions.insert(m.positions.end(), {x, y, z});
    return index;
}

// Appends a tet, swapping two nodes when it would be negatively oriented. Builders only cut
// boxes and right prisms, so no tet is flat unless the parameters are absurd, which finish()
// reports.
void add_tet(TetMesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const double* p = m.positions.data();
    if (tet_geometry::six_volume(p + 3 * std::size_t(a), p + 3 * std::size_t(b),
                                 p + 3 * std::size_t(c), p + 3 * std::size_t(d)) < 0.0)
        std::swap(c, d);
    m.tets.insert(m.tets.end(), {a, b, c, d});
}

// corner[bx + 2*by + 4*bz] is the corner at the low (0) or high (1) end of each axis. The 6
// tets are the monotone paths from corner 0 to corner 7, one per order of the three axes.
// `mirror` reflects the split along the axes whose bit is set. Mirroring every cell whose grid
// index is odd along an axis keeps neighbouring faces conforming (mirror images share their
// diagonal) and removes the bias of one diagonal direction repeated through the grid, which
// otherwise couples bending in y and z (a clamped square beam sagging under gravity drifted
// sideways by 17 % of its sag on a 2 x 2 section; mirrored, it does not).
void add_kuhn_hex(TetMesh& m, const uint32_t corner[8], uint32_t mirror) {
    static constexpr int kAxisOrders[6][3] = {{1, 2, 4}, {1, 4, 2}, {2, 1, 4},
                                              {2, 4, 1}, {4, 1, 2}, {4, 2, 1}};
    const auto c = [&](uint32_t b) { return corner[b ^ mirror]; };
    for (const auto& order : kAxisOrders)
        add_tet(m, c(0), c(order[0]), c(order[0] | order[1]), c(7));
}

uint32_t parity_mirror(uint32_t i, uint32_t j, uint32_t k) {
    return (i & 1u) | ((j & 1u) << 1) | ((k & 1u) << 2);
}

// prism[0..2]: bottom triangle, prism[3..5]: the nodes above them. Cut into 3 tets with every
// side quad split along the diagonal through its lowest node index.
void add_prism(TetMesh& m, const uint32_t prism[6]) {
    uint32_t v[6];
    std::copy(prism, prism + 6, v);
    // Relabel (top/bottom swap, rotation) so that the lowest index is v[0]. The two side
    // quads touching v[0] are then cut through v[0], and the corner tet (v0, v3, v4, v5)
    // comes off; what remains is a pyramid with apex v0 over the quad (v1, v2, v5, v4).
    const int lowest = int(std::min_element(v, v + 6) - v);
    if (lowest >= 3)
        for (int i = 0; i < 3; ++i) std::swap(v[i], v[i + 3]);
    const int shift = lowest % 3;
    const uint32_t r[6] = {v[shift],     v[(shift + 1) % 3],     v[(shift + 2) % 3],
                           v[3 + shift], v[3 + (shift + 1) % 3], v[3 + (shift + 2) % 3]};
    add_tet(m, r[0], r[3], r[4], r[5]);
    if (std::min(r[1], r[5]) < std::min(r[2], r[4])) {  // quad cut along v1-v5
        add_tet(m, r[0], r[1], r[2], r[5]);
        add_tet(m, r[0], r[1], r[5], r[4]);
    } else {  // quad cut along v2-v4
        add_tet(m, r[0], r[1], r[2], r[4]);
        add_tet(m, r[0], r[2], r[5], r[4]);
    }
}

// Removes nodes no tet uses, keeping the order of the others.
void drop_unused_nodes(TetMesh& m) {
    const uint32_t none = UINT32_MAX;
    std::vector<uint32_t> new_index(m.node_count(), none);
    for (uint32_t node : m.tets) new_index[node] = 0;
    uint32_t kept = 0;
    for (uint32_t n = 0; n < m.node_count(); ++n) {
        if (new_index[n] == none) continue;
        new_index[n] = kept;
        for (int i = 0; i < 3; ++i)
            m.positions[3 * std::size_t(kept) + i] = m.positions[3 * std::size_t(n) + i];
        ++kept;
    }
    m.positions.resize(3 * std::size_t(kept));
    for (uint32_t& node : m.tets) node = new_index[node];
}

// The last step of every builder: the promise of mesh_builders.h, checked.
TetMesh finish(TetMesh m, const char* shape) {
    for (double x : m.positions)
        if (!std::isfinite(x))
            invalid(std::string("the ") + shape +
                    " parameters put nodes at non-finite coordinates");
    try {
        check_tet_mesh(m.positions.data(), m.node_count(), m.tets.data(), m.tet_count());
    } catch (const Error& e) {
        invalid(std::string("the ") + shape + " parameters give a degenerate mesh (" + e.what() +
                ")");
    }
    return m;
}

// ---- polar cross-sections extruded along z (cylinder, cup) -------------------------------

// A triangulated disk: node 0 at the centre, ring r (1-based) node s at radius radii[r-1]
// and angle 2*pi*s/segments. Triangles counter-clockwise seen from +z.
struct PolarSection {
    std::vector<double> xy;           // 2 per node
    std::vector<uint32_t> triangles;  // 3 per triangle
    std::vector<uint32_t> ring;       // per triangle: the ring of its outer edge (1-based)
};

PolarSection polar_section(const std::vector<double>& radii, uint32_t segments) {
    PolarSection s;
    const uint32_t rings = uint32_t(radii.size());
    s.xy = {0.0, 0.0};
    for (uint32_t r = 1; r <= rings; ++r)
        for (uint32_t k = 0; k < segments; ++k) {
            const double angle = 2.0 * kPi * (double(k) / segments);
            s.xy.push_back(radii[r - 1] * std::cos(angle));
            s.xy.push_back(radii[r - 1] * std::sin(angle));
        }
    const auto node = [segments](uint32_t r, uint32_t k) {
        return 1 + (r - 1) * segments + k % segments;
    };
    for (uint32_t k = 0; k < segments; ++k) {  // centre fan
        s.triangles.insert(s.triangles.end(), {0, node(1, k), node(1, k + 1)});
        s.ring.push_back(1);
    }
    for (uint32_t r = 1; r < rings; ++r)  // quads between rings r and r+1, two triangles each
        for (uint32_t k = 0; k < segments; ++k) {
            s.triangles.insert(s.triangles.end(), {node(r, k), node(r + 1, k), node(r + 1, k + 1)});
            s.triangles.insert(s.triangles.end(), {node(r, k), node(r + 1, k + 1), node(r, k + 1)});
            s.ring.insert(s.ring.end(), {r + 1, r + 1});
        }
    return s;
}

// Extrudes the section through the z levels; triangle t fills the layers
// [0, layers_filled[t]) (layer l lies between z_levels[l] and z_levels[l+1]).
TetMesh extrude(const PolarSection& s, const std::vector<double>& z_levels,
                const std::vector<uint32_t>& layers_filled) {
    TetMesh m;
    const uint32_t per_level = uint32_t(s.xy.size() / 2);
    m.positions.reserve(3 * std::size_t(per_level) * z_levels.size());
    for (double z : z_levels)
        for (uint32_t p = 0; p < per_level; ++p) add_node(m, s.xy[2 * p], s.xy[2 * p + 1], z);
    for (std::size_t t = 0; t < layers_filled.size(); ++t) {
        const uint32_t* tri = &s.triangles[3 * t];
        for (uint32_t l = 0; l < layers_filled[t]; ++l) {
            const uint32_t below = l * per_level, above = (l + 1) * per_level;
            const uint32_t prism[6] = {tri[0] + below, tri[1] + below, tri[2] + below,
                                       tri[0] + above, tri[1] + above, tri[2] + above};
            add_prism(m, prism);
        }
    }
    drop_unused_nodes(m);
    return m;
}

// n + 1 values from a to b, the ends exact.
std::vector<double> even_steps(double a, double b, uint32_t n) {
    std::vector<double> v(n + 1);
    for (uint32_t i = 0; i <= n; ++i) v[i] = a + (b - a) * (double(i) / n);
    v[n] = b;
    return v;
}

// ---- tensor grids (hammer) ---------------------------------------------------------------

// The grid lines of one axis for the union of two boxes: every box face is a grid line, and
// each gap between face planes is cut into cells of about cell_size.
struct GridAxis {
    std::vector<double> lines;
    uint32_t low[2], high[2];  // per box: indices of its two face lines
};

GridAxis make_axis(const double low[2], const double high[2], double cell_size,
                   const char* const names[2]) {
    struct Plane {
        double at;
        int box;
        bool is_high;
    };
    Plane planes[4] = {
        {low[0], 0, false}, {high[0], 0, true}, {low[1], 1, false}, {high[1], 1, true}};
    std::sort(planes, planes + 4, [](const Plane& a, const Plane& b) { return a.at < b.at; });
    // Face planes closer than 1/1000 of a cell are merged (at their mean): the shape moves by
    // far less than the mesh resolves, and no layer of cells 1000 times thinner than asked
    // for (ruinous for the explicit time step) appears.
    const double merge = 1e-3 * cell_size;
    std::vector<double> planes_at;
    int cluster_of[4];
    for (int i = 0; i < 4;) {
        int end = i + 1;
        double sum = planes[i].at;
        while (end < 4 && planes[end].at - planes[end - 1].at <= merge) sum += planes[end++].at;
        for (int k = i; k < end; ++k) cluster_of[k] = int(planes_at.size());
        planes_at.push_back(sum / (end - i));
        i = end;
    }
    GridAxis axis;
    std::vector<uint32_t> line_of_cluster;
    double axis_cells = 0.0;
    for (std::size_t c = 0; c + 1 < planes_at.size(); ++c) {
        const double gap = planes_at[c + 1] - planes_at[c];
        const double cells = std::max(1.0, std::round(gap / cell_size));
        // The two boxes overlap on every axis, so each cell of the axis belongs to a box, and
        // that box's 6 tets per cell give at least 3 tets per axis cell overall. Checked
        // here, before the lines are allocated.
        axis_cells += cells;
        if (!(3.0 * axis_cells <= kMaxTets))
            invalid("cell_size " + number(cell_size) + " is too small: the hammer would need " +
                    "more than " + number(kMaxTets) + " tets");
        line_of_cluster.push_back(uint32_t(axis.lines.size()));
        const std::vector<double> steps =
            even_steps(planes_at[c], planes_at[c + 1], uint32_t(cells));
        axis.lines.insert(axis.lines.end(), steps.begin(), steps.end() - 1);
    }
    line_of_cluster.push_back(uint32_t(axis.lines.size()));
    axis.lines.push_back(planes_at.back());
    for (int k = 0; k < 4; ++k) {
        uint32_t& index = planes[k].is_high ? axis.high[planes[k].box] : axis.low[planes[k].box];
        index = line_of_cluster[cluster_of[k]];
    }
    for (int b = 0; b < 2; ++b)
        if (axis.low[b] == axis.high[b])
            invalid(std::string(names[b]) + " is below 1/1000 of cell_size " + number(cell_size) +
                    ": cell_size is too big to mesh it");
    return axis;
}

// A block of grid cells [low, high) per axis.
struct CellBlock {
    uint32_t low[3], high[3];
    double count() const {
        return double(high[0] - low[0]) * double(high[1] - low[1]) * double(high[2] - low[2]);
    }
    bool contains(uint32_t i, uint32_t j, uint32_t k) const {
        return low[0] <= i && i < high[0] && low[1] <= j && j < high[1] && low[2] <= k &&
               k < high[2];
    }
};

}  // namespace

TetMesh build_box(const double size[3], const uint32_t cells[3]) {
    for (int a = 0; a < 3; ++a) {
        require_length(size[a], "size[" + std::to_string(a) + "]");
        require_count(cells[a], 1, "cells[" + std::to_string(a) + "]");
    }
    require_tet_budget(6.0 * double(cells[0]) * double(cells[1]) * double(cells[2]), "box");

    const uint32_t nx = cells[0] + 1, ny = cells[1] + 1, nz = cells[2] + 1;
    TetMesh m;
    m.positions.reserve(3 * std::size_t(nx) * ny * nz);
    m.tets.reserve(24 * std::size_t(cells[0]) * cells[1] * cells[2]);
    const std::vector<double> xs = even_steps(0.0, size[0], cells[0]);
    const std::vector<double> ys = even_steps(0.0, size[1], cells[1]);
    const std::vector<double> zs = even_steps(0.0, size[2], cells[2]);
    for (double z : zs)
        for (double y : ys)
            for (double x : xs) add_node(m, x, y, z);
    for (uint32_t k = 0; k < cells[2]; ++k)
        for (uint32_t j = 0; j < cells[1]; ++j)
            for (uint32_t i = 0; i < cells[0]; ++i) {
                uint32_t corner[8];
                for (uint32_t b = 0; b < 8; ++b)
                    corner[b] = (i + (b & 1)) + nx * ((j + ((b >> 1) & 1)) + ny * (k + (b >> 2)));
                add_kuhn_hex(m, corner, parity_mirror(i, j, k));
            }
    return finish(std::move(m), "box");
}

TetMesh build_cylinder(double radius, double height, uint32_t segments, uint32_t rings,
                       uint32_t layers) {
    require_length(radius, "radius");
    require_length(height, "height");
    require_count(segments, 3, "segments");
    require_count(rings, 1, "rings");
    require_count(layers, 1, "layers");
    // segments * (2 rings - 1) triangles per layer, 3 tets per prism.
    require_tet_budget(3.0 * segments * (2.0 * rings - 1.0) * layers, "cylinder");

    std::vector<double> radii(rings);
    for (uint32_t r = 1; r <= rings; ++r) radii[r - 1] = radius * (double(r) / rings);
    const PolarSection section = polar_section(radii, segments);
    const std::vector<uint32_t> filled(section.ring.size(), layers);
    return finish(extrude(section, even_steps(0.0, height, layers), filled), "cylinder");
}

TetMesh build_cup(double outer_radius, double height, double wall, double bottom, uint32_t segments,
                  uint32_t layers) {
    require_length(outer_radius, "outer_radius");
    require_length(height, "height");
    require_length(wall, "wall");
    require_length(bottom, "bottom");
    require_count(segments, 3, "segments");
    require_count(layers, 1, "layers");
    if (!(wall < outer_radius))
        invalid("wall " + number(wall) + " must be less than outer_radius " + number(outer_radius) +
                " (a cup needs a cavity)");
    if (!(bottom < height))
        invalid("bottom " + number(bottom) + " must be less than height " + number(height) +
                " (a cup needs a cavity)");

    // One target cell size for the parts the caller did not divide: the smaller of the arc
    // between segments at the rim and the layer height of the wall.
    const double inner_radius = outer_radius - wall;
    const double cell = std::min(2.0 * kPi * outer_radius / segments, (height - bottom) / layers);
    const auto divisions = [cell](double length) {
        return std::max(1.0, std::round(length / cell));
    };
    const double disk_rings = divisions(inner_radius), wall_rings = divisions(wall),
                 bottom_layers = divisions(bottom);
    // Disk triangles fill the bottom layers; wall triangles fill every layer.
    require_tet_budget(3.0 * segments *
                           ((2.0 * disk_rings - 1.0) * bottom_layers +
                            2.0 * wall_rings * (bottom_layers + layers)),
                       "cup");
    const uint32_t n_disk = uint32_t(disk_rings), n_wall = uint32_t(wall_rings),
                   n_bottom = uint32_t(bottom_layers);

    std::vector<double> radii;
    for (uint32_t r = 1; r <= n_disk; ++r) radii.push_back(inner_radius * (double(r) / n_disk));
    for (uint32_t r = 1; r <= n_wall; ++r)
        radii.push_back(outer_radius - wall * (double(n_wall - r) / n_wall));
    const PolarSection section = polar_section(radii, segments);

    std::vector<double> z_levels = even_steps(0.0, bottom, n_bottom);
    for (uint32_t l = 1; l <= layers; ++l)
        z_levels.push_back(height - (height - bottom) * (double(layers - l) / layers));
    std::vector<uint32_t> filled(section.ring.size());
    for (std::size_t t = 0; t < filled.size(); ++t)
        filled[t] = section.ring[t] <= n_disk ? n_bottom : n_bottom + layers;
    return finish(extrude(section, z_levels, filled), "cup");
}

TetMesh build_hammer(double handle_length, double handle_width, double head_length,
                     double head_width, double cell_size) {
    require_length(handle_length, "handle_length");
    require_length(handle_width, "handle_width");
    require_length(head_length, "head_length");
    require_length(head_width, "head_width");
    require_length(cell_size, "cell_size");

    // Box 0: the handle, centred on the z axis from z = 0 up. Box 1: the head, centred on the
    // handle's top end (0, 0, handle_length).
    const double hw = 0.5 * handle_width;
    const double low[3][2] = {{-hw, -0.5 * head_length},
                              {-hw, -0.5 * head_width},
                              {0.0, handle_length - 0.5 * head_width}};
    const double high[3][2] = {{hw, 0.5 * head_length},
                               {hw, 0.5 * head_width},
                               {handle_length, handle_length + 0.5 * head_width}};
    static const char* const kNames[3][2] = {{"handle_width", "head_length"},
                                             {"handle_width", "head_width"},
                                             {"handle_length", "head_width"}};
    GridAxis axes[3];
    for (int a = 0; a < 3; ++a) axes[a] = make_axis(low[a], high[a], cell_size, kNames[a]);

    CellBlock blocks[2], overlap;
    for (int b = 0; b < 2; ++b)
        for (int a = 0; a < 3; ++a) {
            blocks[b].low[a] = axes[a].low[b];
            blocks[b].high[a] = axes[a].high[b];
        }
    for (int a = 0; a < 3; ++a) {
        overlap.low[a] = std::max(blocks[0].low[a], blocks[1].low[a]);
        overlap.high[a] = std::max(overlap.low[a], std::min(blocks[0].high[a], blocks[1].high[a]));
    }
    require_tet_budget(6.0 * (blocks[0].count() + blocks[1].count() - overlap.count()), "hammer");

    // The nodes: those of the handle block, then those of the head block not in the handle
    // block, sorted by grid id (z-major) so that node numbering follows the grid.
    const uint64_t nx = axes[0].lines.size(), ny = axes[1].lines.size();
    const auto grid_id = [nx, ny](uint64_t i, uint64_t j, uint64_t k) {
        return i + nx * (j + ny * k);
    };
    std::vector<uint64_t> node_ids;
    for (int b = 0; b < 2; ++b)
        for (uint32_t k = blocks[b].low[2]; k <= blocks[b].high[2]; ++k)
            for (uint32_t j = blocks[b].low[1]; j <= blocks[b].high[1]; ++j)
                for (uint32_t i = blocks[b].low[0]; i <= blocks[b].high[0]; ++i) {
                    const CellBlock& handle = blocks[0];
                    const bool in_handle_nodes = handle.low[0] <= i && i <= handle.high[0] &&
                                                 handle.low[1] <= j && j <= handle.high[1] &&
                                                 handle.low[2] <= k && k <= handle.high[2];
                    if (b == 0 || !in_handle_nodes) node_ids.push_back(grid_id(i, j, k));
                }
    std::sort(node_ids.begin(), node_ids.end());

    TetMesh m;
    m.positions.reserve(3 * node_ids.size());
    for (uint64_t id : node_ids)
        add_node(m, axes[0].lines[id % nx], axes[1].lines[(id / nx) % ny],
                 axes[2].lines[id / (nx * ny)]);
    const auto node_of = [&](uint64_t id) {
        return uint32_t(std::lower_bound(node_ids.begin(), node_ids.end(), id) - node_ids.begin());
    };
    for (int b = 0; b < 2; ++b)
        for (uint32_t k = blocks[b].low[2]; k < blocks[b].high[2]; ++k)
            for (uint32_t j = blocks[b].low[1]; j < blocks[b].high[1]; ++j)
                for (uint32_t i = blocks[b].low[0]; i < blocks[b].high[0]; ++i) {
                    if (b == 1 && blocks[0].contains(i, j, k)) continue;  // already meshed
                    uint32_t corner[8];
                    for (uint32_t c = 0; c < 8; ++c)
                        corner[c] = node_of(grid_id(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)));
                    add_kuhn_hex(m, corner, parity_mirror(i, j, k));
                }
    return finish(std::move(m), "hammer");
}

}  // namespace lfem
