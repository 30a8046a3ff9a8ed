// Bodies of 10-node tets through the C API: the lumped masses (measured from the first step under
// node forces), and a Gmsh file of 10-node tets to the boundary faces and a VTK frame. The other
// physics of 10-node tets runs beside the linear tets' in the files of each case
// (test_cantilever, test_resting_contact, test_spinning_body, test_impact, test_stability,
// test_energy, test_numbering, test_threads).
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

// The first step from rest moves a free node by h^2 F / (2 m) (the velocity-Verlet start of
// central differences, no elastic force yet): so each node's mass is measured. Every one is
// positive, they sum to rho V, and each is the sub-tet lumping's rho V_e / 32 per tet at a corner,
// 7 rho V_e / 48 at a mid-edge node.
TEST(QuadraticTets, LumpedMassesArePositiveAndSumToRhoV) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    Mesh mesh;
    make_quadratic_box_mesh(mesh, 0.3, 0.2, 0.1, 3, 2, 1);
    lfem_body_def def = lfem_body_def_default();
    def.density = 2000.0;
    const lfem_body b = add_body(w, def, mesh);
    const uint32_t n = mesh.nodes();
    std::vector<uint32_t> all(n);
    std::iota(all.begin(), all.end(), 0u);
    std::vector<double> F(3 * n, 0.0);
    for (uint32_t i = 0; i < n; ++i) F[3 * i + 2] = 50.0;  // moves the nodes by ~1e-6 m
    ASSERT_EQ(lfem_body_set_node_forces(w, b, all.data(), n, F.data()), LFEM_OK);
    const double h = 1e-4;
    ASSERT_EQ(lfem_world_step(w, h), LFEM_OK) << lfem_last_error();
    ASSERT_EQ(stats(w).substeps_last_call, 1u);
    const std::vector<double> x = positions(w, b);
    const double* X = lfem_mesh_get_positions(mesh.m);
    const uint32_t* tets = lfem_mesh_get_tets(mesh.m);
    std::vector<double> expected(n, 0.0);
    for (uint32_t e = 0; e < mesh.tets(); ++e) {
        const double V = volume(std::vector<double>(X, X + 3 * n), tets + 10 * e, 1, 10);
        for (int a = 0; a < 10; ++a) expected[tets[10 * e + a]] += def.density * V * (a < 4 ? 1.0 / 32 : 7.0 / 48);
    }
    double total = 0, reported = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const double m = h * h * F[3 * i + 2] / (2 * (x[3 * i + 2] - X[3 * i + 2]));
        EXPECT_GT(m, 0.0) << "node " << i;
        // The displacement (~1e-6 m) is read as a difference of positions of up to 0.3 m:
        // 1e-10 relative.
        EXPECT_NEAR(m, expected[i], 1e-9 * expected[i]) << "node " << i;
        total += m;
    }
    ASSERT_EQ(lfem_body_get_mass(w, b, &reported), LFEM_OK);
    const double rhoV = def.density * 0.3 * 0.2 * 0.1;
    EXPECT_NEAR(total, rhoV, 1e-9 * rhoV);
    EXPECT_NEAR(reported, rhoV, 1e-12 * rhoV);
}

// A Gmsh file of 10-node tets (type 11) through the API: its mesh, the body's 6-node boundary
// faces (the cube's six unit squares: mid-edge nodes on the middles of their edges, area 6),
// the flat triangles contact uses (4 a face), and a VTK frame of quadratic cells.
TEST(QuadraticTets, GmshFileBoundaryFacesAndVtkFrame) {
    if (!LFEM_WITH_IO) GTEST_SKIP() << "built without file I/O (LFEM_WITH_IO=OFF)";
    Mesh mesh;
    ASSERT_EQ(lfem_mesh_load_gmsh((std::string(LFEM_TEST_DATA_DIR) + "/cube10_v41.msh").c_str(), &mesh.m), LFEM_OK)
        << lfem_last_error();
    ASSERT_EQ(mesh.nodes_per_tet(), 10u);
    World w;
    const lfem_body b = add_body(w, lfem_body_def_default(), mesh);
    uint32_t width = 0, faces = 0, triangles = 0, tets = 0;
    ASSERT_EQ(lfem_body_get_nodes_per_tet(w, b, &width), LFEM_OK);
    ASSERT_EQ(lfem_body_get_boundary_face_count(w, b, &faces), LFEM_OK);
    ASSERT_EQ(lfem_body_get_boundary_triangle_count(w, b, &triangles), LFEM_OK);
    ASSERT_EQ(lfem_body_get_tet_count(w, b, &tets), LFEM_OK);
    EXPECT_EQ(width, 10u);
    EXPECT_EQ(tets, mesh.tets());
    EXPECT_EQ(triangles, 4 * faces);
    std::vector<uint32_t> f(6 * faces);
    ASSERT_EQ(lfem_body_get_boundary_faces(w, b, f.data(), faces), LFEM_OK);
    const std::vector<double> x = positions(w, b);
    double area = 0;
    for (uint32_t k = 0; k < faces; ++k) {
        const double* p[6];
        for (int i = 0; i < 6; ++i) p[i] = &x[3 * f[6 * k + i]];
        for (int i = 0; i < 3; ++i)
            for (int d = 0; d < 3; ++d) EXPECT_NEAR(p[3 + i][d], 0.5 * (p[i][d] + p[(i + 1) % 3][d]), 1e-12);
        const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        // Outward: the normal points away from the cube's centre (0.5, 0.5, 0.5).
        EXPECT_GT(n[0] * (p[0][0] - 0.5) + n[1] * (p[0][1] - 0.5) + n[2] * (p[0][2] - 0.5), 0.0);
    }
    EXPECT_NEAR(area, 6.0, 1e-12);
    const std::string pvd = ::testing::TempDir() + "lfem_quadratic_frame.pvd";
    lfem_vtk_series* series = nullptr;
    ASSERT_EQ(lfem_vtk_series_create(pvd.c_str(), &series), LFEM_OK);
    ASSERT_EQ(lfem_vtk_series_write_frame(series, w), LFEM_OK) << lfem_last_error();
    lfem_vtk_series_destroy(series);
    const std::string vtu = ::testing::TempDir() + "lfem_quadratic_frame_000000.vtu";
    FILE* in = std::fopen(vtu.c_str(), "r");
    ASSERT_NE(in, nullptr);
    std::string text;
    for (int c; (c = std::fgetc(in)) != EOF;) text.push_back(char(c));
    std::fclose(in);
    std::size_t cells24 = 0;
    const std::size_t types = text.find("Name=\"types\"");
    for (std::size_t at = text.find("          24\n", types); at != std::string::npos; at = text.find("          24\n", at + 1))
        ++cells24;
    EXPECT_EQ(cells24, tets);
    std::remove(vtu.c_str());
    std::remove(pvd.c_str());
}

// The composite element's flag is 0 or 1; anything else is refused with its name, and nothing is
// created.
TEST(QuadraticTets, CompositeFlagIsChecked) {
    World w;
    lfem_body_def d = lfem_body_def_default();
    EXPECT_EQ(d.composite_tets, 0);
    d.composite_tets = 2;
    lfem_body b{};
    EXPECT_EQ(lfem_body_create(w, &d, &b), LFEM_INVALID_ARGUMENT);
    EXPECT_NE(std::string(lfem_last_error()).find("composite_tets"), std::string::npos) << lfem_last_error();
    EXPECT_EQ(stats(w).body_count, 0u);
}
