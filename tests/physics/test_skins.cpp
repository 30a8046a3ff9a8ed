// Skins (lfem_body_add_skin): a render mesh bound to a body's tets follows them. Checked
// against closed forms: a body moved by a known linear map (every node prescribed v = B X, so
// x(t) = (I + t B) X) carries every skin vertex, inside a tet or just outside, to (I + t B) p,
// and its flat normals to the transformed face normals (I + t B)^-T n; a rigid body's and a
// kinematic body's skins turn with them; a sphere's smooth normals converge to the sphere's (and,
// stretched, the ellipsoid's) at second order. Several skins per body, the float vertex buffer
// with strides, checkpoints, and bad input refused with the world unchanged.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "physics/lfem_test_util.h"
#include "physics/skin_test_meshes.h"

using namespace lfem_test;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

struct SkinRead {
    std::vector<double> x, n;
};

SkinRead read_skin(lfem_world* w, lfem_body b, uint32_t skin) {
    uint32_t nv = 0;
    EXPECT_EQ(lfem_body_get_skin_sizes(w, b, skin, &nv, nullptr), LFEM_OK) << lfem_last_error();
    SkinRead r;
    r.x.resize(3 * std::size_t(nv));
    r.n.resize(3 * std::size_t(nv));
    EXPECT_EQ(lfem_body_get_skin_vertices(w, b, skin, r.x.data(), r.n.data(), nv), LFEM_OK) << lfem_last_error();
    return r;
}

uint32_t add_skin(lfem_world* w, lfem_body b, const SkinMesh& s) {
    uint32_t index = UINT32_MAX;
    EXPECT_EQ(lfem_body_add_skin(w, b, s.x.data(), s.vertices(), s.tri.data(), s.triangles(), &index), LFEM_OK)
        << lfem_last_error();
    return index;
}

// Random points in the box [lo, hi] grown by `out` on every side (out > 0: some just outside).
SkinMesh scattered(const double lo[3], const double hi[3], double out, uint32_t count, unsigned seed) {
    std::mt19937 rng(seed);
    SkinMesh s;
    for (uint32_t i = 0; i < count; ++i)
        for (int k = 0; k < 3; ++k)
            s.x.push_back(std::uniform_real_distribution<double>(lo[k] - out, hi[k] + out)(rng));
    for (uint32_t i = 0; i + 2 < count; i += 3) s.tri.insert(s.tri.end(), {i, i + 1, i + 2});
    return s;
}

// The cofactor matrix of a row-major 3x3 matrix: its inverse transposed times its determinant.
void cofactors(const double m[9], double c[9]) {
    const auto at = [&](int r, int k) { return m[3 * (r % 3) + k % 3]; };
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k)
            c[3 * r + k] = at(r + 1, k + 1) * at(r + 2, k + 2) - at(r + 1, k + 2) * at(r + 2, k + 1);
}

// The node of a body's mesh at position p (exactly, as the builder placed it).
uint32_t node_at(const std::vector<double>& X, double x, double y, double z) {
    for (uint32_t i = 0; i < X.size() / 3; ++i)
        if (std::fabs(X[3 * i] - x) + std::fabs(X[3 * i + 1] - y) + std::fabs(X[3 * i + 2] - z) < 1e-12) return i;
    ADD_FAILURE() << "no node at " << x << " " << y << " " << z;
    return 0;
}

// A 0.2 x 0.1 x 0.1 m box of 4 x 2 x 2 cells at the origin, no gravity: the body the linear
// map moves.
struct StretchedBox {
    World world{[] {
        lfem_world_def d = lfem_world_def_default();
        d.gravity[2] = 0.0;
        return d;
    }()};
    Mesh mesh;
    lfem_body body{};
    // Stretch along x, shear of y into x and z into y, squeeze along z (1/s).
    const double B[9] = {2.0, 0.5, 0.0, 0.0, 0.5, 0.8, 0.0, 0.0, -1.0};
    double time = 0.1;  // s: (I + t B) then stretches x by 1.2 and squeezes z by 0.9
    StretchedBox() {
        make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
        body = add_body(world, lfem_body_def_default(), mesh);
    }
    void move() {
        prescribe_linear_motion(world, body, B);
        ASSERT_EQ(lfem_world_step(world, time), LFEM_OK) << lfem_last_error();
    }
};

}  // namespace

