// Skins and queries on bodies of 10-node tets, against closed forms. A skin vertex is bound to
// its tet's ten nodes by the element's quadratic shape functions, so it follows what the
// element does: an affine motion (as on linear tets) and any quadratic displacement of a
// straight-sided element to round-off, and in a curved element (mid-edge nodes off their
// edges) the element's own map. Rays and boxes meet a 10-node body's surface as contact does:
// each 6-node face as the 4 flat triangles of its corner and mid-edge nodes.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "physics/lfem_test_util.h"
#include "physics/skin_test_meshes.h"

using namespace lfem_test;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A quadratic velocity field (1/s for the linear part's scale, 1/(m s) for the quadratic):
// every component a different quadratic monomial, so that each is interpolated in earnest.
std::array<double, 3> quadratic_field(const double* X) {
    const double x = X[0], y = X[1], z = X[2];
    return {0.5 * y * z + 0.3 * x, 2.0 * x * x - 0.4 * z, 1.5 * x * y + 0.2 * y};
}

// The largest distance between the skin's vertices and expected(p) over the vertices p given.
template <class Expected>
double worst_vertex_error(lfem_world* w, lfem_body b, uint32_t skin, const SkinMesh& given, const Expected& expected) {
    const SkinRead r = read_skin(w, b, skin);
    double worst = 0;
    for (uint32_t v = 0; v < given.vertices(); ++v) {
        const std::array<double, 3> e = expected(&given.x[3 * std::size_t(v)]);
        for (int d = 0; d < 3; ++d) worst = std::max(worst, std::fabs(r.x[3 * v + d] - e[d]));
    }
    return worst;
}

// The rounding a skin vertex carries after `steps` sub-steps: each node's position takes one
// rounding of eps |x| per sub-step (x += h v, |x| <= scale), and a vertex sums ten of them with
// weights N_a whose magnitudes add up to at most 17 for a vertex within one mean boundary edge
// of its tet (barycentric coordinates >= -1: at L = (-1, 1, 1/2, 1/2), the worst case, the
// corners give 3 + 1 and the mid-edge nodes 4 + 2 + 2 + 2 + 2 + 1), plus ten roundings of the
// sum itself: (17 + 10) eps scale per sub-step, and one more for the binding at rest.
double rounding_bound(uint64_t steps, double scale) { return 27.0 * kEps * scale * double(steps + 1); }

struct QuadraticBox {
    World world{no_gravity()};
    lfem_body body{};
    // A 0.2 x 0.1 x 0.1 m box of 4 x 2 x 2 cells of 10-node tets at the origin.
    explicit QuadraticBox(uint32_t nodes_per_tet = 10) {
        Mesh mesh;
        if (nodes_per_tet == 10) make_quadratic_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
        else make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
        body = add_body(world, lfem_body_def_default(), mesh);
    }
};

}  // namespace

TEST(QuadraticSkins, AffineMotionIsReproducedToRoundOff) {
    QuadraticBox s;
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    // Inside the tets, and up to 0.01 m outside on each axis (0.017 m at a corner, within the
    // mean boundary edge: the flat triangles of the 6-node faces, about 0.029 m).
    const SkinMesh inside = scattered(lo, hi, 0.0, 300, 11), around = scattered(lo, hi, 0.01, 300, 12);
    add_skin(s.world, s.body, inside);
    add_skin(s.world, s.body, around);
    const double B[9] = {2.0, 0.5, 0.0, 0.0, 0.5, 0.8, 0.0, 0.0, -1.0};
    prescribe_linear_motion(s.world, s.body, B);
    ASSERT_EQ(lfem_world_step(s.world, 0.1), LFEM_OK) << lfem_last_error();
    const lfem_world_stats st = stats(s.world);
    const auto map = [&](const double* p) { return linear_map(B, st.time, p); };
    const double worst = std::max(worst_vertex_error(s.world, s.body, 0, inside, map),
                                  worst_vertex_error(s.world, s.body, 1, around, map));
    const double bound = rounding_bound(st.steps, 0.3);
    std::printf("10-node tets, affine motion over %llu sub-steps: largest skin vertex error %.3g m (bound %.3g m)\n",
                (unsigned long long)st.steps, worst, bound);
    EXPECT_LE(worst, bound);
    EXPECT_GT(st.steps, 1u);
}

