// The Bullet side of the benchmark: the scene of scene.h in Bullet's deformable world
// (btDeformableMultiBodyDynamicsWorld), each cube a btSoftBody built from the same nodes, tets
// and lumped masses, with btDeformableNeoHookeanForce (mu, lambda from E, nu) and
// btDeformableGravityForce, on a static ground, one thread, a fixed step.
//
// The ground is a static btBoxShape whose top face is z = 0, not a btStaticPlaneShape: the
// deformable world finds rigid contacts through a sparse signed distance field
// (btSparseSdf::DistanceToShape), which answers 0 for any non-convex shape, and a plane is
// non-convex in Bullet, so cubes fall through a plane. The Bullet deformable demos use a box.
#include "run_bullet.h"

#include <btBulletDynamicsCommon.h>
#include <BulletSoftBody/btDeformableBodySolver.h>
#include <BulletSoftBody/btDeformableMultiBodyConstraintSolver.h>
#include <BulletSoftBody/btDeformableMultiBodyDynamicsWorld.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "../bench_common.h"

namespace {

// Everything a Bullet world owns, destroyed in the reverse order of creation.
struct BulletWorld {
    std::unique_ptr<btSoftBodyRigidBodyCollisionConfiguration> config{
        new btSoftBodyRigidBodyCollisionConfiguration()};
    std::unique_ptr<btCollisionDispatcher> dispatcher{new btCollisionDispatcher(config.get())};
    std::unique_ptr<btDbvtBroadphase> broadphase{new btDbvtBroadphase()};
    std::unique_ptr<btDeformableBodySolver> body_solver{new btDeformableBodySolver()};
    std::unique_ptr<btDeformableMultiBodyConstraintSolver> solver{
        new btDeformableMultiBodyConstraintSolver()};
    std::unique_ptr<btDeformableMultiBodyDynamicsWorld> world;
    std::unique_ptr<btBoxShape> ground_shape;
    std::unique_ptr<btDefaultMotionState> ground_motion;
    std::unique_ptr<btRigidBody> ground;
    std::vector<std::unique_ptr<btSoftBody>> cubes;
    std::vector<std::unique_ptr<btDeformableLagrangianForce>> forces;

    ~BulletWorld() {
        if (!world) return;
        for (auto& c : cubes) world->removeSoftBody(c.get());
        if (ground) world->removeRigidBody(ground.get());
    }
};

}  // namespace

extern "C" const char* bench_bullet_version(void) {
    static char text[16];
    std::snprintf(text, sizeof text, "%d.%02d", btGetVersion() / 100, btGetVersion() % 100);
    return text;
}

