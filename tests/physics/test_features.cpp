// What passes between nodes: rigid shapes against faces. A soft cube set on thin rods or small
// studs that lie between its nodes rests on them, held by face-against-shape contacts
// (contact/face_shape.h); before, the 3 x 3 x 3 cube fell through them to the floor.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

lfem_body static_shapes(lfem_world* w, const std::vector<lfem_shape_def>& shapes) {
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_STATIC;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_OK) << lfem_last_error();
    for (const lfem_shape_def& s : shapes) EXPECT_EQ(lfem_body_add_shape(w, b, &s, NULL), LFEM_OK) << lfem_last_error();
    return b;
}

// A rod of radius r along y through (x, 0, z), 0.3 m long.
lfem_shape_def rod(double x, double z, double r) {
    lfem_shape_def s = lfem_shape_def_default();
    s.type = LFEM_SHAPE_CAPSULE;
    s.radius = r;
    s.half_length = 0.15;
    s.center[0] = x, s.center[2] = z;
    s.rotation[0] = std::sqrt(0.5), s.rotation[1] = -std::sqrt(0.5);  // local z along world y
    return s;
}

lfem_shape_def stud(double x, double y, double r) {
    lfem_shape_def s = lfem_shape_def_default();
    s.type = LFEM_SHAPE_SPHERE;
    s.radius = r;
    s.center[0] = x, s.center[1] = y;
    return s;
}

// A 10 cm cube of n^3 cells (E 1e5, nu 0.3) whose bottom is 2 mm above the shapes' tops.
lfem_body soft_cube(lfem_world* w, Mesh& m, uint32_t n, double damping) {
    make_box_mesh(m, 0.1, 0.1, 0.1, n, n, n, -0.05, -0.05, 0.012);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e5;
    d.poisson_ratio = 0.3;
    d.damping = damping;
    return add_body(w, d, m);
}

struct Resting {
    double weight_error;  // |contact force from the shapes / weight - 1|
    double feature_share; // of that force, what the face-shape records carry
    double depth;         // deepest sampled shape point inside the cube (m)
    double lowest;        // the cube's lowest node (m)
    double element;       // the cube's mean boundary edge (m)
};

// A 10 cm cube of n^3 cells (E 1e5, nu 0.3) dropped from 2 mm onto static shapes whose tops are
// at z = 0.01, over a plane floor 10 cm below; `surface` samples the shapes' upper surfaces.
Resting drop_on(const std::vector<lfem_shape_def>& shapes, uint32_t n, const std::vector<std::array<double, 3>>& surface) {
    World w;
    lfem_shape_def floor = lfem_shape_def_default();  // a plane facing +z
    floor.center[2] = -0.1;
    static_shapes(w, {floor});
    const lfem_body holder = static_shapes(w, shapes);
    Mesh m;
    const lfem_body cube = soft_cube(w, m, n, 20.0);
    double total = 0, features = 0;
    const int frames = 150, measured = 30;
    for (int frame = 0; frame < frames; ++frame) {
        EXPECT_EQ(lfem_world_step(w, 1.0 / 60.0), LFEM_OK) << lfem_last_error();
        if (frame < frames - measured) continue;
        uint32_t count = 0;
        lfem_world_query_contacts(w, nullptr, 0, &count);
        std::vector<lfem_contact> c(count);
        EXPECT_EQ(lfem_world_query_contacts(w, c.data(), count, &count), LFEM_OK);
        for (const lfem_contact& k : c) {
            if (k.body_a.index != cube.index || k.body_b.index != holder.index) continue;
            total += k.force[2] / measured;
            if (k.kind == LFEM_CONTACT_FACE_SHAPE) features += k.force[2] / measured;
        }
    }
    Resting r{};
    double mass = 0;
    lfem_body_get_mass(w, cube, &mass);
    r.weight_error = std::fabs(total / (mass * 9.81) - 1.0);
    r.feature_share = total > 0 ? features / total : 0.0;
    const BodyShape s = body_shape(w, cube, m);
    for (const auto& y : surface) r.depth = std::max(r.depth, depth_inside(y.data(), s));
    r.lowest = HUGE_VAL;
    for (std::size_t i = 2; i < s.x.size(); i += 3) r.lowest = std::min(r.lowest, s.x[i]);
    r.element = mean_boundary_edge(s);
    return r;
}

// Points on the upper half of a rod's surface, over the cube's width.
void sample_rod(double x, double z, double r, std::vector<std::array<double, 3>>& out) {
    for (int i = 0; i <= 40; ++i)
        for (int k = 0; k <= 8; ++k) {
            const double a = M_PI * k / 8.0;
            out.push_back({x + r * std::cos(a), -0.05 + 0.1 * i / 40.0, z + r * std::sin(a)});
        }
}

void sample_stud(double x, double y, double r, std::vector<std::array<double, 3>>& out) {
    for (int i = 0; i <= 8; ++i)
        for (int k = 0; k < 16; ++k) {
            const double polar = 0.5 * M_PI * i / 8.0, a = 2.0 * M_PI * k / 16.0;
            out.push_back({x + r * std::sin(polar) * std::cos(a), y + r * std::sin(polar) * std::sin(a), r * std::cos(polar)});
        }
}

}  // namespace

