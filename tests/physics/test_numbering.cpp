// A body keeps its nodes and tets in an order of its own, for locality (src/mesh/node_ordering.h),
// and the C API translates every index and per-node or per-tet array to the caller's
// numbering. That order is a function of the geometry alone, so a mesh given in any numbering
// must give the same simulation bit for bit: the test renumbers a mesh at random (nodes, tets,
// and the nodes inside each tet by an even permutation, which keeps its orientation) and
// compares everything the API reads back, translated through the permutation. Any index the
// shim forgot to translate (a fixed node, a node force, a contact's node or triangle, a stress)
// would act on or report a different material point and break the equality.
#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <set>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// A mesh held in plain arrays, with how it was renumbered from the builder's mesh.
struct Numbered {
    std::vector<double> x;
    std::vector<uint32_t> tets;
    std::vector<uint32_t> new_of_node, new_of_tet;  // identity for the builder's numbering
    uint32_t nodes_per_tet = 4;                      // 10: the corners, then edges (0,1), (1,2),
                                                     // (0,2), (0,3), (1,3), (2,3) (lfem.h)
    uint32_t tet_count() const { return uint32_t(tets.size() / nodes_per_tet); }
};

Numbered as_given(const Mesh& m) {
    Numbered out;
    out.nodes_per_tet = m.nodes_per_tet();
    out.x.assign(lfem_mesh_get_positions(m.m), lfem_mesh_get_positions(m.m) + 3 * m.nodes());
    out.tets.assign(lfem_mesh_get_tets(m.m), lfem_mesh_get_tets(m.m) + out.nodes_per_tet * m.tets());
    out.new_of_node.resize(m.nodes());
    std::iota(out.new_of_node.begin(), out.new_of_node.end(), 0u);
    out.new_of_tet.resize(m.tets());
    std::iota(out.new_of_tet.begin(), out.new_of_tet.end(), 0u);
    return out;
}

std::vector<uint32_t> random_permutation(uint32_t n, uint64_t& state) {
    std::vector<uint32_t> p(n);
    std::iota(p.begin(), p.end(), 0u);
    for (uint32_t i = n; i > 1; --i) {
        state ^= state << 13, state ^= state >> 7, state ^= state << 17;
        std::swap(p[i - 1], p[state % i]);
    }
    return p;
}

// The mid-edge node (4..9) of corners i and j of a 10-node tet.
uint32_t mid_of(uint32_t i, uint32_t j) {
    static const uint32_t edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    for (uint32_t e = 0; e < 6; ++e)
        if ((edges[e][0] == i && edges[e][1] == j) || (edges[e][0] == j && edges[e][1] == i)) return 4 + e;
    return 0;
}

Numbered shuffled(const Mesh& m, uint64_t seed) {
    static const uint32_t edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    const Numbered given = as_given(m);
    Numbered out;
    out.nodes_per_tet = given.nodes_per_tet;
    out.new_of_node = random_permutation(m.nodes(), seed);
    out.new_of_tet = random_permutation(m.tets(), seed);
    out.x.resize(given.x.size());
    for (uint32_t i = 0; i < m.nodes(); ++i)
        for (int k = 0; k < 3; ++k) out.x[3 * out.new_of_node[i] + k] = given.x[3 * i + k];
    out.tets.resize(given.tets.size());
    const uint32_t npt = given.nodes_per_tet;
    for (uint32_t e = 0; e < m.tets(); ++e) {
        const uint32_t* t = &given.tets[npt * e];
        uint32_t* u = &out.tets[npt * out.new_of_tet[e]];
        const uint32_t turn = out.new_of_tet[e] % 3;  // rotate the last three: orientation kept
        const uint32_t from[4] = {0, 1 + turn % 3, 1 + (1 + turn) % 3, 1 + (2 + turn) % 3};
        for (uint32_t a = 0; a < 4; ++a) u[a] = out.new_of_node[t[from[a]]];
        if (npt == 10)  // each mid-edge node goes with its edge
            for (uint32_t k = 0; k < 6; ++k) u[4 + k] = out.new_of_node[t[mid_of(from[edges[k][0]], from[edges[k][1]])]];
    }
    return out;
}

