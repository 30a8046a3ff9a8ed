// Stiffness against closed forms computed here from E and nu by hand (lambda and mu too): a
// neo-Hookean bar stretched to 1.5 times its length at nu = 0.3, and a column sagging under its
// own weight. Both are settled with mass-proportional damping, which leaves the equilibrium
// unchanged (it acts on velocities only).
#include <cmath>

#include "physics/lfem_test_util.h"

using namespace lfem_test;

namespace {

// Area (m^2) of the triangle with corners a, b, c.
double triangle_area(const double* a, const double* b, const double* c) {
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

std::vector<uint32_t> boundary_triangles(lfem_world* w, lfem_body b) {
    uint32_t count = 0;
    EXPECT_EQ(lfem_body_get_boundary_triangle_count(w, b, &count), LFEM_OK);
    std::vector<uint32_t> t(3 * std::size_t(count));
    EXPECT_EQ(lfem_body_get_boundary_triangles(w, b, t.data(), count), LFEM_OK);
    return t;
}

// Whether all three corners of boundary triangle t (3 indices) have coordinate k equal to c.
bool triangle_on_plane(const double* X, const uint32_t* t, int k, double c) {
    for (int j = 0; j < 3; ++j)
        if (std::fabs(X[3 * t[j] + k] - c) > 1e-12) return false;
    return true;
}

// Mean of coordinate k over the nodes whose reference coordinate k is c.
double face_mean(const std::vector<double>& x, const double* X, int k, double c) {
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < x.size() / 3; ++i)
        if (std::fabs(X[3 * i + k] - c) < 1e-12) sum += x[3 * i + k], ++n;
    return sum / n;
}

}  // namespace

