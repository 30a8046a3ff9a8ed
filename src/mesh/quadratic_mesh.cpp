// Edges as flat records sorted by their corner pair: the copies of an edge in its tets become
// neighbours, which both the conversion (one new node per edge) and the check (one mid-edge node
// per edge) need. No hash map: memory and run time do not depend on how the nodes are numbered.
#include "mesh/quadratic_mesh.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "common/error.h"
#include "common/quadratic_tet_nodes.h"

namespace lfem {
namespace {

struct EdgeRecord {
    uint32_t lo, hi;  // corner node indices, lo < hi
    uint32_t mid;     // the mid-edge node (quadratic meshes) or 0
    uint32_t tet;
    uint8_t local;    // which of kQuadraticTetEdges
};

bool edge_less(const EdgeRecord& a, const EdgeRecord& b) {
    return std::tie(a.lo, a.hi, a.mid, a.tet, a.local) < std::tie(b.lo, b.hi, b.mid, b.tet, b.local);
}

// The 6 edges of each tet (stride nodes per tet), sorted.
std::vector<EdgeRecord> sorted_edges(const uint32_t* tets, uint32_t tet_count, uint32_t stride) {
    std::vector<EdgeRecord> edges(6 * std::size_t(tet_count));
    for (uint32_t t = 0; t < tet_count; ++t)
        for (int e = 0; e < 6; ++e) {
            const uint32_t* tet = tets + std::size_t(stride) * t;
            const uint32_t a = tet[kQuadraticTetEdges[e][0]], b = tet[kQuadraticTetEdges[e][1]];
            edges[6 * std::size_t(t) + e] = {std::min(a, b), std::max(a, b), stride == kQuadraticTetNodes ? tet[4 + e] : 0,
                                             t, uint8_t(e)};
        }
    std::sort(edges.begin(), edges.end(), edge_less);
    return edges;
}

[[noreturn]] void invalid_mesh(const std::string& message) { throw Error(Status::invalid_mesh, message); }

std::string edge_name(const EdgeRecord& r) {
    return "the edge between nodes " + std::to_string(r.lo) + " and " + std::to_string(r.hi);
}

}  // namespace

TetMesh make_quadratic(const TetMesh& linear) {
    if (linear.nodes_per_tet != kLinearTetNodes)
        throw Error(Status::invalid_argument, "the mesh already has 10-node tets");
    const std::vector<EdgeRecord> edges = sorted_edges(linear.tets.data(), linear.tet_count(), kLinearTetNodes);
    TetMesh out;
    out.nodes_per_tet = kQuadraticTetNodes;
    out.positions = linear.positions;
    out.tets.resize(kQuadraticTetNodes * std::size_t(linear.tet_count()));
    for (uint32_t t = 0; t < linear.tet_count(); ++t)
        std::copy_n(&linear.tets[4 * std::size_t(t)], 4, &out.tets[kQuadraticTetNodes * std::size_t(t)]);
    uint64_t next = linear.node_count();
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const EdgeRecord& r = edges[i];
        if (i == 0 || r.lo != edges[i - 1].lo || r.hi != edges[i - 1].hi) {  // a new edge: its node
            if (next >= 0xFFFFFFF0ull) throw Error(Status::invalid_argument, "the quadratic mesh would pass 2^32 nodes");
            for (int k = 0; k < 3; ++k)
                out.positions.push_back(0.5 * (linear.positions[3 * std::size_t(r.lo) + k] +
                                               linear.positions[3 * std::size_t(r.hi) + k]));
            ++next;
        }
        out.tets[kQuadraticTetNodes * std::size_t(r.tet) + 4 + r.local] = uint32_t(next - 1);
    }
    return out;
}

void permute_corners(uint32_t* tet, uint32_t nodes_per_tet, const int from[4]) {
    uint32_t old[kQuadraticTetNodes];
    std::copy_n(tet, nodes_per_tet, old);
    for (int k = 0; k < 4; ++k) tet[k] = old[from[k]];
    if (nodes_per_tet != kQuadraticTetNodes) return;
    for (int e = 0; e < 6; ++e)
        tet[4 + e] = old[mid_edge_node(from[kQuadraticTetEdges[e][0]], from[kQuadraticTetEdges[e][1]])];
}

void check_quadratic_topology(const uint32_t* tets, uint32_t tet_count, uint32_t node_count) {
    const std::vector<EdgeRecord> edges = sorted_edges(tets, tet_count, kQuadraticTetNodes);
    for (std::size_t i = 1; i < edges.size(); ++i) {
        const EdgeRecord &a = edges[i - 1], &b = edges[i];
        if (a.lo == b.lo && a.hi == b.hi && a.mid != b.mid)
            invalid_mesh("tets " + std::to_string(a.tet) + " and " + std::to_string(b.tet) + " give " + edge_name(a) +
                         " different mid-edge nodes (" + std::to_string(a.mid) + " and " + std::to_string(b.mid) +
                         "): the mesh is not conforming");
    }
    // Each node's role: a corner, or the mid-edge node of one edge (its first record).
    constexpr uint64_t kNone = UINT64_MAX, kCorner = UINT64_MAX - 1;
    std::vector<uint64_t> role(node_count, kNone);
    for (uint32_t t = 0; t < tet_count; ++t)
        for (int k = 0; k < 4; ++k) role[tets[kQuadraticTetNodes * std::size_t(t) + k]] = kCorner;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const EdgeRecord& r = edges[i];
        uint64_t& mine = role[r.mid];
        if (mine == kCorner)
            invalid_mesh("node " + std::to_string(r.mid) + " is a corner of one tet and the mid-edge node of " +
                         edge_name(r) + " in tet " + std::to_string(r.tet));
        if (mine == kNone) {
            mine = i;
        } else if (edges[mine].lo != r.lo || edges[mine].hi != r.hi) {
            invalid_mesh("node " + std::to_string(r.mid) + " is the mid-edge node of both " + edge_name(edges[mine]) +
                         " and " + edge_name(r));
        }
    }
}

}  // namespace lfem