TEST(QuadraticSkins, QuadraticDisplacementOfTheElementsIsReproduced) {
    // Every node moved by x = X + t u(X), u quadratic: a 10-node tet's shape functions
    // interpolate u exactly, so a vertex at p goes to p + t u(p) to round-off. The same skin
    // on the same mesh of 4-node tets follows the corners' linear interpolation of u instead,
    // off by about t |u''| h^2 / 8 (h = 0.05 m): the test can tell the two apart.
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    const SkinMesh skin = scattered(lo, hi, 0.0, 300, 13);
    double worst[2] = {0, 0};
    uint64_t steps = 0;
    for (uint32_t kind : {10u, 4u}) {
        QuadraticBox s(kind);
        add_skin(s.world, s.body, skin);
        prescribe_motion(s.world, s.body, quadratic_field);
        ASSERT_EQ(lfem_world_step(s.world, 0.1), LFEM_OK) << lfem_last_error();
        const lfem_world_stats st = stats(s.world);
        if (kind == 10) steps = st.steps;
        worst[kind == 10 ? 0 : 1] = worst_vertex_error(s.world, s.body, 0, skin, [&](const double* p) {
            const std::array<double, 3> u = quadratic_field(p);
            return std::array<double, 3>{p[0] + st.time * u[0], p[1] + st.time * u[1], p[2] + st.time * u[2]};
        });
    }
    const double bound = rounding_bound(steps, 0.3);
    std::printf("quadratic displacement: largest skin vertex error %.3g m on 10-node tets (bound %.3g m), "
                "%.3g m on 4-node tets\n",
                worst[0], bound, worst[1]);
    EXPECT_LE(worst[0], bound);
    // The linear tets' interpolation error: t * 4 / m (u_y'' = 4) * h^2 / 8 ~ 1e-4 m at most;
    // anywhere near it is far above the round-off of the 10-node skin.
    EXPECT_GT(worst[1], 1e-6);
}