// The library's neo-Hookean model is the stable neo-Hookean energy of Smith, de Goes and Kim
// (2018) without its log term (src/fem/tet_element.h):
//   psi = mu/2 (tr(F^T F) - 3) - mu (J - 1) + lambda'/2 (J - 1)^2,  lambda' = lambda + mu,
//   P = mu F + (lambda' (J - 1) - mu) cof(F),
// with Lame's mu and lambda of E and nu (lambda' makes it Hooke's law for small strains). A
// bar pulled along x by a nominal (first Piola-Kirchhoff) stress P11 on its ends, its sides
// free: F = diag(l, s, s), J = l s^2, cof(F) = diag(s^2, l s, l s). The free sides, P22 = 0:
//   mu s + (lambda' (J - 1) - mu) l s = 0  =>  J = 1 + mu (1 - 1/l) / lambda',  s = sqrt(J / l),
// and then P11 = mu l + (lambda' (J - 1) - mu) s^2 = mu (l - s^2 / l). The Cauchy stress
// P F^T / J is uniaxial, sigma11 = P11 l / J, which is its von Mises value.
//
// The test takes l = 1.5, loads the ends' reference faces with P11 (each boundary triangle of an
// end gives P11 area / 3 to each of its nodes, along x: the consistent load of a uniform dead
// traction on linear triangles) and lets the bar settle. The homogeneous stretch is an exact
// solution of the discrete equations on any mesh: F constant makes P constant in every tet, the
// element forces cancel at interior nodes, and at the boundary they are those of the traction
// P N over the faces, (P11, 0, 0) on the ends and 0 on the sides, which is the load. So no
// discretisation error enters: what remains is the settling, e^(-omega_1 t) = e^(-50) with
// critical damping of the lowest axial mode over 0.1 s, and round-off. 1e-4 bounds that with a
// wide margin, and is far inside what a wrong energy would give: Hooke's law would stop at
// l = 1 + P11 / E = 1.383; mu 1 % off moves l - 1 and 1 - s by 1.2 %, lambda 1 % off moves
// 1 - s by 0.2 %; lambda' = lambda (the unshifted parameter) moves them by 5 % and 22 %.
TEST(Stiffness, NeoHookeanBarUnderUniaxialStressStretchesAsTheEnergySays) {
    lfem_world_def wd = lfem_world_def_default();
    wd.gravity[2] = 0.0;
    World w(wd);
    const double L = 0.2, a = 0.05, E = 1e6, nu = 0.3, rho = 1000.0;
    const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), lambda_p = lambda + mu;
    const double l = 1.5, J = 1 + mu * (1 - 1 / l) / lambda_p, s = std::sqrt(J / l);
    const double P11 = mu * (l - s * s / l), sigma = P11 * l / J;

    Mesh mesh;
    make_box_mesh(mesh, L, a, a, 4, 2, 2);  // 2 x 2 across: interior nodes too
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_NEO_HOOKEAN;
    def.young_modulus = E;
    def.poisson_ratio = nu;
    def.density = rho;
    const double omega_1 = M_PI * std::sqrt(E / rho) / L;  // lowest axial mode of the free bar
    def.damping = 2 * omega_1;
    const lfem_body b = add_body(w, def, mesh);

    const double* X = lfem_mesh_get_positions(mesh.m);
    const std::vector<uint32_t> tri = boundary_triangles(w, b);
    std::vector<double> load(3 * std::size_t(mesh.nodes()), 0.0);
    double pulled = 0;
    for (std::size_t t = 0; t < tri.size(); t += 3)
        for (const double end : {0.0, L}) {
            if (!triangle_on_plane(X, &tri[t], 0, end)) continue;
            const double f = (end == 0.0 ? -1.0 : 1.0) * P11 * triangle_area(&X[3 * tri[t]], &X[3 * tri[t + 1]], &X[3 * tri[t + 2]]) / 3;
            for (int j = 0; j < 3; ++j) load[3 * tri[t + j]] += f;
            if (end == L) pulled += 3 * f;
        }
    ASSERT_NEAR(pulled, P11 * a * a, 1e-9 * P11 * a * a);  // the end's whole area, once
    std::vector<uint32_t> nodes;
    std::vector<double> forces;
    for (uint32_t i = 0; i < mesh.nodes(); ++i)
        if (load[3 * i] != 0.0) nodes.push_back(i), forces.insert(forces.end(), {load[3 * i], 0.0, 0.0});
    ASSERT_EQ(lfem_body_set_node_forces(w, b, nodes.data(), uint32_t(nodes.size()), forces.data()), LFEM_OK)
        << lfem_last_error();

    ASSERT_EQ(lfem_world_step(w, 0.1), LFEM_OK) << lfem_last_error();
    const std::vector<double> x = positions(w, b);
    const double stretch = (face_mean(x, X, 0, L) - face_mean(x, X, 0, 0.0)) / L;
    const double side_y = (face_mean(x, X, 1, a) - face_mean(x, X, 1, 0.0)) / a;
    const double side_z = (face_mean(x, X, 2, a) - face_mean(x, X, 2, 0.0)) / a;
    std::vector<double> von_mises(mesh.tets());
    ASSERT_EQ(lfem_body_get_von_mises_stress(w, b, von_mises.data(), mesh.tets()), LFEM_OK);
    double worst_stress = 0;
    for (double v : von_mises) worst_stress = std::fmax(worst_stress, std::fabs(v / sigma - 1));
    std::printf("neo-Hookean bar under P11 = %.6g Pa: stretch %.7f (closed form %.7f), sides %.7f, %.7f (%.7f), "
                "von Mises within %.1e of sigma11 = %.6g Pa, %llu steps\n",
                P11, stretch, l, side_y, side_z, s, worst_stress, sigma, (unsigned long long)stats(w).steps);
    EXPECT_NEAR(stretch - 1, l - 1, 1e-4 * (l - 1));
    EXPECT_NEAR(1 - side_y, 1 - s, 1e-4 * (1 - s));
    EXPECT_NEAR(1 - side_z, 1 - s, 1e-4 * (1 - s));
    EXPECT_LT(worst_stress, 1e-4);
}

