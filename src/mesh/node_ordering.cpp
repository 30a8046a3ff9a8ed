#include "mesh/node_ordering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

#include "common/quadratic_tet_nodes.h"
#include "mesh/quadratic_mesh.h"

namespace lfem {
namespace {

// Mean edge length of the tets (each edge counted once per tet that has it; stride node
// indices per tet, the corners first): the size of a slab and of a row of the sweep order.
double mean_edge_length(const double* x, const uint32_t* tets, uint32_t stride, uint32_t tet_count) {
    static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    double sum = 0.0;
    for (uint32_t e = 0; e < tet_count; ++e)
        for (const auto& edge : kEdges) {
            const double* p = &x[3 * std::size_t(tets[std::size_t(stride) * e + edge[0]])];
            const double* q = &x[3 * std::size_t(tets[std::size_t(stride) * e + edge[1]])];
            sum += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                             (p[2] - q[2]) * (p[2] - q[2]));
        }
    return sum / (6.0 * tet_count);
}

// The sweep order: slabs across the longest axis of the mesh's box, rows across the next,
// nodes along the shortest. The element loop then reads nodes from a few nearly sequential
// streams (rows of neighbouring slabs), which the hardware prefetches, and consecutive blocks
// of tets touch only the slabs next to them (few colours, element_colouring.h). Slabs and rows
// are half a mean edge wide, so the planes of a structured grid never share one: a box mesh
// numbered plane by plane keeps its node order; 10-node tets have a plane of nodes every half
// edge, so theirs are a quarter edge wide. (A Morton curve, tried first, needed 18 colours
// instead of 8 on the 55^3 box, and its element loop ran slower.) Returns the given index of
// each new node.
std::vector<uint32_t> sweep_order(const double* x, uint32_t n, const uint32_t* tets, uint32_t stride, uint32_t t) {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = x[k];
    for (uint32_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], x[3 * i + k]);
            hi[k] = std::max(hi[k], x[3 * i + k]);
        }
    int axis[3] = {2, 1, 0};  // slowest first: by extent, ties kept in the order z, y, x
    for (int i = 1; i < 3; ++i)  // insertion sort (std::stable_sort may allocate)
        for (int j = i; j > 0 && hi[axis[j]] - lo[axis[j]] > hi[axis[j - 1]] - lo[axis[j - 1]]; --j)
            std::swap(axis[j], axis[j - 1]);
    const double h = (stride == kQuadraticTetNodes ? 0.25 : 0.5) * mean_edge_length(x, tets, stride, t);
    // The bin of a coordinate, finite whatever the mesh (coordinates near the largest double
    // can overflow the difference, a tiny h the quotient): the keys must order strictly.
    auto bin = [h](double d) {
        const double q = std::floor(d / h);
        return std::isnan(q) ? 0.0 : std::min(q, 1e300);
    };
    struct Key {
        double slab, row;
        double along, across, through;
        uint32_t index;
    };
    std::vector<Key> key(n);
    for (uint32_t i = 0; i < n; ++i) {
        const double* p = &x[3 * std::size_t(i)];
        key[i] = {bin(p[axis[0]] - lo[axis[0]]), bin(p[axis[1]] - lo[axis[1]]), p[axis[2]],
                  p[axis[1]], p[axis[0]], i};
    }
    std::sort(key.begin(), key.end(), [](const Key& a, const Key& b) {
        return std::tie(a.slab, a.row, a.along, a.across, a.through, a.index) <
               std::tie(b.slab, b.row, b.along, b.across, b.through, b.index);
    });
    std::vector<uint32_t> old_of_node(n);
    for (uint32_t i = 0; i < n; ++i) old_of_node[i] = key[i].index;
    return old_of_node;
}

// Turns a tet by an even permutation of its corners (so its orientation is kept; a 10-node
// tet's mid-edge nodes follow their edges) until its lowest corner comes first and, of the
// three rotations of the others, the lowest second.
void turn_to_lowest(uint32_t* t, uint32_t nodes_per_tet) {
    uint32_t v[4] = {t[0], t[1], t[2], t[3]};
    int from[4] = {0, 1, 2, 3};
    const auto swap = [&](int i, int j) { std::swap(v[i], v[j]), std::swap(from[i], from[j]); };
    const int low = int(std::min_element(v, v + 4) - v);
    if (low != 0) {  // swap corners 0 and low, and two others, to keep the orientation
        const int other[2] = {low == 1 ? 2 : 1, low == 3 ? 2 : 3};
        swap(0, low);
        swap(other[0], other[1]);
    }
    while (v[1] > v[2] || v[1] > v[3]) {  // rotate the last three (an even permutation)
        swap(1, 2);
        swap(2, 3);
    }
    permute_corners(t, nodes_per_tet, from);
}

}  // namespace