// Everything the scene's API calls read back, in the builder's numbering.
struct Outcome {
    std::vector<double> x, v, stress;
    std::set<std::array<uint32_t, 3>> boundary;  // each triangle from its lowest node
    std::vector<std::array<double, 11>> contacts;  // node, triangle, force, position (sorted)
    std::vector<uint32_t> fixed_found;
};

// A block of each model with its bottom-left edge fixed, a force on its top corner, dropped
// with a spin onto a second, static block of the same mesh: contact in both directions (the
// dynamic block's nodes against the static one's triangles and back).
Outcome run(lfem_model model, const Numbered& mesh, const Numbered& base_mesh, int calls = 20) {
    World w;
    lfem_body_def s = lfem_body_def_default();
    s.type = LFEM_BODY_STATIC;
    lfem_body base{};
    EXPECT_EQ(lfem_body_create(w, &s, &base), LFEM_OK);
    EXPECT_EQ(lfem_body_add_mesh(w, base, base_mesh.x.data(), uint32_t(base_mesh.x.size() / 3),
                                 base_mesh.tets.data(), base_mesh.tet_count()),
              LFEM_OK)
        << lfem_last_error();
    lfem_body_def d = lfem_body_def_default();
    d.model = model;
    d.young_modulus = 2e5;
    d.angular_velocity[2] = 2.0;
    d.linear_velocity[2] = -0.5;
    lfem_body body{};
    EXPECT_EQ(lfem_body_create(w, &d, &body), LFEM_OK);
    std::vector<double> x = mesh.x;
    for (std::size_t i = 2; i < x.size(); i += 3) x[i] += 0.0005;  // 0.5 mm above the base
    const uint32_t n = uint32_t(x.size() / 3), t = mesh.tet_count();
    const auto add = mesh.nodes_per_tet == 10 ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh;
    EXPECT_EQ(add(w, body, x.data(), n, mesh.tets.data(), t), LFEM_OK) << lfem_last_error();

    auto to_builder_node = [&](uint32_t api) {  // inverse of new_of_node
        return uint32_t(std::find(mesh.new_of_node.begin(), mesh.new_of_node.end(), api) -
                        mesh.new_of_node.begin());
    };
    Outcome out;
    const double lo[3] = {-1, -1, 0.1}, hi[3] = {1, -0.0299, 0.101};  // top edge at y = -0.03
    std::vector<uint32_t> edge = nodes_in_box(w, body, lo, hi);
    EXPECT_GT(edge.size(), 3u);
    for (uint32_t i : edge) out.fixed_found.push_back(to_builder_node(i));
    std::sort(out.fixed_found.begin(), out.fixed_found.end());
    // Release half the edge again and prescribe a downward velocity on a quarter: three node
    // modes. The fixed half is let go after 5 steps, so that the block reaches the base.
    EXPECT_EQ(lfem_body_fix_nodes(w, body, edge.data(), uint32_t(edge.size())), LFEM_OK);
    std::vector<uint32_t> some;
    for (uint32_t b : out.fixed_found)
        if (b % 2) some.push_back(mesh.new_of_node[b]);
    EXPECT_EQ(lfem_body_release_nodes(w, body, some.data(), uint32_t(some.size())), LFEM_OK);
    some.clear();
    for (uint32_t b : out.fixed_found)
        if (b % 4 == 1) some.push_back(mesh.new_of_node[b]);
    const double up[3] = {0, 0, -0.5};
    EXPECT_EQ(lfem_body_prescribe_node_velocity(w, body, some.data(), uint32_t(some.size()), up),
              LFEM_OK);
    const uint32_t corner = mesh.new_of_node[n - 1];  // the builder's last node: a top corner
    const double force[3] = {0.3, -0.2, 0.1};
    EXPECT_EQ(lfem_body_set_node_forces(w, body, &corner, 1, force), LFEM_OK);

    uint32_t most = 0;  // the scene must exercise contact
    for (int i = 0; i < calls; ++i) {
        if (i == 5) {
            some.clear();
            for (uint32_t b : out.fixed_found)
                if (b % 2 == 0) some.push_back(mesh.new_of_node[b]);
            EXPECT_EQ(lfem_body_release_nodes(w, body, some.data(), uint32_t(some.size())), LFEM_OK);
        }
        EXPECT_EQ(lfem_world_step(w, 1e-3), LFEM_OK) << lfem_last_error();
        most = std::max(most, stats(w).contact_count);
    }
    EXPECT_GT(most, 10u);

    const std::vector<double> xa = positions(w, body), va = velocities(w, body);
    out.x.resize(xa.size()), out.v.resize(va.size());
    for (uint32_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            out.x[3 * i + k] = xa[3 * mesh.new_of_node[i] + k];
            out.v[3 * i + k] = va[3 * mesh.new_of_node[i] + k];
        }
    std::vector<double> stress(t);
    EXPECT_EQ(lfem_body_get_von_mises_stress(w, body, stress.data(), t), LFEM_OK);
    out.stress.resize(t);
    for (uint32_t e = 0; e < t; ++e) out.stress[e] = stress[mesh.new_of_tet[e]];
    uint32_t tris = 0;
    lfem_body_get_boundary_triangle_count(w, body, &tris);
    std::vector<uint32_t> tri(3 * tris);
    EXPECT_EQ(lfem_body_get_boundary_triangles(w, body, tri.data(), tris), LFEM_OK);
    for (uint32_t f = 0; f < tris; ++f) {
        std::array<uint32_t, 3> b = {to_builder_node(tri[3 * f]), to_builder_node(tri[3 * f + 1]),
                                     to_builder_node(tri[3 * f + 2])};
        std::rotate(b.begin(), std::min_element(b.begin(), b.end()), b.end());  // keeps the turn
        out.boundary.insert(b);
    }
    uint32_t count = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> c(count);
    EXPECT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
    for (std::size_t i = 1; i < count; ++i)  // the promised order, in the caller's numbering
        EXPECT_TRUE(c[i - 1].body_a.index < c[i].body_a.index ||
                    (c[i - 1].body_a.index == c[i].body_a.index && c[i - 1].node <= c[i].node));
    const Numbered* of_body[2] = {&base_mesh, &mesh};
    for (const lfem_contact& k : c) {
        const Numbered& a = *of_body[k.body_a.index == body.index];
        const Numbered& b = *of_body[k.body_b.index == body.index];
        auto builder = [](const Numbered& m, uint32_t api) {
            return double(std::find(m.new_of_node.begin(), m.new_of_node.end(), api) -
                          m.new_of_node.begin());
        };
        out.contacts.push_back({double(k.body_a.index), builder(a, k.node),
                                builder(b, k.triangle[0]), builder(b, k.triangle[1]),
                                builder(b, k.triangle[2]), k.force[0], k.force[1], k.force[2],
                                k.position[0], k.position[1], k.position[2]});
    }
    std::sort(out.contacts.begin(), out.contacts.end());
    return out;
}

}  // namespace