TEST(Skins, AffineMotionOfTheTetsIsReproducedToRoundOff) {
    StretchedBox s;
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    // Inside the tets, and up to 0.02 m outside (the mean boundary edge is 0.05 m).
    const SkinMesh inside = scattered(lo, hi, 0.0, 300, 1), around = scattered(lo, hi, 0.02, 300, 2);
    add_skin(s.world, s.body, inside);
    add_skin(s.world, s.body, around);
    s.move();
    const lfem_world_stats st = stats(s.world);
    // The nodes carry the rounding of their sub-steps (x += h v, one rounding of ~eps |x| each),
    // and a vertex sums four of them with weights of magnitude below 3 (a vertex within one edge
    // outside its tet): (3 * 4 + 4) eps |x| per sub-step bounds the error.
    const double scale = 0.3;
    const double bound = 16.0 * kEps * scale * (st.steps + 1);
    double worst = 0;
    for (uint32_t k = 0; k < 2; ++k) {
        const SkinMesh& m = k == 0 ? inside : around;
        const SkinRead r = read_skin(s.world, s.body, k);
        for (uint32_t v = 0; v < m.vertices(); ++v) {
            const auto expected = linear_map(s.B, st.time, &m.x[3 * v]);
            for (int d = 0; d < 3; ++d) worst = std::max(worst, std::fabs(r.x[3 * v + d] - expected[d]));
        }
    }
    std::printf("affine motion over %llu sub-steps: largest skin vertex error %.3g m (bound %.3g m)\n",
                (unsigned long long)st.steps, worst, bound);
    EXPECT_LE(worst, bound);
    EXPECT_GT(st.steps, 1u);
}

TEST(Skins, FlatNormalsFollowTheInverseTransposeOfTheMotion) {
    StretchedBox s;
    // A box skin a little inside the body (flat faces: each vertex's normal is its face's).
    const double lo[3] = {0.01, 0.01, 0.01}, hi[3] = {0.19, 0.09, 0.09};
    const SkinMesh box = box_skin(lo, hi, 4);
    add_skin(s.world, s.body, box);
    const SkinRead rest = read_skin(s.world, s.body, 0);
    s.move();
    const SkinRead moved = read_skin(s.world, s.body, 0);
    // Closed form: a face normal n becomes (I + t B)^-T n, normalised: the cofactors of
    // (I + t B) times n, normalised.
    const double t = stats(s.world).time;
    double M[9], cof[9];
    for (int i = 0; i < 9; ++i) M[i] = (i % 4 == 0 ? 1.0 : 0.0) + t * s.B[i];
    cofactors(M, cof);
    double worst_rest = 0, worst = 0;
    for (uint32_t v = 0; v < box.vertices(); ++v) {
        const double* n0 = &rest.n[3 * v];
        // At rest the normal is exactly an axis.
        for (int d = 0; d < 3; ++d) worst_rest = std::max(worst_rest, std::fabs(std::fabs(n0[d]) - std::round(std::fabs(n0[d]))));
        double e[3], len = 0;
        for (int r = 0; r < 3; ++r) e[r] = cof[3 * r] * n0[0] + cof[3 * r + 1] * n0[1] + cof[3 * r + 2] * n0[2], len += e[r] * e[r];
        for (int r = 0; r < 3; ++r) worst = std::max(worst, std::fabs(moved.n[3 * v + r] - e[r] / std::sqrt(len)));
    }
    std::printf("flat normals: at rest %.3g from the axes, moved %.3g from (I + tB)^-T n\n", worst_rest, worst);
    // Each normal is a sum of cross products of vertex differences, whose rounding (the
    // vertices' own, above, over a face edge of 0.045 m) is ~1e-14 relative: 1e-12 leaves 100x.
    EXPECT_LE(worst_rest, 1e-14);
    EXPECT_LE(worst, 1e-12);
}