LocalityOrder order_for_locality(const double* positions, uint32_t node_count,
                                 const uint32_t* tets, uint32_t tet_count, uint32_t nodes_per_tet) {
    LocalityOrder order;
    const std::size_t stride = nodes_per_tet;
    const std::vector<uint32_t> old_of_node = sweep_order(positions, node_count, tets, nodes_per_tet, tet_count);
    order.node_of_old.resize(node_count);
    order.positions.resize(3 * std::size_t(node_count));
    for (uint32_t i = 0; i < node_count; ++i) {
        order.node_of_old[old_of_node[i]] = i;
        std::copy_n(&positions[3 * std::size_t(old_of_node[i])], 3, &order.positions[3 * std::size_t(i)]);
    }

    // Tets in the new numbering, each turned to its lowest node, then sorted by their nodes
    // (lowest first): the element loop walks the nodes from first to last, each tet touching
    // nodes near those of the tets before it.
    std::vector<uint32_t> turned(stride * tet_count);
    for (uint32_t e = 0; e < tet_count; ++e) {
        uint32_t* t = &turned[stride * e];
        for (std::size_t a = 0; a < stride; ++a) t[a] = order.node_of_old[tets[stride * e + a]];
        turn_to_lowest(t, nodes_per_tet);
    }
    auto key = [&](uint32_t e) {  // the tet's corners in ascending order
        std::array<uint32_t, 4> k;
        std::copy_n(&turned[stride * e], 4, k.begin());
        std::sort(k.begin(), k.end());
        return k;
    };
    order.old_of_tet.resize(tet_count);
    std::iota(order.old_of_tet.begin(), order.old_of_tet.end(), 0u);
    std::sort(order.old_of_tet.begin(), order.old_of_tet.end(), [&](uint32_t a, uint32_t b) {
        const std::array<uint32_t, 4> ka = key(a), kb = key(b);
        return ka != kb ? ka < kb : a < b;
    });
    order.tets.resize(stride * tet_count);
    for (uint32_t e = 0; e < tet_count; ++e)
        std::copy_n(&turned[stride * order.old_of_tet[e]], stride, &order.tets[stride * e]);
    return order;
}

void Numbering::append(const LocalityOrder& order, uint32_t old_nodes, uint32_t old_tets) {
    const uint32_t n = uint32_t(order.node_of_old.size()), t = uint32_t(order.old_of_tet.size());
    // Each map stays empty (no memory, nothing to translate) while every block kept its order.
    bool nodes_kept = node_of_api.empty(), tets_kept = api_of_tet.empty();
    for (uint32_t i = 0; i < n && nodes_kept; ++i) nodes_kept = order.node_of_old[i] == i;
    for (uint32_t e = 0; e < t && tets_kept; ++e) tets_kept = order.old_of_tet[e] == e;
    if (!nodes_kept) {
        if (node_of_api.empty()) {  // earlier meshes kept their order: spell it out
            node_of_api.resize(old_nodes);
            std::iota(node_of_api.begin(), node_of_api.end(), 0u);
            api_of_node = node_of_api;
        }
        node_of_api.resize(std::size_t(old_nodes) + n);
        api_of_node.resize(std::size_t(old_nodes) + n);
        for (uint32_t i = 0; i < n; ++i) {
            node_of_api[old_nodes + i] = old_nodes + order.node_of_old[i];
            api_of_node[old_nodes + order.node_of_old[i]] = old_nodes + i;
        }
    }
    if (!tets_kept) {
        if (api_of_tet.empty()) {
            api_of_tet.resize(old_tets);
            std::iota(api_of_tet.begin(), api_of_tet.end(), 0u);
        }
        api_of_tet.resize(std::size_t(old_tets) + t);
        for (uint32_t e = 0; e < t; ++e) api_of_tet[old_tets + e] = old_tets + order.old_of_tet[e];
    }
}

void Numbering::nodes_to_api(const double* internal, uint32_t node_count, double* api) const {
    for (uint32_t i = 0; i < node_count; ++i)
        std::copy_n(&internal[3 * std::size_t(i)], 3, &api[3 * std::size_t(api_node(i))]);
}

void Numbering::nodes_from_api(const double* api, uint32_t node_count, double* internal) const {
    for (uint32_t i = 0; i < node_count; ++i)
        std::copy_n(&api[3 * std::size_t(api_node(i))], 3, &internal[3 * std::size_t(i)]);
}

void Numbering::tets_to_api(const double* internal, uint32_t tet_count, double* api) const {
    for (uint32_t e = 0; e < tet_count; ++e) api[api_tet(e)] = internal[e];
}

void Numbering::tet_nodes_to_api(const uint32_t* internal, uint32_t tet_count, uint32_t nodes_per_tet,
                                 uint32_t* api) const {
    for (uint32_t e = 0; e < tet_count; ++e)
        for (uint32_t a = 0; a < nodes_per_tet; ++a)
            api[std::size_t(nodes_per_tet) * api_tet(e) + a] = api_node(internal[std::size_t(nodes_per_tet) * e + a]);
}

bool Numbering::consistent(uint32_t node_count, uint32_t tet_count) const {
    if (!node_of_api.empty() || !api_of_node.empty()) {
        if (node_of_api.size() != node_count || api_of_node.size() != node_count) return false;
        for (uint32_t i = 0; i < node_count; ++i)  // inverse of each other, so permutations
            if (api_of_node[i] >= node_count || node_of_api[api_of_node[i]] != i) return false;
    }
    if (!api_of_tet.empty()) {
        if (api_of_tet.size() != tet_count) return false;
        std::vector<uint8_t> seen(tet_count, 0);
        for (uint32_t e : api_of_tet) {
            if (e >= tet_count || seen[e]) return false;
            seen[e] = 1;
        }
    }
    return true;
}

}  // namespace lfem
