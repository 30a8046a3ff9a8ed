// Bad input through the C API: every case returns the right status with a message, and the
// world is bit-for-bit what it was (fingerprint of everything a user can read back).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// A world with one deformable body that has already taken a few steps (so velocities, stress
// and stats are non-trivial) and one static body.
class BadInput : public ::testing::Test {
protected:
    void SetUp() override {
        make_box_mesh(mesh, 0.2, 0.1, 0.1, 4, 2, 2);
        lfem_body_def def = lfem_body_def_default();
        def.linear_velocity[0] = 0.3;
        body = add_body(world, def, mesh);
        lfem_body_def ground = lfem_body_def_default();
        ground.type = LFEM_BODY_STATIC;
        floor = add_body(world, ground, mesh);
        ASSERT_EQ(lfem_world_step(world, 0.01), LFEM_OK) << lfem_last_error();
        before = fingerprint(world, {body, floor});
    }
    // The call's status is `expected`, it left a message, and the world is unchanged.
    void expect_refused(lfem_status got, lfem_status expected, const char* what) {
        EXPECT_EQ(got, expected) << what << ": " << lfem_last_error();
        EXPECT_STRNE(lfem_last_error(), "") << what;
        EXPECT_EQ(before, fingerprint(world, {body, floor})) << what << " changed the world";
        ++cases;
    }
    void TearDown() override { std::printf("%d bad inputs refused cleanly\n", cases); }

    World world;
    Mesh mesh;
    lfem_body body{}, floor{};
    std::vector<unsigned char> before;
    int cases = 0;
};

}  // namespace

TEST_F(BadInput, NullPointers) {
    lfem_world_def wd = lfem_world_def_default();
    expect_refused(lfem_world_create(nullptr, nullptr), LFEM_INVALID_ARGUMENT, "world_create(NULL)");
    expect_refused(lfem_world_create(&wd, nullptr), LFEM_INVALID_ARGUMENT, "world_create(out NULL)");
    expect_refused(lfem_world_step(nullptr, 0.01), LFEM_INVALID_ARGUMENT, "step(NULL world)");
    expect_refused(lfem_body_get_positions(world, body, nullptr, 1000), LFEM_INVALID_ARGUMENT,
                   "get_positions(out NULL)");
    expect_refused(lfem_body_add_mesh(world, body, nullptr, 4, lfem_mesh_get_tets(mesh.m), 1),
                   LFEM_INVALID_ARGUMENT, "add_mesh(positions NULL)");
    lfem_body out{};
    expect_refused(lfem_body_create(world, nullptr, &out), LFEM_INVALID_ARGUMENT, "body_create(def NULL)");
    expect_refused(lfem_world_get_stats(world, nullptr), LFEM_INVALID_ARGUMENT, "get_stats(NULL)");
    expect_refused(lfem_mesh_load_gmsh(nullptr, &mesh.m), LFEM_INVALID_ARGUMENT, "load_gmsh(NULL path)");
}