namespace {

// Area-weighted vertex normals of a mesh at the vertex positions x (the definition the skins
// follow), computed here from the closed-form positions.
std::vector<double> area_weighted_normals(const std::vector<double>& x, const std::vector<uint32_t>& tri) {
    std::vector<double> n(x.size(), 0.0);
    for (std::size_t f = 0; f < tri.size(); f += 3) {
        const double* a = &x[3 * tri[f]];
        const double* b = &x[3 * tri[f + 1]];
        const double* c = &x[3 * tri[f + 2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double w[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) n[3 * tri[f + k] + d] += w[d];
    }
    for (std::size_t i = 0; i < n.size(); i += 3) {
        const double len = std::sqrt(n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2]);
        for (int d = 0; d < 3; ++d) n[i + d] /= len;
    }
    return n;
}

// A sphere skinned in a cube, then stretched by diag(1.3, 0.9, 1.1) into an ellipsoid. The
// largest angle (rad) between its smooth normals and the surface's (radial at rest, the
// ellipsoid's A^-1 (p - c) stretched), and the largest difference from the area-weighted
// normals of the closed-form vertex positions.
struct SphereNormals {
    double at_rest = 0, stretched = 0, definition = 0;
};

SphereNormals sphere_normal_errors(int level) {
    World world{[] {
        lfem_world_def d = lfem_world_def_default();
        d.gravity[2] = 0.0;
        return d;
    }()};
    Mesh mesh;
    make_box_mesh(mesh, 0.2, 0.2, 0.2, 3, 3, 3, -0.1, -0.1, -0.1);
    const lfem_body body = add_body(world, lfem_body_def_default(), mesh);
    const double c[3] = {0, 0, 0};
    const SkinMesh sphere = sphere_skin(c, 0.08, level);
    add_skin(world, body, sphere);
    const auto angle_error = [&](const SkinRead& r, const double scale[3]) {
        double worst = 0;
        for (uint32_t v = 0; v < sphere.vertices(); ++v) {
            double e[3], len = 0, dot = 0;
            for (int k = 0; k < 3; ++k) e[k] = sphere.x[3 * v + k] / scale[k], len += e[k] * e[k];
            for (int k = 0; k < 3; ++k) dot += r.n[3 * v + k] * e[k] / std::sqrt(len);
            worst = std::max(worst, std::acos(std::min(1.0, dot)));
        }
        return worst;
    };
    SphereNormals out;
    const double one[3] = {1, 1, 1};
    out.at_rest = angle_error(read_skin(world, body, 0), one);
    const double B[9] = {3.0, 0, 0, 0, -1.0, 0, 0, 0, 1.0};
    prescribe_linear_motion(world, body, B);
    EXPECT_EQ(lfem_world_step(world, 0.1), LFEM_OK) << lfem_last_error();
    const double t = stats(world).time;
    const double scale[3] = {1 + 3 * t, 1 - t, 1 + t};  // x -> 1.3 x, y -> 0.9 y, z -> 1.1 z
    const SkinRead r = read_skin(world, body, 0);
    out.stretched = angle_error(r, scale);
    std::vector<double> exact(sphere.x);
    for (std::size_t i = 0; i < exact.size(); ++i) exact[i] *= scale[i % 3];
    const std::vector<double> n = area_weighted_normals(exact, sphere.tri);
    for (std::size_t i = 0; i < n.size(); ++i) out.definition = std::max(out.definition, std::fabs(n[i] - r.n[i]));
    return out;
}

}  // namespace

TEST(Skins, SmoothNormalsOfASphereMatchTheSurfaceAsTheMeshIsRefined) {
    // On this mesh (a subdivided octahedron: vertices of valence 4 and 6, triangles of unequal
    // size) area weighting is first-order: the normal's error is O(h), h the edge angle, and
    // halves with each refinement (Max 1999 shows second order only on symmetric stars). The
    // test asks for first order (ratio >= 1.8 of the ideal 2), an error below h / 2, and the
    // area-weighted definition itself met to round-off (1e-12: the vertices carry ~1e-15 m over
    // edges of 0.01 m) on the closed-form deformed positions.
    SphereNormals e[3];
    for (int level = 2; level <= 4; ++level) {
        e[level - 2] = sphere_normal_errors(level);
        const double h = (M_PI / 2) / (1 << level);  // edge angle of the subdivided octahedron
        std::printf("sphere level %d (edge %.3f rad): normal error %.3g rad at rest, %.3g rad stretched to an "
                    "ellipsoid; %.3g from the area-weighted normals of the exact positions\n",
                    level, h, e[level - 2].at_rest, e[level - 2].stretched, e[level - 2].definition);
        EXPECT_LE(e[level - 2].at_rest, 0.5 * h);
        EXPECT_LE(e[level - 2].stretched, 0.5 * h);
        EXPECT_LE(e[level - 2].definition, 1e-12);
    }
    for (int i = 0; i < 2; ++i) {
        EXPECT_GE(e[i].at_rest / e[i + 1].at_rest, 1.8);
        EXPECT_GE(e[i].stretched / e[i + 1].stretched, 1.8);
    }
}

TEST(Skins, SeveralSkinsPerBodyEachKeptAsGiven) {
    World world;
    Mesh mesh;
    make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
    const lfem_body body = add_body(world, lfem_body_def_default(), mesh);
    const double lo[3] = {0.02, 0.02, 0.02}, hi[3] = {0.18, 0.08, 0.08}, c[3] = {0.1, 0.05, 0.05};
    const SkinMesh a = box_skin(lo, hi, 2), b = sphere_skin(c, 0.04, 2), d = scattered(lo, hi, 0.0, 30, 3);
    EXPECT_EQ(add_skin(world, body, a), 0u);
    EXPECT_EQ(add_skin(world, body, b), 1u);
    EXPECT_EQ(add_skin(world, body, d), 2u);
    uint32_t count = 0;
    ASSERT_EQ(lfem_body_get_skin_count(world, body, &count), LFEM_OK);
    EXPECT_EQ(count, 3u);
    const SkinMesh* all[3] = {&a, &b, &d};
    for (uint32_t k = 0; k < 3; ++k) {
        uint32_t nv = 0, nt = 0;
        ASSERT_EQ(lfem_body_get_skin_sizes(world, body, k, &nv, &nt), LFEM_OK);
        EXPECT_EQ(nv, all[k]->vertices());
        EXPECT_EQ(nt, all[k]->triangles());
        std::vector<uint32_t> tri(3 * std::size_t(nt));
        ASSERT_EQ(lfem_body_get_skin_triangles(world, body, k, tri.data(), nt), LFEM_OK);
        EXPECT_EQ(tri, all[k]->tri);
        // At rest each vertex is where it was given (the weights reproduce it: a few roundings).
        const SkinRead r = read_skin(world, body, k);
        for (std::size_t i = 0; i < r.x.size(); ++i) EXPECT_NEAR(r.x[i], all[k]->x[i], 8 * kEps * 0.2);
    }
    // Falling under gravity, every skin moves with the body: by g t^2 / 2 in z (no contact).
    ASSERT_EQ(lfem_world_step(world, 0.05), LFEM_OK) << lfem_last_error();
    const double drop = 0.5 * 9.81 * 0.05 * 0.05;
    for (uint32_t k = 0; k < 3; ++k) {
        const SkinRead r = read_skin(world, body, k);
        for (std::size_t v = 0; v < r.x.size() / 3; ++v) {
            EXPECT_NEAR(r.x[3 * v], all[k]->x[3 * v], 1e-12);
            EXPECT_NEAR(r.x[3 * v + 2], all[k]->x[3 * v + 2] - drop, 1e-12);  // free fall: exact to round-off
        }
    }
}

TEST(Skins, RigidKinematicAndStaticBodiesCarryTheirSkins) {
    World world;
    Mesh mesh;
    make_box_mesh(mesh, 0.2, 0.1, 0.1, 2, 1, 1, -0.1, -0.05, -0.05);
    const double lo[3] = {-0.09, -0.04, -0.04}, hi[3] = {0.09, 0.04, 0.04};
    const SkinMesh skin = scattered(lo, hi, 0.02, 60, 4);
    lfem_body bodies[3];
    const lfem_body_type types[3] = {LFEM_BODY_RIGID, LFEM_BODY_KINEMATIC, LFEM_BODY_STATIC};
    for (int i = 0; i < 3; ++i) {
        lfem_body_def d = lfem_body_def_default();
        d.type = types[i];
        d.angular_velocity[0] = 3.0, d.angular_velocity[2] = 5.0;  // rad/s
        d.linear_velocity[1] = 1.0;
        d.category_bits = 1u << (i + 1), d.mask_bits = 0;  // no contact between them
        bodies[i] = add_body(world, d, mesh);
        add_skin(world, bodies[i], skin);
    }
    ASSERT_EQ(lfem_world_step(world, 0.2), LFEM_OK) << lfem_last_error();
    for (int i = 0; i < 3; ++i) {
        // A rigid motion: x = x0 + R (p - X0) from a node and the rotation: the rigid body's
        // own, the kinematic body's from three edges of node 0 (D1 D0^-1).
        const std::vector<double> x = positions(world, bodies[i]);
        const std::vector<double> X(lfem_mesh_get_positions(mesh.m), lfem_mesh_get_positions(mesh.m) + 3 * mesh.nodes());
        const uint32_t j0 = node_at(X, -0.1, -0.05, -0.05);
        const uint32_t edge[3] = {node_at(X, 0.0, -0.05, -0.05), node_at(X, -0.1, 0.05, -0.05), node_at(X, -0.1, -0.05, 0.05)};
        double R[9];
        if (types[i] == LFEM_BODY_RIGID) {
            ASSERT_EQ(lfem_body_get_rotation(world, bodies[i], R), LFEM_OK);
        } else {
            double D0[9], D1[9], C[9];
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k)
                    D0[3 * k + c] = X[3 * edge[c] + k] - X[3 * j0 + k], D1[3 * k + c] = x[3 * edge[c] + k] - x[3 * j0 + k];
            cofactors(D0, C);  // D0^-1 = C^T / det D0
            const double det = D0[0] * C[0] + D0[1] * C[1] + D0[2] * C[2];
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) {
                    R[3 * r + c] = 0;
                    for (int k = 0; k < 3; ++k) R[3 * r + c] += D1[3 * r + k] * C[3 * c + k] / det;
                }
        }
        const SkinRead r = read_skin(world, bodies[i], 0);
        double worst = 0, moved = 0;
        for (uint32_t v = 0; v < skin.vertices(); ++v) {
            const double* p = &skin.x[3 * v];
            double travel = 0;
            for (int k = 0; k < 3; ++k) {
                double e = x[3 * j0 + k];
                for (int c = 0; c < 3; ++c) e += R[3 * k + c] * (p[c] - X[3 * j0 + c]);
                worst = std::max(worst, std::fabs(r.x[3 * v + k] - e));
                travel += (r.x[3 * v + k] - p[k]) * (r.x[3 * v + k] - p[k]);
            }
            moved = std::max(moved, std::sqrt(travel));
        }
        std::printf("%s body: skin off its rigid motion by %.3g m, moved %.3g m\n",
                    i == 0 ? "rigid" : (i == 1 ? "kinematic" : "static"), worst, moved);
        // The nodes are placed by c + R (X - C) in one rounding each: 1e-14 m is 50 ulp at 0.3 m.
        EXPECT_LE(worst, 1e-14);
        if (types[i] == LFEM_BODY_STATIC) EXPECT_LE(moved, 1e-15);
        else EXPECT_GT(moved, 0.1);
    }
}