// A column standing on its fixed base shortens under its own weight. At nu = 0 the uniaxial
// stress sigma_zz = -rho g (L - z) strains nothing sideways, so fixing the base's nodes in all
// directions is exact and the top settles by delta = rho g L^2 / (2E). On the mesh: with
// nu = 0 (lambda = 0) the virtual work of a test field (0, 0, phi(z)), phi linear in z between
// the node layers, involves u only through its integrals over the layers' planes,
// U_k = integral of u_z over plane k, and the lumped weights through each plane's total; those
// totals are rho g A h (half at the top) as the test checks below, so the U_k obey the 1-D
// finite element equations with the consistent load, which are exact at the nodes. Hence the
// area-weighted mean of u_z over the top face is exactly rho g L^2 / (2E) for linear elasticity
// on any mesh layered in z (the plain mean of its nodes' is not: 4e-4 off on this mesh). What
// remains is the settling (critical damping of the lowest axial mode over 20 / omega_1: e^-20)
// and, for the corotational model, rotation terms of second order (~(rho g L / E)^2 = 1e-6):
// 1e-5 bounds both; E 20 % off is 17 % off.
TEST(Stiffness, ColumnSagsUnderItsOwnWeightAsRhoGLSquaredOver2E) {
    const double L = 1.0, a = 0.1, E = 1e7, rho = 1000.0, g = 9.81;
    const uint32_t layers = 10;
    const double expected = rho * g * L * L / (2 * E);
    for (lfem_model model : {LFEM_MODEL_LINEAR, LFEM_MODEL_COROTATIONAL}) {
        World w;  // gravity (0, 0, -9.81)
        Mesh mesh;
        make_box_mesh(mesh, a, a, L, 2, 2, layers, -a / 2, -a / 2, 0.0);
        lfem_body_def def = lfem_body_def_default();
        def.model = model;
        def.young_modulus = E;
        def.poisson_ratio = 0.0;
        def.density = rho;
        const double omega_1 = M_PI * std::sqrt(E / rho) / (2 * L);  // fixed-free bar
        def.damping = 2 * omega_1;
        const lfem_body b = add_body(w, def, mesh);
        const double lo[3] = {-1, -1, -1e-9}, hi[3] = {1, 1, 1e-9};
        const std::vector<uint32_t> base = nodes_in_box(w, b, lo, hi);
        ASSERT_EQ(base.size(), 9u);
        ASSERT_EQ(lfem_body_fix_nodes(w, b, base.data(), uint32_t(base.size())), LFEM_OK) << lfem_last_error();

        // The premise: each layer plane's lumped mass (rho V / 4 from every tet a node is in,
        // src/DESIGN.md) is rho A h, half at the top, whatever the tet split.
        const double* X = lfem_mesh_get_positions(mesh.m);
        const uint32_t* tets = lfem_mesh_get_tets(mesh.m);
        const std::vector<double> X0(X, X + 3 * std::size_t(mesh.nodes()));
        const double h = L / layers;
        std::vector<double> plane_mass(layers + 1, 0.0);
        for (uint32_t e = 0; e < mesh.tets(); ++e) {
            const double m = rho * volume(X0, tets + 4 * e, 1) / 4;
            for (int j = 0; j < 4; ++j) plane_mass[std::lround(X[3 * tets[4 * e + j] + 2] / h)] += m;
        }
        for (uint32_t k = 1; k <= layers; ++k)
            ASSERT_NEAR(plane_mass[k], rho * a * a * h * (k == layers ? 0.5 : 1.0), 1e-12) << "plane " << k;

        ASSERT_EQ(lfem_world_step(w, 20 / omega_1), LFEM_OK) << lfem_last_error();
        const std::vector<double> x = positions(w, b);
        const std::vector<uint32_t> tri = boundary_triangles(w, b);
        double area = 0, integral = 0;
        for (std::size_t t = 0; t < tri.size(); t += 3) {
            if (!triangle_on_plane(X, &tri[t], 2, L)) continue;
            const double A = triangle_area(&X[3 * tri[t]], &X[3 * tri[t + 1]], &X[3 * tri[t + 2]]);
            area += A;
            for (int j = 0; j < 3; ++j) integral += A / 3 * (x[3 * tri[t + j] + 2] - X[3 * tri[t + j] + 2]);
        }
        ASSERT_NEAR(area, a * a, 1e-12);
        const double sag = -integral / area;
        std::printf("column (%s) under its own weight: top sags %.7e m, rho g L^2/(2E) = %.7e m (%+.1e), %llu steps\n",
                    model_name(model), sag, expected, sag / expected - 1, (unsigned long long)stats(w).steps);
        EXPECT_NEAR(sag, expected, 1e-5 * expected) << model_name(model);
    }
}