TEST(QuadraticSkins, CurvedElementsCarryVerticesByTheirOwnMap) {
    // The box's nodes placed by phi(X) = (x, y, z + k x^2): the mid-edge nodes sit off the
    // straight edges of the corners (by k (h/2)^2 = 1.25e-3 m on the x edges), and as phi is
    // quadratic the curved elements are exactly its image of the straight ones. A vertex given
    // at phi(p) is then bound at the element coordinates of p (Newton's iterations in the
    // element), and a field u quadratic in the straight box's coordinates (v_i = u(X_i)
    // prescribed on the curved nodes) carries it to phi(p) + t u(p): the corners' barycentric
    // weights alone would miss it by about t |u''| h^2 / 8.
    constexpr double k = 2.0;  // 1/m
    Mesh mesh;
    make_quadratic_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
    const double* X = lfem_mesh_get_positions(mesh.m);
    const auto phi = [&](const double* p) { return std::array<double, 3>{p[0], p[1], p[2] + k * p[0] * p[0]}; };
    std::vector<double> curved(3 * std::size_t(mesh.nodes()));
    for (uint32_t i = 0; i < mesh.nodes(); ++i) {
        const std::array<double, 3> c = phi(&X[3 * std::size_t(i)]);
        std::copy(c.begin(), c.end(), &curved[3 * std::size_t(i)]);
    }
    World world(no_gravity());
    lfem_body body{};
    const lfem_body_def def = lfem_body_def_default();
    ASSERT_EQ(lfem_body_create(world, &def, &body), LFEM_OK);
    ASSERT_EQ(lfem_body_add_quadratic_mesh(world, body, curved.data(), mesh.nodes(), lfem_mesh_get_tets(mesh.m),
                                           mesh.tets()),
              LFEM_OK)
        << lfem_last_error();
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    const SkinMesh straight = scattered(lo, hi, 0.0, 300, 14);
    SkinMesh bent = straight;
    for (uint32_t v = 0; v < bent.vertices(); ++v) {
        const std::array<double, 3> c = phi(&straight.x[3 * std::size_t(v)]);
        std::copy(c.begin(), c.end(), &bent.x[3 * std::size_t(v)]);
    }
    add_skin(world, body, bent);
    // At rest the skin is where it was given (the weights reproduce the vertex).
    const double at_rest = worst_vertex_error(world, body, 0, straight, phi);
    for (uint32_t i = 0; i < mesh.nodes(); ++i) {
        const std::array<double, 3> u = quadratic_field(&X[3 * std::size_t(i)]);
        ASSERT_EQ(lfem_body_prescribe_node_velocity(world, body, &i, 1, u.data()), LFEM_OK) << lfem_last_error();
    }
    ASSERT_EQ(lfem_world_step(world, 0.1), LFEM_OK) << lfem_last_error();
    const lfem_world_stats st = stats(world);
    const double moved = worst_vertex_error(world, body, 0, straight, [&](const double* p) {
        const std::array<double, 3> c = phi(p), u = quadratic_field(p);
        return std::array<double, 3>{c[0] + st.time * u[0], c[1] + st.time * u[1], c[2] + st.time * u[2]};
    });
    // Newton's iterations end at the rounding floor of the element's map (a few eps of its
    // 0.1 m size); the motion adds the rounding of the sub-steps.
    const double bound = rounding_bound(st.steps, 0.4);
    std::printf("curved 10-node elements: skin vertex error %.3g m at rest, %.3g m after the quadratic motion "
                "(bound %.3g m)\n",
                at_rest, moved, bound);
    EXPECT_LE(at_rest, 64 * kEps * 0.4);
    EXPECT_LE(moved, bound);
}

TEST(QuadraticSkins, CheckpointsKeepThem) {
    QuadraticBox s;
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    add_skin(s.world, s.body, scattered(lo, hi, 0.01, 90, 15));
    prescribe_motion(s.world, s.body, quadratic_field);
    ASSERT_EQ(lfem_world_step(s.world, 0.05), LFEM_OK) << lfem_last_error();
    expect_checkpoint_keeps(s.world, s.body, "quadratic_skins_checkpoint.bin");
}