// calls: steps of 1 ms, ending while the block touches the base.
void expect_numbering_free(bool quadratic, std::initializer_list<lfem_model> models, int calls) {
    Mesh block;
    if (quadratic)
        make_quadratic_box_mesh(block, 0.1, 0.06, 0.1, 5, 3, 5, -0.05, -0.03, 0.0);
    else
        make_box_mesh(block, 0.1, 0.06, 0.1, 5, 3, 5, -0.05, -0.03, 0.0);
    Mesh base_box;
    make_box_mesh(base_box, 0.2, 0.2, 0.1, 6, 6, 3, -0.1, -0.1, -0.1);
    const Numbered block_given = as_given(block), base_given = as_given(base_box);
    const Numbered block_shuffled = shuffled(block, 0x9E3779B97F4A7C15ull);
    const Numbered base_shuffled = shuffled(base_box, 0xD1B54A32D192ED03ull);
    for (lfem_model model : models) {
        SCOPED_TRACE("model " + std::to_string(int(model)));
        const Outcome a = run(model, block_given, base_given, calls);
        const Outcome b = run(model, block_shuffled, base_shuffled, calls);
        // Bitwise: the body's internal order, and so every sum, is the same in both runs.
        EXPECT_EQ(a.fixed_found, b.fixed_found);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.v, b.v);
        EXPECT_EQ(a.stress, b.stress);
        EXPECT_EQ(a.boundary, b.boundary);
        EXPECT_EQ(a.contacts, b.contacts);
        EXPECT_GT(a.contacts.size(), 3u);  // compared while the block touches the base
    }
}