// Two rods of 1 cm radius under the cube, each half-way between two columns of its nodes (3 x 3
// x 3 cells: columns every 3.33 cm): no node of the cube meets them. The cube rests on them,
// their contacts carrying its weight to 1e-3 (averaged over the last half second of 2.5: the
// solve converges to 1e-3 of the load's motion, solve_contact_multipliers.h, and with damping 20
// the cube's remaining motion changes its momentum by far less), and no point of the rods lies
// inside it deeper than 1 % of its element size (the target).
TEST(Features, ASoftCubeRestsOnARailingOfThinRods) {
    for (uint32_t n : {3u, 6u}) {
        const double half = 0.1 / 6.0;  // half a cell of the 3-cell mesh: between its columns
        const double x0 = -0.05 + half, x1 = 0.05 - half;
        std::vector<std::array<double, 3>> surface;
        sample_rod(x0, 0.0, 0.01, surface);
        sample_rod(x1, 0.0, 0.01, surface);
        const Resting r = drop_on({rod(x0, 0.0, 0.01), rod(x1, 0.0, 0.01)}, n, surface);
        std::printf("%u^3 cells on two rods: weight within %.2e (faces carry %.0f %%), deepest rod point %.2e m "
                    "(%.2f %% of the element), lowest node z = %.4f m\n",
                    n, r.weight_error, 100 * r.feature_share, r.depth, 100 * r.depth / r.element, r.lowest);
        EXPECT_GT(r.lowest, -0.02);  // on the rods, not fallen through to the floor at -0.1
        EXPECT_LT(r.weight_error, 1e-3);
        EXPECT_LT(r.depth, 0.01 * r.element);
    }
}

// Four small studs (r 1 cm), each under the middle of a bottom cell of the 3 x 3 x 3 cube.
TEST(Features, ASoftCubeRestsOnFourStuds) {
    for (uint32_t n : {3u, 6u}) {
        const double c = 0.1 / 3.0;
        std::vector<lfem_shape_def> studs;
        std::vector<std::array<double, 3>> surface;
        for (double x : {-c, c})
            for (double y : {-c, c}) studs.push_back(stud(x, y, 0.01)), sample_stud(x, y, 0.01, surface);
        const Resting r = drop_on(studs, n, surface);
        std::printf("%u^3 cells on four studs: weight within %.2e (faces carry %.0f %%), deepest stud point %.2e m "
                    "(%.2f %% of the element), lowest node z = %.4f m\n",
                    n, r.weight_error, 100 * r.feature_share, r.depth, 100 * r.depth / r.element, r.lowest);
        EXPECT_GT(r.lowest, -0.02);
        EXPECT_LT(r.weight_error, 1e-3);
        EXPECT_LT(r.depth, 0.01 * r.element);
    }
}


// The face-against-shape records (their kind, faces, weights and multipliers) are part of a
// checkpoint: a world saved while a cube rests on studs between its nodes and loaded again
// continues bitwise as the one that was not saved.
TEST(Features, FaceContactsContinueBitwiseAfterACheckpoint) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without checkpoint files (LFEM_WITH_IO=OFF)";
    World w;
    const double c = 0.1 / 3.0;
    static_shapes(w, {stud(-c, -c, 0.01), stud(-c, c, 0.01), stud(c, -c, 0.01), stud(c, c, 0.01)});
    Mesh m;
    const lfem_body cube = soft_cube(w, m, 3, 0.0);
    for (int i = 0; i < 20; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60.0), LFEM_OK);
    uint32_t count = 0, faces = 0;
    lfem_world_query_contacts(w, nullptr, 0, &count);
    std::vector<lfem_contact> k(count);
    ASSERT_EQ(lfem_world_query_contacts(w, k.data(), count, &count), LFEM_OK);
    for (const lfem_contact& x : k) faces += x.kind == LFEM_CONTACT_FACE_SHAPE;
    ASSERT_GT(faces, 0u) << "the studs must be held by face contacts when the world is saved";
    const std::string path = std::string(::testing::TempDir()) + "lfem_face_contacts.ckpt";
    ASSERT_EQ(lfem_world_save(w, path.c_str()), LFEM_OK) << lfem_last_error();
    lfem_world* loaded = nullptr;
    ASSERT_EQ(lfem_world_load(path.c_str(), &loaded), LFEM_OK) << lfem_last_error();
    for (int i = 0; i < 20; ++i) {
        ASSERT_EQ(lfem_world_step(w, 1.0 / 60.0), LFEM_OK);
        ASSERT_EQ(lfem_world_step(loaded, 1.0 / 60.0), LFEM_OK);
    }
    const std::vector<double> a = positions(w, cube), b = positions(loaded, cube);
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(double)));
    lfem_world_destroy(loaded);
    std::remove(path.c_str());
}

// The same on 1, 2 and 3 threads, bit for bit: the face pass runs on one thread, in a fixed
// order of shapes, bodies and faces, and its records join the list in key order.
TEST(Features, FaceContactsAreBitwiseTheSameOnOneTwoAndThreeThreads) {
    std::vector<std::vector<double>> runs;
    for (uint32_t threads : {1u, 2u, 3u}) {
        lfem_world_def wd = lfem_world_def_default();
        wd.thread_count = threads;
        World w(wd);
        const double half = 0.1 / 6.0;
        static_shapes(w, {rod(-0.05 + half, 0.0, 0.01), rod(0.05 - half, 0.0, 0.01)});
        Mesh m;
        const lfem_body cube = soft_cube(w, m, 3, 0.0);
        for (int i = 0; i < 30; ++i) ASSERT_EQ(lfem_world_step(w, 1.0 / 60.0), LFEM_OK);
        runs.push_back(positions(w, cube));
    }
    for (std::size_t r = 1; r < runs.size(); ++r)
        EXPECT_EQ(0, std::memcmp(runs[0].data(), runs[r].data(), runs[0].size() * sizeof(double))) << r + 1 << " threads";
}