TEST(Skins, AMeshAddedLaterLeavesTheSkinBound) {
    World world;
    Mesh first, second;
    make_box_mesh(first, 0.1, 0.1, 0.1, 2, 2, 2);
    make_box_mesh(second, 0.1, 0.1, 0.1, 2, 2, 2, 0.5, 0, 0);
    const lfem_body body = add_body(world, lfem_body_def_default(), first);
    const double lo[3] = {0.01, 0.01, 0.01}, hi[3] = {0.09, 0.09, 0.09};
    const SkinMesh skin = box_skin(lo, hi, 2);
    add_skin(world, body, skin);
    const SkinRead before = read_skin(world, body, 0);
    ASSERT_EQ(lfem_body_add_mesh(world, body, lfem_mesh_get_positions(second.m), second.nodes(),
                                 lfem_mesh_get_tets(second.m), second.tets()),
              LFEM_OK);
    const SkinRead after = read_skin(world, body, 0);
    EXPECT_EQ(before.x, after.x);
    EXPECT_EQ(before.n, after.n);
    // A skin of the second mesh binds to it.
    const double lo2[3] = {0.51, 0.01, 0.01}, hi2[3] = {0.59, 0.09, 0.09};
    EXPECT_EQ(add_skin(world, body, box_skin(lo2, hi2, 2)), 1u);
}