TEST(Numbering, ResultsDoNotDependOnHowTheCallerNumbersTheMesh) {
    expect_numbering_free(false, {LFEM_MODEL_LINEAR, LFEM_MODEL_PAPER, LFEM_MODEL_NEO_HOOKEAN, LFEM_MODEL_COROTATIONAL},
                          20);
}

// The same for 10-node tets, renumbered with their mid-edge nodes following their edges: the
// shim's translation of 10 nodes a tet, and the order of node_ordering.h, keep every bit.
TEST(Numbering, QuadraticResultsDoNotDependOnHowTheCallerNumbersTheMesh) {
    expect_numbering_free(true, {LFEM_MODEL_PAPER, LFEM_MODEL_COROTATIONAL}, 12);
}

// Right after add_mesh, before any step, every per-node and per-tet quantity read back is the
// one given, in the caller's order: positions exactly, velocities from the body def, stresses
// zero, and the boundary made of the caller's node indices.
TEST(Numbering, ReadBackIsInTheCallersNumbering) {
    Mesh block;
    make_box_mesh(block, 0.1, 0.1, 0.1, 4, 4, 4);
    const Numbered mesh = shuffled(block, 12345);
    World w;
    lfem_body_def d = lfem_body_def_default();
    d.linear_velocity[0] = 1.0;
    d.angular_velocity[2] = 1.0;
    lfem_body body{};
    ASSERT_EQ(lfem_body_create(w, &d, &body), LFEM_OK);
    const uint32_t n = uint32_t(mesh.x.size() / 3);
    ASSERT_EQ(lfem_body_add_mesh(w, body, mesh.x.data(), n, mesh.tets.data(),
                                 uint32_t(mesh.tets.size() / 4)),
              LFEM_OK);
    EXPECT_EQ(positions(w, body), mesh.x);
    // v = v0 + omega x (x - c), c = (0.05, 0.05, 0.05): checks that each velocity belongs to
    // its own node's position. 1e-12 m/s: the centre of mass is a sum of 125 rounded terms.
    const std::vector<double> v = velocities(w, body);
    for (uint32_t i = 0; i < n; ++i) {
        EXPECT_NEAR(v[3 * i], 1.0 - (mesh.x[3 * i + 1] - 0.05), 1e-12);
        EXPECT_NEAR(v[3 * i + 1], mesh.x[3 * i] - 0.05, 1e-12);
    }
    uint32_t tris = 0;
    lfem_body_get_boundary_triangle_count(w, body, &tris);
    std::vector<uint32_t> tri(3 * tris);
    ASSERT_EQ(lfem_body_get_boundary_triangles(w, body, tri.data(), tris), LFEM_OK);
    for (uint32_t f = 0; f < tris; ++f) {  // outward: (b - a) x (c - a) points away from the centre
        const double* a = &mesh.x[3 * tri[3 * f]];
        const double* b = &mesh.x[3 * tri[3 * f + 1]];
        const double* c = &mesh.x[3 * tri[3 * f + 2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double s[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double nrm[3] = {u[1] * s[2] - u[2] * s[1], u[2] * s[0] - u[0] * s[2],
                               u[0] * s[1] - u[1] * s[0]};
        const double out = nrm[0] * (a[0] - 0.05) + nrm[1] * (a[1] - 0.05) + nrm[2] * (a[2] - 0.05);
        EXPECT_GT(out, 0.0) << "triangle " << f;
    }
}