extern "C" bench_result bench_run_bullet(const bench_scene* s) {
    bench_result r{};
    BulletWorld b;
    const btVector3 gravity(0, 0, btScalar(-9.81));
    // Lame parameters from E and nu, then handed to Bullet so that its energy has them at small
    // strain. Bullet's stable neo-Hookean (Smith, de Goes & Kim 2018, with the log term) has
    // P = mu (1 - 1/(I_C + 1)) F + (lambda (J - 1) - 3/4 mu) cof F, whose linearisation at
    // F = I is Hooke's law with shear modulus 3/4 mu and Lame lambda - 5/8 mu: passed E and nu
    // as they are, Bullet's cube would be a quarter softer than lfem's (whose stable
    // neo-Hookean linearises to exactly (mu, lambda)). The paper's remapping mu_B = 4/3 mu,
    // lambda_B = lambda + 5/6 mu gives both engines the same small-strain material.
    const double mu = s->young_modulus / (2 * (1 + s->poisson_ratio));
    const double lambda = s->young_modulus * s->poisson_ratio /
                          ((1 + s->poisson_ratio) * (1 - 2 * s->poisson_ratio));
    const double mu_bullet = 4.0 / 3.0 * mu, lambda_bullet = lambda + 5.0 / 6.0 * mu;
    const unsigned cube_count = s->grid * s->grid, nodes = s->node_count;
    const unsigned frames = unsigned(std::lround(s->duration / s->frame));
    const unsigned rest_from = frames - frames / 10;  // the last 10 % of the frames
    const btScalar step = btScalar(s->frame / s->bullet_substeps);
    bench_meter meter{};
    std::vector<double> x(3 * nodes), v(3 * nodes);

    b.solver->setDeformableSolver(b.body_solver.get());
    b.world.reset(new btDeformableMultiBodyDynamicsWorld(b.dispatcher.get(), b.broadphase.get(),
                                                         b.solver.get(), b.config.get(),
                                                         b.body_solver.get()));
    b.world->setGravity(gravity);
    btSoftBodyWorldInfo& info = b.world->getWorldInfo();
    info.m_gravity = gravity;
    // Voxels of the signed distance field: a quarter of a cube, as in Bullet's demos (0.25 for
    // 1 m bodies); the box's top face is a plane, which the field's trilinear interpolation
    // reproduces exactly.
    info.m_sparsesdf.setDefaultVoxelsz(btScalar(0.25 * s->edge));
    info.m_sparsesdf.Reset();
    b.world->setImplicit(s->bullet_implicit != 0);
    b.world->setLineSearch(false);

    // Ground: a box far wider than the grid, top face at z = 0.
    const double wide = 2.0 * s->grid * (s->edge + s->spacing) + s->edge;
    b.ground_shape.reset(new btBoxShape(btVector3(btScalar(wide), btScalar(wide),
                                                  btScalar(s->edge))));
    btTransform at;
    at.setIdentity();
    at.setOrigin(btVector3(0, 0, btScalar(-s->edge)));
    b.ground_motion.reset(new btDefaultMotionState(at));
    btRigidBody::btRigidBodyConstructionInfo ground_info(0, b.ground_motion.get(),
                                                         b.ground_shape.get());
    b.ground.reset(new btRigidBody(ground_info));
    b.ground->setFriction(btScalar(s->friction));  // times the cubes' kDF = 1 below
    b.world->addRigidBody(b.ground.get());

    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (unsigned e = 0; e < s->tet_count; ++e) {
        const uint32_t* t = s->tets + 4 * e;
        for (int a = 0; a < 4; ++a)
            for (int c = a + 1; c < 4; ++c)
                edges.emplace_back(std::min(t[a], t[c]), std::max(t[a], t[c]));
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    std::vector<btVector3> placed(nodes);
    std::vector<btScalar> mass(nodes);
    for (unsigned i = 0; i < nodes; ++i) mass[i] = btScalar(s->node_mass[i]);
    for (unsigned k = 0; k < cube_count; ++k) {
        double off[3];
        bench_scene_cube_offset(s, k, off);
        for (unsigned i = 0; i < nodes; ++i)
            placed[i] = btVector3(btScalar(s->positions[3 * i] + off[0]),
                                  btScalar(s->positions[3 * i + 1] + off[1]),
                                  btScalar(s->positions[3 * i + 2] + off[2]));
        btSoftBody* psb = new btSoftBody(&info, int(nodes), placed.data(), mass.data());
        b.cubes.emplace_back(psb);
        for (unsigned e = 0; e < s->tet_count; ++e) {
            const uint32_t* t = s->tets + 4 * e;
            psb->appendTetra(int(t[0]), int(t[1]), int(t[2]), int(t[3]));
        }
        // The tets' edges as links, as CreateFromTetGenData(btetralinks = true) makes them:
        // no force acts on them here, but the node tree's bottom-up build pairs nodes along
        // links and never ends without them. Each edge once (sorted), without Bullet's O(n)
        // existence check per link.
        for (const auto& edge : edges) psb->appendLink(int(edge.first), int(edge.second));
        // What btSoftBodyHelpers::CreateFromTetGenData does after the tets and links.
        psb->initializeDmInverse();
        // (from a filled scratch: Bullet's own TetraScratch has no constructor)
        btSoftBody::TetraScratch blank;
        blank.m_F.setIdentity();
        blank.m_cofF.setIdentity();
        blank.m_corotation.setIdentity();
        blank.m_trace = 3;
        blank.m_J = 1;
        psb->m_tetraScratches.resize(psb->m_tetras.size(), blank);
        psb->m_tetraScratchesTn.resize(psb->m_tetras.size(), blank);
        btSoftBodyHelpers::generateBoundaryFaces(psb);
        psb->getCollisionShape()->setMargin(btScalar(s->bullet_margin));
        psb->m_cfg.kKHR = 1;  // contact hardness with kinematic and rigid objects (demos: 1)
        psb->m_cfg.kCHR = 1;
        psb->m_cfg.kDF = 1;   // friction = kDF x the ground's friction
        // rigid contacts by the signed distance field, node by node (SDF_RDN: without it no
        // node is tested at all)
        psb->m_cfg.collisions = btSoftBody::fCollision::SDF_RD | btSoftBody::fCollision::SDF_RDN;
        psb->m_cfg.drag = btScalar(s->bullet_drag);
        psb->m_sleepingThreshold = 0;  // never put to sleep: every step integrates every node
        b.world->addSoftBody(psb);
        btDeformableLagrangianForce* g = new btDeformableGravityForce(gravity);
        b.forces.emplace_back(g);
        b.world->addForce(psb, g);
        btDeformableLagrangianForce* nh = new btDeformableNeoHookeanForce(
            btScalar(mu_bullet), btScalar(lambda_bullet), btScalar(s->bullet_damping));
        b.forces.emplace_back(nh);
        b.world->addForce(psb, nh);
    }

    r.step_min = r.step_max = step;
    for (unsigned f = 0; f < frames; ++f) {
        const double t0 = bench_now();
        for (unsigned q = 0; q < s->bullet_substeps; ++q)
            b.world->stepSimulation(step, 0, step);  // maxSubSteps 0: exactly one step of `step`
        r.wall_seconds += bench_now() - t0;
        r.steps += s->bullet_substeps;
        for (unsigned k = 0; k < cube_count; ++k) {
            const btSoftBody* psb = b.cubes[k].get();
            for (unsigned i = 0; i < nodes; ++i) {
                const btSoftBody::Node& n = psb->m_nodes[int(i)];
                for (int d = 0; d < 3; ++d) x[3 * i + d] = n.m_x[d], v[3 * i + d] = n.m_v[d];
                // A blown-up run: stop rather than time NaNs.
                if (!(std::fabs(x[3 * i + 2]) < 1e3 * s->edge)) {
                    std::fprintf(stderr, "Bullet blew up at t = %.4f s (step %.3g s)\n",
                                 (f + 1) * s->frame, double(step));
                    return r;
                }
            }
            bench_meter_add(&meter, x.data(), v.data(), nodes, f >= rest_from);
            if (f + 1 == frames)
                for (unsigned i = 0; i < nodes; ++i) {
                    const double z = x[3 * i + 2];
                    if ((k == 0 && i == 0) || z < r.lowest_final) r.lowest_final = z;
                    if ((k == 0 && i == 0) || z > r.top_final) r.top_final = z;
                }
        }
    }
    r.simulated_seconds = frames * s->frame;
    r.tets = double(s->tet_count) * cube_count;
    r.max_penetration = meter.max_penetration;
    r.rest_rms_velocity = std::sqrt(meter.rest_sum_v2 / meter.rest_samples);
    r.ok = 1;
    return r;
}