TEST(Skins, FloatVertexBufferWithStrides) {
    StretchedBox s;
    const double lo[3] = {0.01, 0.01, 0.01}, hi[3] = {0.19, 0.09, 0.09};
    const SkinMesh box = box_skin(lo, hi, 3);
    add_skin(s.world, s.body, box);
    s.move();
    const SkinRead d = read_skin(s.world, s.body, 0);
    const uint32_t nv = box.vertices();
    // One interleaved buffer: position, normal, and two floats of the caller's own per vertex.
    const float sentinel = -12345.0f;
    std::vector<float> buffer(8 * std::size_t(nv), sentinel);
    ASSERT_EQ(lfem_body_get_skin_vertices_f32(s.world, s.body, 0, buffer.data(), 8, buffer.data() + 3, 8, nv), LFEM_OK)
        << lfem_last_error();
    for (uint32_t v = 0; v < nv; ++v) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(buffer[8 * v + k], float(d.x[3 * v + k]));
            EXPECT_EQ(buffer[8 * v + 3 + k], float(d.n[3 * v + k]));
        }
        EXPECT_EQ(buffer[8 * v + 6], sentinel);
        EXPECT_EQ(buffer[8 * v + 7], sentinel);
    }
    // Positions alone, packed; the normal stride is not looked at without normals.
    std::vector<float> packed(3 * std::size_t(nv));
    ASSERT_EQ(lfem_body_get_skin_vertices_f32(s.world, s.body, 0, packed.data(), 3, nullptr, 0, nv), LFEM_OK);
    for (std::size_t i = 0; i < packed.size(); ++i) EXPECT_EQ(packed[i], float(d.x[i]));
}

