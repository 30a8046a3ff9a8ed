// Self-contact (issue 15): with lfem_body_def.self_contact, a body's boundary nodes meet its own
// boundary triangles (not those around them or next to those) through the same multipliers as
// contact between bodies.
//
// What "passing through itself" means here, measured from outside the library: a boundary
// node lying inside one of the body's own tets (all four barycentric coordinates above 0.02)
// that shares no node with the triangles around it. A body that keeps itself apart has none;
// the same scene without self-contact has many, so the measure would see a failure.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// The body's own surface around each node (the nodes of its boundary triangles), and whether
// a node is on the boundary: what the measure excludes.
struct OwnSurface {
    std::vector<std::vector<uint32_t>> ring;  // per node: the nodes of the triangles around it
    std::vector<uint32_t> boundary;
};

OwnSurface own_surface(lfem_world* w, lfem_body b, uint32_t nodes) {
    uint32_t count = 0;
    EXPECT_EQ(lfem_body_get_boundary_triangle_count(w, b, &count), LFEM_OK);
    std::vector<uint32_t> tri(3 * std::size_t(count));
    EXPECT_EQ(lfem_body_get_boundary_triangles(w, b, tri.data(), count), LFEM_OK);
    OwnSurface s;
    s.ring.resize(nodes);
    for (uint32_t t = 0; t < count; ++t)
        for (int v = 0; v < 3; ++v)
            for (int u = 0; u < 3; ++u) s.ring[tri[3 * t + v]].push_back(tri[3 * t + u]);
    for (uint32_t i = 0; i < nodes; ++i)
        if (!s.ring[i].empty()) s.boundary.push_back(i);
    return s;
}

// Boundary nodes inside a far tet of their own body (see the top of the file). Brute force
// with a box test: the meshes here are small.
int nodes_inside_own_tets(const std::vector<double>& x, const uint32_t* tets, uint32_t tet_count, const OwnSurface& s) {
    int count = 0;
    for (uint32_t e = 0; e < tet_count; ++e) {
        const uint32_t* q = tets + 4 * e;
        double lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = HUGE_VAL, hi[k] = -HUGE_VAL;
            for (int a = 0; a < 4; ++a) lo[k] = std::min(lo[k], x[3 * q[a] + k]), hi[k] = std::max(hi[k], x[3 * q[a] + k]);
        }
        for (uint32_t p : s.boundary) {
            const double* y = &x[3 * p];
            if (y[0] < lo[0] || y[0] > hi[0] || y[1] < lo[1] || y[1] > hi[1] || y[2] < lo[2] || y[2] > hi[2]) continue;
            bool near = false;
            for (int a = 0; a < 4; ++a)
                near = near || std::find(s.ring[p].begin(), s.ring[p].end(), q[a]) != s.ring[p].end();
            if (near) continue;
            count += depth_in_tet(x, q, y) > 0.02;
        }
    }
    return count;
}

struct Fold {
    int worst_inside = 0;    // the most boundary nodes inside own tets after any call
    uint32_t most_self = 0;  // the most self-contacts after any call
    double lowest = HUGE_VAL, highest = -HUGE_VAL, widest = 0;  // m, at the end
    std::vector<double> x_end;
};