TEST_F(BadInput, BadNumbers) {
    expect_refused(lfem_world_step(world, kNaN), LFEM_INVALID_ARGUMENT, "step(NaN)");
    expect_refused(lfem_world_step(world, 0.0), LFEM_INVALID_ARGUMENT, "step(0)");
    expect_refused(lfem_world_step(world, -1e-3), LFEM_INVALID_ARGUMENT, "step(-1e-3)");
    expect_refused(lfem_world_step(world, std::numeric_limits<double>::infinity()),
                   LFEM_INVALID_ARGUMENT, "step(inf)");
    const double g[3] = {0, kNaN, 0};
    expect_refused(lfem_world_set_gravity(world, g), LFEM_INVALID_ARGUMENT, "set_gravity(NaN)");
    expect_refused(lfem_world_set_time_step(world, -1.0), LFEM_INVALID_ARGUMENT, "set_time_step(-1)");

    lfem_body out{};
    const auto bad_def = [&](void (*edit)(lfem_body_def&), const char* what) {
        lfem_body_def d = lfem_body_def_default();
        edit(d);
        expect_refused(lfem_body_create(world, &d, &out), LFEM_INVALID_ARGUMENT, what);
    };
    bad_def([](lfem_body_def& d) { d.young_modulus = 0.0; }, "E = 0");
    bad_def([](lfem_body_def& d) { d.young_modulus = -5.0; }, "E < 0");
    bad_def([](lfem_body_def& d) { d.young_modulus = kNaN; }, "E = NaN");
    bad_def([](lfem_body_def& d) { d.density = 0.0; }, "density = 0");
    bad_def([](lfem_body_def& d) { d.density = -1000.0; }, "density < 0");
    bad_def([](lfem_body_def& d) { d.poisson_ratio = 0.5; }, "nu = 0.5");
    bad_def([](lfem_body_def& d) { d.poisson_ratio = 0.7; }, "nu = 0.7");
    bad_def([](lfem_body_def& d) { d.damping = -1.0; }, "damping < 0");
    bad_def([](lfem_body_def& d) { d.linear_velocity[1] = kNaN; }, "velocity NaN");
    bad_def([](lfem_body_def& d) { d.type = lfem_body_type(17); }, "unknown body type");
    bad_def([](lfem_body_def& d) { d.model = lfem_model(9); }, "unknown model");
    bad_def([](lfem_body_def& d) { d.internal_value = 0; }, "def not from lfem_body_def_default");
    EXPECT_FALSE(lfem_body_is_valid(world, out));

    lfem_world_def wd = lfem_world_def_default();
    wd.step_safety = 1.5;
    lfem_world* w2 = nullptr;
    expect_refused(lfem_world_create(&wd, &w2), LFEM_INVALID_ARGUMENT, "step_safety 1.5");
    EXPECT_EQ(w2, nullptr);
}