TEST(QuadraticQueries, RaysAndBoxesMeetTheSurfaceOfTheMidEdgeNodes) {
    // Every node moved up by t c X^2 (c = 1 /(m s)): the top face z = 0.1 becomes, as contact
    // sees it, the flat triangles of its corner and mid-edge nodes, 0.025 m apart along x, on
    // which the height is the chord of 0.1 + t c x^2 between the nodes' x on either side,
    // xa <= x0 <= xb: z = 0.1 + t c (x0 (xa + xb) - xa xb), with normal (-t c (xa + xb), 0, 1)
    // normalised. The corners alone (0.05 m apart) would give a chord higher by
    // t c ((x0 - Xa)(Xb - x0) - (x0 - xa)(xb - x0)).
    QuadraticBox s;
    constexpr double c = 1.0;
    prescribe_motion(s.world, s.body, [](const double* X) { return std::array<double, 3>{0, 0, c * X[0] * X[0]}; });
    ASSERT_EQ(lfem_world_step(s.world, 0.5), LFEM_OK) << lfem_last_error();
    const double t = stats(s.world).time;
    const double x0 = 0.0375, y0 = 0.041, xa = 0.025, xb = 0.05;  // between the mid-edge and corner rows
    const double z_faces = 0.1 + t * c * (x0 * (xa + xb) - xa * xb);
    const double z_corners = 0.1 + t * c * (x0 * (0.0 + 0.05) - 0.0);  // corners at x = 0 and 0.05
    const double from[3] = {x0, y0, 1.0}, down[3] = {0, 0, -1};
    const Hit h = cast(s.world, from, down);
    ASSERT_TRUE(h.found);
    // Distances of order 1 from a few operations on node positions carrying ~1e-16 m of the
    // sub-steps' rounding: 1e-13 leaves three orders of magnitude.
    EXPECT_NEAR(h.h.distance, 1.0 - z_faces, 1e-13);
    const double slope = t * c * (xa + xb), len = std::sqrt(1 + slope * slope);
    EXPECT_NEAR(h.h.normal[0], -slope / len, 1e-12);
    EXPECT_NEAR(h.h.normal[1], 0.0, 1e-12);
    EXPECT_NEAR(h.h.normal[2], 1.0 / len, 1e-12);
    std::printf("10-node top face at x = %.4g: hit at z = %.15g (closed form %.15g; the corners' chord %.6g)\n", x0,
                1.0 - h.h.distance, z_faces, z_corners);
    // The triangle hit is one of lfem_body_get_boundary_triangles, two of its nodes a face's
    // mid-edge nodes, on the rows x = xa and xb.
    uint32_t nt = 0;
    ASSERT_EQ(lfem_body_get_boundary_triangle_count(s.world, s.body, &nt), LFEM_OK);
    std::vector<uint32_t> tri(3 * std::size_t(nt));
    ASSERT_EQ(lfem_body_get_boundary_triangles(s.world, s.body, tri.data(), nt), LFEM_OK);
    ASSERT_LT(h.h.triangle, nt);
    const std::vector<double> x = positions(s.world, s.body);
    for (int v = 0; v < 3; ++v) {
        const double xv = x[3 * std::size_t(tri[3 * h.h.triangle + v])];
        EXPECT_TRUE(std::fabs(xv - xa) < 1e-12 || std::fabs(xv - xb) < 1e-12) << "node at x = " << xv;
    }
    // A small box between the two chords is outside the body; the same box just under the
    // faces' chord is inside it (the gap is t c (0.0375 * 0.0125 - 0.0125^2) = 1.6e-4 m here).
    const double gap = z_corners - z_faces, r = 0.05 * gap;
    ASSERT_GT(gap, 1e-4);
    const double above_lo[3] = {x0 - r, y0 - r, z_faces + 0.3 * gap}, above_hi[3] = {x0 + r, y0 + r, z_faces + 0.4 * gap};
    EXPECT_TRUE(overlap(s.world, above_lo, above_hi).empty());
    const double below_lo[3] = {x0 - r, y0 - r, z_faces - 0.4 * gap}, below_hi[3] = {x0 + r, y0 + r, z_faces - 0.3 * gap};
    const std::vector<lfem_body> in = overlap(s.world, below_lo, below_hi);
    ASSERT_EQ(in.size(), 1u);
    EXPECT_EQ(in[0].index, s.body.index);
}

TEST(QuadraticSkins, AFarVertexIsRefusedAndChangesNothing) {
    // The reach is one mean boundary edge of the flat triangles of the 6-node faces (about
    // 0.029 m here): 0.05 m beyond the x = 0.2 face is farther, and named in the message.
    QuadraticBox s;
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    add_skin(s.world, s.body, scattered(lo, hi, 0.0, 30, 16));
    SkinMesh far = scattered(lo, hi, 0.0, 30, 17);
    far.x[3 * 7] = 0.2 + 0.05;
    const std::vector<unsigned char> before = fingerprint(s.world, {s.body});
    EXPECT_EQ(lfem_body_add_skin(s.world, s.body, far.x.data(), far.vertices(), far.tri.data(), far.triangles(), nullptr),
              LFEM_INVALID_ARGUMENT);
    const std::string message = lfem_last_error();
    EXPECT_NE(message.find("vertex 7 "), std::string::npos) << message;
    EXPECT_EQ(fingerprint(s.world, {s.body}), before);
    uint32_t count = 0;
    ASSERT_EQ(lfem_body_get_skin_count(s.world, s.body, &count), LFEM_OK);
    EXPECT_EQ(count, 1u);
}