// A soft bar (0.6 x 0.03 x 0.03 m, 24 x 2 x 2 cells, E = 2e4 Pa, corotational) dropped across
// a thin static rod (a capsule of radius 5 mm along y, 0.4 m above a floor): it folds over the
// rod and its halves swing in and meet below it.
Fold bar_over_rod(bool self_contact, uint32_t threads = 1, int calls = 90) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    World w(wd);
    add_plane_floor(w);
    lfem_body_def sd = lfem_body_def_default();
    sd.type = LFEM_BODY_STATIC;
    lfem_body rod{};
    EXPECT_EQ(lfem_body_create(w, &sd, &rod), LFEM_OK);
    lfem_shape_def capsule = lfem_shape_def_default();
    capsule.type = LFEM_SHAPE_CAPSULE;
    capsule.radius = 0.005;
    capsule.half_length = 0.1;
    capsule.center[2] = 0.4;
    capsule.rotation[0] = capsule.rotation[1] = std::sqrt(0.5);  // local z along world y
    capsule.rotation[2] = capsule.rotation[3] = 0.0;
    EXPECT_EQ(lfem_body_add_shape(w, rod, &capsule, nullptr), LFEM_OK) << lfem_last_error();
    Mesh bar;
    make_box_mesh(bar, 0.6, 0.03, 0.03, 24, 2, 2, -0.3, -0.015, 0.406);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 2e4;
    d.damping = 2;
    d.friction = 0.3;
    d.self_contact = self_contact;
    const lfem_body b = add_body(w, d, bar);
    const OwnSurface surface = own_surface(w, b, bar.nodes());
    Fold out;
    std::vector<lfem_contact> contacts(4096);
    for (int i = 0; i < calls; ++i) {
        EXPECT_EQ(lfem_world_step(w, 1.0 / 60), LFEM_OK) << lfem_last_error();
        const std::vector<double> x = positions(w, b);
        out.worst_inside = std::max(out.worst_inside, nodes_inside_own_tets(x, lfem_mesh_get_tets(bar.m), bar.tets(), surface));
        uint32_t count = 0, self = 0;
        EXPECT_EQ(lfem_world_query_contacts(w, contacts.data(), uint32_t(contacts.size()), &count), LFEM_OK);
        for (uint32_t k = 0; k < count; ++k) self += contacts[k].body_a.index == contacts[k].body_b.index;
        out.most_self = std::max(out.most_self, self);
    }
    out.x_end = positions(w, b);
    double xmin = HUGE_VAL, xmax = -HUGE_VAL;
    for (size_t k = 0; k < out.x_end.size(); k += 3) {
        xmin = std::min(xmin, out.x_end[k]), xmax = std::max(xmax, out.x_end[k]);
        out.lowest = std::min(out.lowest, out.x_end[k + 2]), out.highest = std::max(out.highest, out.x_end[k + 2]);
    }
    out.widest = xmax - xmin;
    return out;
}

}  // namespace

TEST(SelfContact, ASoftBarFoldsOverARodWithoutPassingThroughItself) {
    const Fold with = bar_over_rod(true), without = bar_over_rod(false);
    std::printf("bar over a rod: %d boundary nodes inside own tets at worst with self-contact (%u self-contacts "
                "at most), %d without\n",
                with.worst_inside, with.most_self, without.worst_inside);
    EXPECT_EQ(with.worst_inside, 0);
    EXPECT_GT(with.most_self, 0u);        // the halves did meet
    EXPECT_GT(without.worst_inside, 0);   // and without self-contact they pass through each other
    // It hangs folded over the rod: its top on the rod (0.4 m + 5 mm), its halves side by side
    // below it (0.6 m of bar within a few thicknesses across), clear of the floor.
    EXPECT_GT(with.highest, 0.405);
    EXPECT_LT(with.highest, 0.45);
    EXPECT_LT(with.widest, 0.2);
    EXPECT_GT(with.lowest, 0.05);
}

TEST(SelfContact, IsBitwiseTheSameOnOneAndTwoThreads) {
    const Fold one = bar_over_rod(true, 1, 40), two = bar_over_rod(true, 2, 40);
    ASSERT_EQ(one.x_end.size(), two.x_end.size());
    EXPECT_EQ(0, std::memcmp(one.x_end.data(), two.x_end.data(), one.x_end.size() * sizeof(double)));
}

TEST(SelfContact, IsRefusedForBodiesThatKeepTheirShapeAndForValuesOtherThanZeroOrOne) {
    World w;
    for (lfem_body_type type : {LFEM_BODY_STATIC, LFEM_BODY_KINEMATIC, LFEM_BODY_RIGID}) {
        lfem_body_def d = lfem_body_def_default();
        d.type = type;
        d.self_contact = 1;
        lfem_body b{};
        EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_INVALID_ARGUMENT) << type;
        EXPECT_NE(std::string(lfem_last_error()).find("self_contact"), std::string::npos) << lfem_last_error();
    }
    lfem_body_def d = lfem_body_def_default();
    d.self_contact = 2;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_INVALID_ARGUMENT);
    EXPECT_EQ(stats(w).body_count, 0u);  // nothing was created
}