TEST_F(BadInput, BadMeshes) {
    const double X[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    const auto bad_mesh = [&](std::vector<uint32_t> tets, const double* x, uint32_t nodes,
                              lfem_status expected, const char* what) {
        lfem_body_def d = lfem_body_def_default();
        lfem_body fresh{};
        // add_mesh to the existing body: must leave it exactly as it was.
        expect_refused(lfem_body_add_mesh(world, body, x, nodes, tets.data(), uint32_t(tets.size() / 4)),
                       expected, what);
        (void)d;
        (void)fresh;
    };
    bad_mesh({0, 1, 2, 7}, X, 4, LFEM_INVALID_MESH, "index out of range");
    bad_mesh({0, 1, 1, 3}, X, 4, LFEM_INVALID_MESH, "repeated index");
    bad_mesh({0, 2, 1, 3}, X, 4, LFEM_INVALID_MESH, "inverted tet");
    const double flat[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    bad_mesh({0, 1, 2, 3}, flat, 4, LFEM_INVALID_MESH, "zero-volume tet");
    bad_mesh({0, 1, 2, 3}, X, 5, LFEM_INVALID_MESH, "unused node");
    const double nan_x[] = {0, 0, 0, 1, 0, 0, 0, kNaN, 0, 0, 0, 1};
    bad_mesh({0, 1, 2, 3}, nan_x, 4, LFEM_INVALID_ARGUMENT, "NaN position");
    bad_mesh({0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}, X, 4, LFEM_INVALID_MESH,
             "face shared by three tets");
    // A tet whose volume is finite (1.5e102^3 / 6 = 5.6e305 m^3) but whose mass at the default
    // 1000 kg/m^3 overflows (found by fuzz_api: the body's mass was inf).
    const double s = 1.5e102, huge[] = {0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s};
    bad_mesh({0, 1, 2, 3}, huge, 4, LFEM_INVALID_MESH, "a mass that overflows");
    EXPECT_NE(std::string(lfem_last_error()).find("mass overflows"), std::string::npos);
}

// 10-node tets (lfem_body_add_quadratic_mesh): the linear checks on their corners, then their
// own: conforming mid-edge nodes, no folded curved element, one kind of tet per body, and the
// mesh calls that make and read them.
TEST_F(BadInput, BadQuadraticMeshes) {
    Mesh q;
    make_quadratic_box_mesh(q, 0.1, 0.1, 0.1, 1, 1, 1);
    const uint32_t n = q.nodes(), t = q.tets();
    const std::vector<double> X(lfem_mesh_get_positions(q.m), lfem_mesh_get_positions(q.m) + 3 * n);
    const std::vector<uint32_t> tets(lfem_mesh_get_tets(q.m), lfem_mesh_get_tets(q.m) + 10 * t);
    const auto refused = [&](const std::vector<double>& x, const std::vector<uint32_t>& e, uint32_t nodes,
                             lfem_status expected, const char* what) {
        expect_refused(lfem_body_add_quadratic_mesh(world, body, x.data(), nodes, e.data(), uint32_t(e.size() / 10)),
                       expected, what);
    };
    // The linear body of the fixture cannot take 10-node tets, nor a 10-node body 4-node ones.
    refused(X, tets, n, LFEM_INVALID_ARGUMENT, "10-node tets for a body of 4-node tets");
    EXPECT_NE(std::string(lfem_last_error()).find("cannot join"), std::string::npos) << lfem_last_error();
    lfem_body_def d = lfem_body_def_default();
    const lfem_body quad = add_body(world, d, q);
    const std::vector<lfem_body> all = {body, floor, quad};
    before = fingerprint(world, all);
    const auto refused_on = [&](lfem_status got, lfem_status expected, const char* what) {
        EXPECT_EQ(got, expected) << what << ": " << lfem_last_error();
        EXPECT_EQ(before, fingerprint(world, all)) << what << " changed the world";
        ++cases;
    };
    refused_on(lfem_body_add_mesh(world, quad, lfem_mesh_get_positions(mesh.m), mesh.nodes(),
                                  lfem_mesh_get_tets(mesh.m), mesh.tets()),
               LFEM_INVALID_ARGUMENT, "4-node tets for a body of 10-node tets");
    const auto refused_quad = [&](const std::vector<double>& x, const std::vector<uint32_t>& e, uint32_t nodes,
                                  lfem_status expected, const char* what) {
        refused_on(lfem_body_add_quadratic_mesh(world, quad, x.data(), nodes, e.data(), uint32_t(e.size() / 10)),
                   expected, what);
    };
    refused_quad(X, tets, 9, LFEM_INVALID_ARGUMENT, "fewer than 10 nodes");
    std::vector<uint32_t> e = tets;
    e[5] = n;
    refused_quad(X, e, n, LFEM_INVALID_MESH, "mid-edge index out of range");
    e = tets;
    e[5] = e[0];
    refused_quad(X, e, n, LFEM_INVALID_MESH, "a mid-edge node repeating a corner");
    // Tet 1's node on an edge it shares with tet 0 replaced by a node of its own.
    std::vector<double> Xs = X;
    e = tets;
    for (int k = 4; k < 10; ++k) {
        bool shared = false;
        for (int j = 4; j < 10; ++j) shared = shared || e[10 + k] == e[j];
        if (!shared) continue;
        Xs.insert(Xs.end(), &X[3 * e[10 + k]], &X[3 * e[10 + k]] + 3);
        e[10 + k] = uint32_t(Xs.size() / 3 - 1);
        break;
    }
    refused_quad(Xs, e, uint32_t(Xs.size() / 3), LFEM_INVALID_MESH, "non-conforming mid-edge node");
    EXPECT_NE(std::string(lfem_last_error()).find("not conforming"), std::string::npos) << lfem_last_error();
    // A mid-edge node pulled past the opposite corner: the curved element folds over.
    Xs = X;
    const uint32_t mid = tets[4], far = tets[3];
    for (int k = 0; k < 3; ++k) Xs[3 * mid + k] = 1.5 * X[3 * far + k] - 0.5 * X[3 * mid + k];
    refused_quad(Xs, tets, n, LFEM_INVALID_MESH, "folded curved tet");
    EXPECT_NE(std::string(lfem_last_error()).find("folds over"), std::string::npos) << lfem_last_error();
    // The mesh calls.
    EXPECT_EQ(lfem_mesh_make_quadratic(nullptr), LFEM_INVALID_ARGUMENT);
    const std::vector<uint32_t> kept(lfem_mesh_get_tets(q.m), lfem_mesh_get_tets(q.m) + 10 * t);
    EXPECT_EQ(lfem_mesh_make_quadratic(q.m), LFEM_INVALID_ARGUMENT);  // already quadratic: unchanged
    EXPECT_EQ(std::vector<uint32_t>(lfem_mesh_get_tets(q.m), lfem_mesh_get_tets(q.m) + 10 * t), kept);
    EXPECT_EQ(lfem_mesh_get_nodes_per_tet(nullptr), 0u);
    uint32_t faces = 0, width = 0;
    ASSERT_EQ(lfem_body_get_boundary_face_count(world, quad, &faces), LFEM_OK);
    ASSERT_EQ(lfem_body_get_nodes_per_tet(world, quad, &width), LFEM_OK);
    EXPECT_EQ(width, 10u);
    std::vector<uint32_t> out(6 * faces);
    refused_on(lfem_body_get_boundary_faces(world, quad, out.data(), faces - 1), LFEM_BUFFER_TOO_SMALL,
               "face buffer short");
    refused_on(lfem_body_get_boundary_faces(world, quad, nullptr, faces), LFEM_INVALID_ARGUMENT, "faces NULL");
    refused_on(lfem_body_get_nodes_per_tet(world, quad, nullptr), LFEM_INVALID_ARGUMENT, "nodes per tet NULL");
}

TEST_F(BadInput, StaleForeignAndNullHandles) {
    // Stale: a destroyed body's handle.
    lfem_body_def d = lfem_body_def_default();
    lfem_body doomed{};
    ASSERT_EQ(lfem_body_create(world, &d, &doomed), LFEM_OK);
    ASSERT_EQ(lfem_body_destroy(world, doomed), LFEM_OK);
    before = fingerprint(world, {body, floor});
    uint32_t n = 0;
    expect_refused(lfem_body_get_node_count(world, doomed, &n), LFEM_INVALID_HANDLE, "stale handle");
    expect_refused(lfem_body_destroy(world, doomed), LFEM_INVALID_HANDLE, "double destroy");
    // A new body reuses the slot: the old handle must still be refused.
    lfem_body reborn{};
    ASSERT_EQ(lfem_body_create(world, &d, &reborn), LFEM_OK);
    EXPECT_EQ(reborn.index, doomed.index);
    EXPECT_FALSE(lfem_body_is_valid(world, doomed));
    ASSERT_EQ(lfem_body_destroy(world, reborn), LFEM_OK);
    before = fingerprint(world, {body, floor});

    // Foreign: a handle from another world, same slot index.
    World other;
    Mesh m2;
    make_box_mesh(m2, 0.1, 0.1, 0.1, 1, 1, 1);
    const lfem_body alien = add_body(other, d, m2);
    EXPECT_EQ(alien.index, body.index);
    double x[3 * 64];
    expect_refused(lfem_body_get_positions(world, alien, x, 64), LFEM_INVALID_HANDLE, "foreign handle");
    // Null handle and a made-up one.
    expect_refused(lfem_body_fix_nodes(world, lfem_body{0, 0}, nullptr, 0), LFEM_INVALID_HANDLE, "null handle");
    expect_refused(lfem_body_destroy(world, lfem_body{999, 1}), LFEM_INVALID_HANDLE, "index out of range");
}

TEST_F(BadInput, TooSmallBuffersAndBadIndices) {
    const uint32_t n = node_count(world, body);
    std::vector<double> x(3 * n);
    expect_refused(lfem_body_get_positions(world, body, x.data(), n - 1), LFEM_BUFFER_TOO_SMALL,
                   "positions buffer one node short");
    expect_refused(lfem_body_get_velocities(world, body, x.data(), 0), LFEM_BUFFER_TOO_SMALL,
                   "velocities buffer empty");
    uint32_t tris = 0;
    ASSERT_EQ(lfem_body_get_boundary_triangle_count(world, body, &tris), LFEM_OK);
    std::vector<uint32_t> t(3 * tris);
    expect_refused(lfem_body_get_boundary_triangles(world, body, t.data(), tris - 1),
                   LFEM_BUFFER_TOO_SMALL, "triangle buffer short");
    const uint32_t bad[2] = {0, n};
    expect_refused(lfem_body_fix_nodes(world, body, bad, 2), LFEM_INVALID_ARGUMENT, "fix node out of range");
    const uint32_t twice[2] = {3, 3};
    expect_refused(lfem_body_fix_nodes(world, body, twice, 2), LFEM_INVALID_ARGUMENT, "fix node twice");
    const double f[6] = {0, 0, kNaN, 0, 0, 0};
    const uint32_t ok[2] = {0, 1};
    expect_refused(lfem_body_set_node_forces(world, body, ok, 2, f), LFEM_INVALID_ARGUMENT, "NaN force");
    std::vector<double> v(3 * n, 0.0);
    expect_refused(lfem_body_set_velocities(world, body, v.data(), n + 1), LFEM_INVALID_ARGUMENT,
                   "velocities for the wrong node count");
    expect_refused(lfem_body_fix_nodes(world, floor, ok, 2), LFEM_INVALID_ARGUMENT, "fix nodes of a static body");
    uint32_t count = 0, one = 0;
    const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    expect_refused(lfem_body_find_nodes_in_box(world, body, lo, hi, &one, 1, &count), LFEM_BUFFER_TOO_SMALL,
                   "find_nodes buffer short");
    EXPECT_EQ(count, n);  // the total is still reported
}

TEST_F(BadInput, MissingAndMalformedFiles) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without file I/O (LFEM_WITH_IO=OFF)";
    lfem_mesh* m = nullptr;
    expect_refused(lfem_mesh_load_gmsh("/nonexistent/dir/mesh.msh", &m), LFEM_IO_ERROR, "missing file");
    EXPECT_EQ(m, nullptr);
    const std::string path = ::testing::TempDir() + "lfem_bad_input.msh";
    {
        std::ofstream f(path);
        f << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 zero\n";
    }
    expect_refused(lfem_mesh_load_gmsh(path.c_str(), &m), LFEM_IO_ERROR, "malformed file");
    EXPECT_NE(std::string(lfem_last_error()).find(":7"), std::string::npos)
        << "message should name line 7: " << lfem_last_error();
    EXPECT_EQ(m, nullptr);
    lfem_vtk_series* s = nullptr;
    ASSERT_EQ(lfem_vtk_series_create("/nonexistent/dir/out.pvd", &s), LFEM_OK);
    expect_refused(lfem_vtk_series_write_frame(s, world), LFEM_IO_ERROR, "unwritable series");
    lfem_vtk_series_destroy(s);
}

// A body destroyed while in contact takes its contacts with it: the query must not report (or
// read the freed nodes of) a pair with a body that is gone. Found by fuzz_api
// (tests/fuzz/regressions/api/query_contacts_after_body_destroyed).
TEST(StaleHandles, DestroyingABodyInContactDropsItsContacts) {
    World w(lfem_world_def_default());
    Mesh floor_mesh, cube;
    make_box_mesh(floor_mesh, 0.4, 0.4, 0.1, 2, 2, 1, -0.2, -0.2, -0.1);
    lfem_body_def fixed = lfem_body_def_default();
    fixed.type = LFEM_BODY_STATIC;
    const lfem_body floor = add_body(w, fixed, floor_mesh);
    make_box_mesh(cube, 0.1, 0.1, 0.1, 2, 2, 2, -0.05, -0.05, 0.0);
    const lfem_body block = add_body(w, lfem_body_def_default(), cube);
    for (int i = 0; i < 20; ++i) ASSERT_EQ(lfem_world_step(w, 0.002), LFEM_OK) << lfem_last_error();
    uint32_t count = 0;  // asked with capacity 0: too small while there are contacts
    ASSERT_EQ(lfem_world_query_contacts(w, nullptr, 0, &count), LFEM_BUFFER_TOO_SMALL);
    ASSERT_GT(count, 0u) << "the block must rest on the floor for this test to mean anything";
    ASSERT_EQ(lfem_body_destroy(w, block), LFEM_OK);
    ASSERT_EQ(lfem_world_query_contacts(w, nullptr, 0, &count), LFEM_OK) << lfem_last_error();
    EXPECT_EQ(count, 0u);
    EXPECT_EQ(stats(w).contact_count, 0u);
    EXPECT_EQ(lfem_body_is_valid(w, floor), 1);
    EXPECT_EQ(lfem_world_step(w, 0.002), LFEM_OK) << lfem_last_error();
}
