// lfem and Bullet 3.24's deformable world side by side (issue 7): soft cubes of 6000 tets
// (10^3 cells, 0.2 m, E = 1e5 Pa, nu = 0.3, rho = 1000 kg/m^3, neo-Hookean) dropped from 1 cm
// onto a static floor, 1 and 16 cubes, the same simulated time and the same step (lfem's
// automatic stable step, which Bullet's implicit solver is also given). Reported, each measured
// in this one run: wall time per simulated second, tet-steps per second, the largest
// penetration of any node into the floor (sampled every 10 steps), and the RMS node velocity
// at the end.
//
//   bench_bullet_side_by_side [simulated seconds, default 0.5]
//
// Built only when Bullet is found; not part of the test command.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableGravityForce.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btDeformableNeoHookeanForce.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <btBulletDynamicsCommon.h>

#include "lfem.h"

namespace {

constexpr double kEdge = 0.2, kYoung = 1e5, kPoisson = 0.3, kDensity = 1000.0, kDrop = 0.01;
constexpr double kFriction = 0.5;

struct Figures {
    double wall = 0;          // s, stepping only
    double steps = 0;
    double tets = 0;
    double penetration = 0;   // m, largest over the run
    double rms_velocity = 0;  // m/s, at the end
};

// The cube mesh (lfem's box builder), placed with its lowest face kDrop above z = 0.
struct CubeMesh {
    std::vector<double> x;
    std::vector<uint32_t> tets;
};
CubeMesh cube_mesh() {
    const double size[3] = {kEdge, kEdge, kEdge};
    const uint32_t cells[3] = {10, 10, 10};
    lfem_mesh* m = nullptr;
    if (lfem_mesh_create_box(size, cells, &m) != LFEM_OK) std::exit(1);
    CubeMesh out;
    const double* p = lfem_mesh_get_positions(m);
    out.x.assign(p, p + 3 * lfem_mesh_get_node_count(m));
    const uint32_t* t = lfem_mesh_get_tets(m);
    out.tets.assign(t, t + 4 * lfem_mesh_get_tet_count(m));
    lfem_mesh_destroy(m);
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    for (std::size_t i = 0; i < out.x.size(); ++i) lo[i % 3] = std::min(lo[i % 3], out.x[i]);
    for (std::size_t i = 0; i < out.x.size(); ++i)
        out.x[i] += (i % 3 == 2 ? kDrop : -0.5 * kEdge) - lo[i % 3];
    return out;
}

// Cube k of n on a square grid, 0.1 m apart.
void cube_offset(int k, int n, double* d) {
    const int side = int(std::ceil(std::sqrt(double(n))));
    d[0] = (k % side) * (kEdge + 0.1);
    d[1] = (k / side) * (kEdge + 0.1);
    d[2] = 0.0;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Figures run_lfem(int cubes, double T, double* step_out) {
    const CubeMesh mesh = cube_mesh();
    lfem_world_def wd = lfem_world_def_default();
    lfem_world* w = nullptr;
    lfem_world_create(&wd, &w);
    lfem_body_def fd = lfem_body_def_default();
    fd.type = LFEM_BODY_STATIC;
    fd.friction = kFriction;
    lfem_body floor_body;
    lfem_body_create(w, &fd, &floor_body);
    lfem_shape_def sd = lfem_shape_def_default();  // the plane z = 0, solid below
    lfem_body_add_shape(w, floor_body, &sd);
    lfem_body_def bd = lfem_body_def_default();
    bd.model = LFEM_MODEL_NEO_HOOKEAN;
    bd.young_modulus = kYoung;
    bd.poisson_ratio = kPoisson;
    bd.density = kDensity;
    bd.friction = kFriction;
    bd.damping = 5.0;  // 1/s, mass-proportional: lets the cubes come to rest
    std::vector<lfem_body> bodies(cubes);
    const uint32_t n = uint32_t(mesh.x.size() / 3), t = uint32_t(mesh.tets.size() / 4);
    for (int k = 0; k < cubes; ++k) {
        double d[3];
        cube_offset(k, cubes, d);
        std::vector<double> x = mesh.x;
        for (std::size_t i = 0; i < x.size(); ++i) x[i] += d[i % 3];
        lfem_body_create(w, &bd, &bodies[k]);
        if (lfem_body_add_mesh(w, bodies[k], x.data(), n, mesh.tets.data(), t) != LFEM_OK) {
            std::fprintf(stderr, "lfem: %s\n", lfem_last_error());
            std::exit(1);
        }
    }
    double limit = 0;
    lfem_world_get_stable_step(w, &limit);
    const double h = wd.step_safety * limit;
    *step_out = h;
    const int steps = int(std::ceil(T / h));
    Figures f;
    std::vector<double> x(3 * n), v(3 * n);
    for (int s = 0; s < steps; ++s) {
        const auto t0 = std::chrono::steady_clock::now();
        if (lfem_world_step(w, h) != LFEM_OK) {
            std::fprintf(stderr, "lfem: %s\n", lfem_last_error());
            std::exit(1);
        }
        f.wall += seconds_since(t0);
        if (s % 10 == 9 || s + 1 == steps)
            for (lfem_body b : bodies) {
                lfem_body_get_positions(w, b, x.data(), n);
                for (uint32_t i = 0; i < n; ++i) f.penetration = std::max(f.penetration, -x[3 * i + 2]);
            }
    }
    double sum = 0;
    for (lfem_body b : bodies) {
        lfem_body_get_velocities(w, b, v.data(), n);
        for (double c : v) sum += c * c;
    }
    f.rms_velocity = std::sqrt(sum / (double(n) * cubes));
    f.steps = steps;
    f.tets = double(t) * cubes;
    lfem_world_destroy(w);
    return f;
}

Figures run_bullet(int cubes, double T, double h) {
    const CubeMesh mesh = cube_mesh();
    auto config = std::make_unique<btSoftBodyRigidBodyCollisionConfiguration>();
    auto dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
    auto broadphase = std::make_unique<btDbvtBroadphase>();
    auto deformable_solver = std::make_unique<btDeformableBodySolver>();
    auto constraint_solver = std::make_unique<btDeformableMultiBodyConstraintSolver>();
    constraint_solver->setDeformableSolver(deformable_solver.get());
    auto world = std::make_unique<btDeformableMultiBodyDynamicsWorld>(
        dispatcher.get(), broadphase.get(), constraint_solver.get(), config.get(),
        deformable_solver.get());
    const btVector3 gravity(0, 0, -9.81);
    world->setGravity(gravity);
    world->getWorldInfo().m_gravity = gravity;
    world->getWorldInfo().m_sparsesdf.setDefaultVoxelsz(0.25);
    world->getWorldInfo().m_sparsesdf.Reset();

    // Static floor: a box whose top face is z = 0.
    auto ground_shape = std::make_unique<btBoxShape>(btVector3(50, 50, 1));
    btTransform ground_pose;
    ground_pose.setIdentity();
    ground_pose.setOrigin(btVector3(0, 0, -1));
    auto ground_motion = std::make_unique<btDefaultMotionState>(ground_pose);
    btRigidBody::btRigidBodyConstructionInfo info(0, ground_motion.get(), ground_shape.get());
    auto ground = std::make_unique<btRigidBody>(info);
    ground->setFriction(kFriction);
    world->addRigidBody(ground.get());

    const double mu = kYoung / (2 * (1 + kPoisson));
    const double lambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
    const int n = int(mesh.x.size() / 3), t = int(mesh.tets.size() / 4);
    std::vector<btSoftBody*> bodies;
    std::vector<std::unique_ptr<btDeformableLagrangianForce>> forces;
    for (int k = 0; k < cubes; ++k) {
        double d[3];
        cube_offset(k, cubes, d);
        std::vector<btVector3> x(n);
        for (int i = 0; i < n; ++i)
            x[i] = btVector3(mesh.x[3 * i] + d[0], mesh.x[3 * i + 1] + d[1], mesh.x[3 * i + 2] + d[2]);
        btSoftBody* psb = new btSoftBody(&world->getWorldInfo(), n, x.data(), nullptr);
        for (int e = 0; e < t; ++e) {
            const uint32_t* q = &mesh.tets[4 * e];
            psb->appendTetra(q[0], q[1], q[2], q[3]);
            const int pairs[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
            for (const auto& p : pairs) psb->appendLink(q[p[0]], q[p[1]], nullptr, true);
        }
        btSoftBodyHelpers::generateBoundaryFaces(psb);
        psb->initializeDmInverse();
        // Bullet's TetraScratch leaves its matrices unset until its solver fills them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
        psb->m_tetraScratches.resize(psb->m_tetras.size());
        psb->m_tetraScratchesTn.resize(psb->m_tetras.size());
#pragma GCC diagnostic pop
        psb->setTotalMass(btScalar(kDensity * kEdge * kEdge * kEdge));
        psb->getCollisionShape()->setMargin(0.005);
        psb->m_cfg.kKHR = 1;
        psb->m_cfg.kCHR = 1;
        psb->m_cfg.kDF = kFriction;
        psb->m_cfg.collisions = btSoftBody::fCollision::SDF_RD | btSoftBody::fCollision::SDF_RDN |
                                btSoftBody::fCollision::VF_DD;
        psb->m_sleepingThreshold = 0;
        world->addSoftBody(psb);
        forces.push_back(std::make_unique<btDeformableGravityForce>(gravity));
        world->addForce(psb, forces.back().get());
        forces.push_back(std::make_unique<btDeformableNeoHookeanForce>(mu, lambda, 0.05));
        world->addForce(psb, forces.back().get());
        bodies.push_back(psb);
    }
    const int steps = int(std::ceil(T / h));
    Figures f;
    for (int s = 0; s < steps; ++s) {
        const auto t0 = std::chrono::steady_clock::now();
        world->stepSimulation(btScalar(h), 0);
        f.wall += seconds_since(t0);
        if (s % 10 == 9 || s + 1 == steps)
            for (btSoftBody* b : bodies)
                for (int i = 0; i < b->m_nodes.size(); ++i)
                    f.penetration = std::max(f.penetration, double(-b->m_nodes[i].m_x.z()));
    }
    double sum = 0;
    for (btSoftBody* b : bodies)
        for (int i = 0; i < b->m_nodes.size(); ++i) sum += b->m_nodes[i].m_v.length2();
    f.rms_velocity = std::sqrt(sum / (double(n) * cubes));
    f.steps = steps;
    f.tets = double(t) * cubes;
    for (btSoftBody* b : bodies) {
        world->removeSoftBody(b);
        delete b;
    }
    world->removeRigidBody(ground.get());
    return f;
}

void print(const char* who, int cubes, double T, double h, const Figures& f) {
    std::printf("%-7s %5d %10.2e %14.2f %14.3f %14.2e %12.2e\n", who, cubes, h, f.wall / T,
                f.tets * f.steps / f.wall / 1e6, f.penetration, f.rms_velocity);
}

}  // namespace

int main(int argc, char** argv) {
    const double T = argc > 1 ? std::atof(argv[1]) : 0.5;
    if (!(T > 0)) {
        std::fprintf(stderr, "usage: %s [simulated seconds > 0]\n", argv[0]);
        return 2;
    }
    std::printf("soft cubes of 6000 tets on a static floor, %.3g s simulated, one thread each\n", T);
    std::printf("%-7s %5s %10s %14s %14s %14s %12s\n", "engine", "cubes", "step (s)",
                "wall s/sim s", "Mtet-steps/s", "penetration m", "rms v (m/s)");
    for (int cubes : {1, 16}) {
        double h = 0;
        const Figures l = run_lfem(cubes, T, &h);
        print("lfem", cubes, T, h, l);
        const Figures b = run_bullet(cubes, T, h);
        print("bullet", cubes, T, h, b);
        std::printf("%-7s %5d %10s %13.1fx\n", "ratio", cubes, "", b.wall / l.wall);
        std::fflush(stdout);
    }
    return 0;
}