TEST(Skins, CheckpointsKeepThem) {
    StretchedBox s;
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.1, 0.1};
    add_skin(s.world, s.body, scattered(lo, hi, 0.02, 90, 5));
    add_skin(s.world, s.body, box_skin(lo, hi, 2));
    s.move();
    const char* path = "skins_checkpoint.bin";
    const lfem_status saved = lfem_world_save(s.world, path);
    if (saved == LFEM_UNSUPPORTED) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    ASSERT_EQ(saved, LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path, &loaded), LFEM_OK) << lfem_last_error();
    std::remove(path);
    EXPECT_EQ(fingerprint(s.world, {s.body}), fingerprint(loaded, {s.body}));  // skins included
    ASSERT_EQ(lfem_world_step(s.world, 0.01), LFEM_OK);
    ASSERT_EQ(lfem_world_step(loaded, 0.01), LFEM_OK);
    EXPECT_EQ(fingerprint(s.world, {s.body}), fingerprint(loaded, {s.body}));
    lfem_world_destroy(loaded);
}

TEST(Skins, BadInputIsRefusedAndChangesNothing) {
    World world;
    Mesh mesh;
    make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
    const lfem_body body = add_body(world, lfem_body_def_default(), mesh);
    lfem_body_def sd = lfem_body_def_default();
    sd.type = LFEM_BODY_STATIC;
    lfem_body shapes_only{};
    ASSERT_EQ(lfem_body_create(world, &sd, &shapes_only), LFEM_OK);
    const lfem_shape_def plane = lfem_shape_def_default();
    ASSERT_EQ(lfem_body_add_shape(world, shapes_only, &plane, nullptr), LFEM_OK);
    lfem_body gone = add_body(world, lfem_body_def_default(), mesh);
    ASSERT_EQ(lfem_body_destroy(world, gone), LFEM_OK);
    const double lo[3] = {0.01, 0.01, 0.01}, hi[3] = {0.19, 0.09, 0.09};
    const SkinMesh good = box_skin(lo, hi, 2);
    add_skin(world, body, good);
    ASSERT_EQ(lfem_world_step(world, 0.01), LFEM_OK);
    const std::vector<unsigned char> before = fingerprint(world, {body, shapes_only});
    int cases = 0;
    const auto refused = [&](lfem_status got, lfem_status expected, const std::string& what) {
        EXPECT_EQ(got, expected) << what << ": " << lfem_last_error();
        EXPECT_STRNE(lfem_last_error(), "") << what;
        EXPECT_EQ(before, fingerprint(world, {body, shapes_only})) << what << " changed the world";
        ++cases;
    };
    const uint32_t nv = good.vertices(), nt = good.triangles();
    uint32_t index = 77;
    auto add = [&](const SkinMesh& m, lfem_body b = lfem_body{}) {
        return lfem_body_add_skin(world, b.generation ? b : body, m.x.data(), m.vertices(), m.tri.data(),
                                  m.triangles(), &index);
    };
    SkinMesh nan = good;
    nan.x[7] = std::nan("");
    refused(add(nan), LFEM_INVALID_ARGUMENT, "a NaN position");
    SkinMesh beyond = good;
    beyond.tri[5] = nv;
    refused(add(beyond), LFEM_INVALID_MESH, "a triangle index out of range");
    SkinMesh repeated = good;
    repeated.tri[4] = repeated.tri[3];
    refused(add(repeated), LFEM_INVALID_MESH, "a triangle repeating a vertex");
    SkinMesh far = good;
    far.x[3 * 10] = 0.2 + 0.1;  // 0.1 m beyond the x = 0.2 face: more than one edge (0.057 m)
    refused(add(far), LFEM_INVALID_ARGUMENT, "a vertex far outside");
    EXPECT_NE(std::string(lfem_last_error()).find("vertex 10"), std::string::npos) << lfem_last_error();
    refused(lfem_body_add_skin(world, body, nullptr, nv, good.tri.data(), nt, &index), LFEM_INVALID_ARGUMENT,
            "positions NULL");
    refused(lfem_body_add_skin(world, body, good.x.data(), nv, nullptr, nt, &index), LFEM_INVALID_ARGUMENT,
            "triangles NULL");
    refused(lfem_body_add_skin(world, body, good.x.data(), 0, good.tri.data(), nt, &index), LFEM_INVALID_ARGUMENT,
            "no vertices");
    refused(lfem_body_add_skin(world, body, good.x.data(), nv, good.tri.data(), 0, &index), LFEM_INVALID_ARGUMENT,
            "no triangles");
    refused(add(good, shapes_only), LFEM_INVALID_ARGUMENT, "a body without tets");
    refused(add(good, gone), LFEM_INVALID_HANDLE, "a stale handle");
    refused(lfem_body_add_skin(nullptr, body, good.x.data(), nv, good.tri.data(), nt, &index), LFEM_INVALID_ARGUMENT,
            "world NULL");
    EXPECT_EQ(index, 77u);  // never written by a failed call

    // Reads: a bad skin index, a stale handle, too-small buffers (left untouched), NULL outputs,
    // strides below 3.
    const double dsentinel = -7.0;
    const float fsentinel = -7.0f;
    std::vector<double> p(3 * std::size_t(nv), dsentinel), n(3 * std::size_t(nv), dsentinel);
    std::vector<float> f(6 * std::size_t(nv), fsentinel);
    std::vector<uint32_t> t(3 * std::size_t(nt), 99u);
    uint32_t a = 5, b = 5;
    refused(lfem_body_get_skin_sizes(world, body, 1, &a, &b), LFEM_INVALID_ARGUMENT, "skin 1 of 1");
    refused(lfem_body_get_skin_sizes(world, gone, 0, &a, &b), LFEM_INVALID_HANDLE, "sizes, stale handle");
    refused(lfem_body_get_skin_count(world, gone, &a), LFEM_INVALID_HANDLE, "count, stale handle");
    refused(lfem_body_get_skin_count(world, body, nullptr), LFEM_INVALID_ARGUMENT, "count, out NULL");
    EXPECT_EQ(a, 5u);
    EXPECT_EQ(b, 5u);
    refused(lfem_body_get_skin_triangles(world, body, 0, t.data(), nt - 1), LFEM_BUFFER_TOO_SMALL,
            "triangles, capacity too small");
    refused(lfem_body_get_skin_triangles(world, body, 3, t.data(), nt), LFEM_INVALID_ARGUMENT, "triangles, skin 3");
    refused(lfem_body_get_skin_triangles(world, body, 0, nullptr, nt), LFEM_INVALID_ARGUMENT, "triangles, out NULL");
    EXPECT_TRUE(std::all_of(t.begin(), t.end(), [](uint32_t v) { return v == 99u; }));
    refused(lfem_body_get_skin_vertices(world, body, 0, p.data(), n.data(), nv - 1), LFEM_BUFFER_TOO_SMALL,
            "vertices, capacity too small");
    refused(lfem_body_get_skin_vertices(world, body, 0, nullptr, n.data(), nv), LFEM_INVALID_ARGUMENT,
            "vertices, positions NULL");
    refused(lfem_body_get_skin_vertices(world, body, 2, p.data(), n.data(), nv), LFEM_INVALID_ARGUMENT,
            "vertices, skin 2");
    refused(lfem_body_get_skin_vertices(world, gone, 0, p.data(), n.data(), nv), LFEM_INVALID_HANDLE,
            "vertices, stale handle");
    EXPECT_TRUE(std::all_of(p.begin(), p.end(), [&](double v) { return v == dsentinel; }));
    EXPECT_TRUE(std::all_of(n.begin(), n.end(), [&](double v) { return v == dsentinel; }));
    refused(lfem_body_get_skin_vertices_f32(world, body, 0, f.data(), 2, nullptr, 3, nv), LFEM_INVALID_ARGUMENT,
            "f32, position stride 2");
    refused(lfem_body_get_skin_vertices_f32(world, body, 0, f.data(), 6, f.data() + 3, 1, nv), LFEM_INVALID_ARGUMENT,
            "f32, normal stride 1");
    refused(lfem_body_get_skin_vertices_f32(world, body, 0, f.data(), 6, f.data() + 3, 6, nv - 1),
            LFEM_BUFFER_TOO_SMALL, "f32, capacity too small");
    refused(lfem_body_get_skin_vertices_f32(world, body, 0, nullptr, 3, nullptr, 3, nv), LFEM_INVALID_ARGUMENT,
            "f32, positions NULL");
    refused(lfem_body_get_skin_vertices_f32(world, shapes_only, 0, f.data(), 3, nullptr, 3, nv), LFEM_INVALID_ARGUMENT,
            "f32, a body without skins");
    EXPECT_TRUE(std::all_of(f.begin(), f.end(), [&](float v) { return v == fsentinel; }));
    std::printf("%d bad skin inputs refused cleanly\n", cases);
}
