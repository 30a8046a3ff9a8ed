// One sub-step, as the pipeline of src/DESIGN.md section 2:
//   predict          central difference (eqs. 1, 3) for the deformable bodies, Newton and
//                    eq. (2) for the rigid ones: x* from the forces at x^n
//   move kinematic   kinematic bodies to where their velocity takes them
//   detect           node-triangle pairs between x^n and x* (eqs. 5, 6), rigid shapes
//   solve            the forward increment multipliers, friction by eq. (7): x* -> x^{n+1}
//   commit           velocities, contact forces, energy bookkeeping
//   rotation update  eq. (2) and the re-fit of the "paper" model's floating frame
//   element forces   elastic forces at x^{n+1}, element by element (they need the frame)
//   energy           the sub-step's tallies added up in slot order
//   warnings         inverted tets, nodes fallen in, an unconverged solve: counted
// Each stage is a function over the list of the bodies it concerns, built once per sub-step.
// Commit, rotation update and element forces concern each body alone: bodies side by side take
// the three in one task (commit_rotate_and_load).
#include <algorithm>
#include <chrono>

#include "common/profile.h"
#include "contact/solve_contact_multipliers.h"
#include "rigid/global_rotation.h"
#include "world/world.h"

namespace lfem {
namespace {

// How far gravity and the node forces move a free node of a moving body in one sub-step of h
// (whose forces act over h_mid): h h_mid times the largest acceleration they give a node (the
// body's total node force over its mass for a rigid body). What a resting contact undoes every
// sub-step, and so the scale of the contact solve's precision at rest.
double load_motion(const Body& b, const double g[3], double h, double h_mid) {
    double accel = 0.0;
    if (b.is_rigid()) {
        Vec3 total = Vec3::Zero();
        const Span<const double> f = b.loads();
        for (std::size_t k = 0; k < f.size(); k += 3) total += Vec3(&f[k]);
        accel = total.norm() / b.ref.total_mass;
    } else {
        const Span<const double> f = b.loads();
        for (std::size_t i = 0; 3 * i < f.size(); ++i) accel = std::max(accel, Vec3(&f[3 * i]).norm() / b.ref.mass[i]);
    }
    return h * h_mid * (Vec3(g).norm() + accel);
}

}  // namespace

// A body that is big, or that holds more than one thread's share of the tets of all the
// deformable bodies, runs its node and element loops on the pool, one such body after another.
// The others run side by side, one body per task, each on one thread: a 6000-tet body has only
// about 3 element blocks per colour and one node block, too little work per round of the pool
// to be worth handing out, while sixteen of them keep two threads busy. A lone small body also
// runs on the pool (there is nothing to put beside it). Either way every loop has the same
// fixed blocks, so the split changes the speed only, never a bit of the result.
void World::plan_stages(double h) {
    StageLists& s = pipeline_.stages;
    for (std::vector<uint32_t>* list : {&s.deformable, &s.rigid, &s.kinematic, &s.paper, &s.with_geometry,
                                        &s.on_pool, &s.side_by_side})
        list->clear();
    pipeline_.bodies.resize(bodies_.slot_count());
    pipeline_.h_mid.assign(bodies_.slot_count(), 0.0);
    uint64_t total = 0;
    for (uint32_t i = 0; i < bodies_.slot_count(); ++i) {
        pipeline_.bodies[i].tally = SubstepTally{};
        pipeline_.bodies[i].touched = false;
        pipeline_.bodies[i].load_motion = 0.0;
        const Body& b = bodies_.slot(i);
        if (!bodies_.live(i) || !b.has_geometry()) continue;
        s.with_geometry.push_back(i);
        if (b.is_kinematic()) s.kinematic.push_back(i);
        if (!b.has_mesh() || b.state.asleep) continue;  // a sleeping body is not stepped
        if (b.is_dynamic()) {
            pipeline_.h_mid[i] = mid_step(b.state.h_last, h);
            // A force for this call alone acts from its start: at the first sub-step over h, not
            // h_mid (half of which is the last call's), so the call's sub-steps give F N h = F dt
            // exactly (the velocity read after the call, extrapolated without it, adds nothing).
            if (!b.call_force.empty())
                bodies_.slot(i).refresh_loads(pipeline_.first_substep ? h / pipeline_.h_mid[i] : 1.0);
            pipeline_.bodies[i].load_motion = load_motion(b, def_.gravity, h, pipeline_.h_mid[i]);
        }
        if (b.is_rigid()) s.rigid.push_back(i);
        if (!b.is_deformable()) continue;
        s.deformable.push_back(i);
        if (b.is_paper()) s.paper.push_back(i);
        total += b.ref.tet_count();
    }
    // A world this small runs on the calling thread alone: a round of the pool costs more than
    // the work it would share (one 162-tet cube took 0.27 ms a frame on 2 threads against 0.15
    // on one). The same blocks either way: the results do not change.
    s.pool = total >= kPoolWork ? pool_.get() : nullptr;
    const uint64_t threads = s.pool ? s.pool->size() : 1;
    for (uint32_t i : s.deformable) {
        const uint64_t tets = bodies_.slot(i).ref.tet_count();
        (tets >= 32 * 1024 || tets * threads > total ? s.on_pool : s.side_by_side).push_back(i);
    }
    if (s.side_by_side.size() == 1) {  // nothing to put beside it
        s.on_pool.push_back(s.side_by_side[0]);
        s.side_by_side.clear();
    }
}

// Calls work(slot, pool) for every deformable body with a mesh: the on_pool bodies one after
// another with the pool for their own loops, the side_by_side ones side by side on the pool with
// none. Each call may write only that body's state and scratch.
template <class Work>
void World::for_each_deformable(const Work& work) {
    for (uint32_t i : pipeline_.stages.on_pool) work(i, pipeline_.stages.pool);
    parallel_for(pipeline_.stages.pool, uint32_t(pipeline_.stages.side_by_side.size()),
                 [&](uint32_t k) { work(pipeline_.stages.side_by_side[k], nullptr); });
}

void World::predict(double h) {
    PhaseTimer timer(profile_.predictor, pipeline_.stages.deformable.size() + pipeline_.stages.rigid.size());
    for (uint32_t i : pipeline_.stages.rigid) {
        Body& b = bodies_.slot(i);
        BodyScratch& sc = pipeline_.bodies[i];
        sc.x_start.assign(b.state.x.begin(), b.state.x.end());
        sc.center_start = Vec3(b.state.global.center);
        const RigidBodyView view = rigid_view(b);
        const double h_mid = pipeline_.h_mid[i];
        predict_rigid(view, def_.gravity, h_mid, h, b.state.global, b.state.x);
        sc.rigid = RigidResponse{};
        sc.rigid.center = Vec3(b.state.global.center);
        sc.rigid.inv_mass = h * h_mid / view.mass;
        sc.rigid.inv_inertia = h * h_mid * rigid_world_inertia(view, b.state.global).inverse();
    }
    for_each_deformable([&](uint32_t i, ThreadPool* pool) {
        Body& b = bodies_.slot(i);
        BodyScratch& sc = pipeline_.bodies[i];
        // "paper": the centre at the start of the step, about which eq. (2) takes its torque;
        // the commit and the rotation update use it too.
        sc.center_start = b.is_paper() ? center_of_mass(b.ref.mass.data(), b.state.x.data(), b.ref.node_count(), pool)
                                       : Vec3::Zero();
        predict_positions(node_loads(b, def_.gravity), pipeline_.h_mid[i], h, b.is_paper() ? sc.center_start.data() : nullptr,
                          b.state.x, b.state.v_half, sc.start, pool);
    });
}

void World::move_kinematic_bodies(double h) {
    if (pipeline_.stages.kinematic.empty()) return;
    PhaseTimer timer(profile_.kinematic_motion, pipeline_.stages.kinematic.size());
    for (uint32_t i : pipeline_.stages.kinematic) {
        Body& b = bodies_.slot(i);
        pipeline_.bodies[i].x_start.assign(b.state.x.begin(), b.state.x.end());
        pipeline_.bodies[i].shape_pose_start.assign(b.state.shape_pose.begin(), b.state.shape_pose.end());
        move_kinematic(Vec3(b.def.linear_velocity), Vec3(b.def.angular_velocity), h, b.state.global.center,
                       b.state.global.rotation, b.state.x,
                       b.state.shape_pose);
    }
}

// Detection between x^n and x*: every body with geometry takes part (contact decides what it
// makes of each); pairs found again are warm-started from the last sub-step's list.
void World::detect() {
    ContactBodies& bodies = contact_.bodies();
    bodies.clear(bodies_.slot_count());
    for (uint32_t i : pipeline_.stages.with_geometry) {
        Body& b = bodies_.slot(i);
        BodyScratch& sc = pipeline_.bodies[i];
        ContactBodyInput in;
        in.slot = i;
        // A sleeping body takes part as a static one (its slaves and its cached candidates
        // those of a static body: the identity says so).
        in.identity = b.geometry_identity() ^ (b.state.asleep ? uint64_t(1) << 31 : 0);
        in.asleep = b.state.asleep != 0;
        in.static_bvh = b.is_static() ? &b.ref.bvh : nullptr;
        in.face_normals = b.is_static() && !b.ref.face_normals.empty() ? b.ref.face_normals.data() : nullptr;
        in.type = b.state.asleep ? BodyKind::static_body : b.def.type;
        in.surface = &b.ref.surface;
        in.every_node = &b.ref.every_node;
        in.elements = b.ref.tets.empty() ? nullptr : b.ref.tets.data();
        in.nodes_per_tet = b.ref.nodes_per_tet;
        in.node_count = b.ref.node_count();
        in.x = b.state.x.data();
        in.x_start = b.is_deformable() ? sc.start.x.data() : sc.x_start.data();
        in.v_last = sc.start.v.data();
        in.inv_mass = sc.start.inv_mass.data();
        in.rigid = &sc.rigid;
        in.friction = b.def.friction;
        in.category = b.def.category_bits;
        in.mask = b.def.mask_bits;
        in.self_contact = b.def.self_contact;
        in.edge_contacts = b.def.edge_contacts;
        in.load_motion = sc.load_motion;
        in.shapes = b.shapes.data();
        in.shape_count = uint32_t(b.shapes.size());
        in.shape_pose = b.state.shape_pose.data();
        in.shape_pose_start = sc.shape_pose_start.data();
        bodies.add(in);
    }
    WorldCounters& c = state_.counters;
    const bool detects = bodies.may_touch();
    pipeline_.fallen = contact_.detect(state_.contacts, c.scan_overlaps, profile_, pipeline_.stages.pool);
    if (detects) c.scan_overlaps = false;
}

// The multipliers move the predicted positions to x^{n+1} (the contact stage), with the
// attachments' links; then what they leave: the links' forces to the attachments, the bodies
// that touch, the events' tallies, and sleepers pressed by an awake body woken.
void World::solve(double h) {
    build_links(pipeline_.frame_fraction, h);
    const ContactSettings settings{def_.contact_iterations, def_.contact_tolerance};
    const ContactOutcome out =
        contact_.solve(pipeline_.links, settings, h, state_.contacts, profile_, pipeline_.stages.pool);
    WorldCounters& c = state_.counters;
    c.solver_iterations = out.solve.iterations;
    c.solver_residual = out.solve.residual;
    c.max_penetration = out.solve.max_penetration;
    pipeline_.unconverged = !out.solve.converged;
    take_link_forces(h);
    mark_touching(out);
    events_.tally(out.pair_forces, out.frozen, pipeline_.h_mid, h);
    wake_touched_sleepers();
}

// The bodies that touch this sub-step (for the commit's contact forces and for waking
// sleepers): those of the pairs that carry force, and the bodies held by attachments.
void World::mark_touching(const ContactOutcome& out) {
    for (const BodyPairForce& f : out.pair_forces) pipeline_.bodies[f.slot_a].touched = pipeline_.bodies[f.slot_b].touched = true;
    for (const ContactRecord& r : out.frozen)
        if (r.active()) pipeline_.bodies[r.body_a].touched = pipeline_.bodies[r.body_b].touched = true;
    for (const LinkRecord& l : pipeline_.links) {  // holds contact forces too
        pipeline_.bodies[l.body_a].touched = true;
        if (l.target_nodes.count > 0) pipeline_.bodies[l.body_b].touched = true;
    }
}

// The commit, the rotation update and the element forces each concern one body at a time:
// body_commit, body_rotation and body_forces. The bodies that run on the pool for their own
// loops take them phase after phase; those side by side take all three in one task per body,
// one round of the pool instead of three, with the body's arrays still in that core's cache
// from one to the next (the same arithmetic in the same order: the results do not change).
// Each phase's share of that round's wall time is its share of the CPU time measured in it.
void World::body_commit(uint32_t i, double h, ThreadPool* pool) {
    Body& b = bodies_.slot(i);
    BodyScratch& sc = pipeline_.bodies[i];
    if (sc.touched) b.state.contact_force.resize(3 * std::size_t(b.ref.node_count()));
    else std::vector<double>().swap(b.state.contact_force);  // nothing held while not touching
    const CommitSums sums =
        commit_positions(node_loads(b, def_.gravity), h, sc.start, b.is_paper() ? sc.center_start.data() : nullptr,
                         b.state.x, b.state.v_half, b.state.contact_force, pool);
    sc.tally.kinetic += sums.kinetic;
    sc.tally.work += sums.work;
    sc.tally.contact_work += sums.contact_work;
    sc.tally.damping += sums.damping;
    sc.torque = sums.torque;
    b.state.h_last = h;
}

void World::body_rotation(uint32_t i, double h, ThreadPool* pool) {
    Body& b = bodies_.slot(i);
    if (!b.is_paper()) return;
    BodyScratch& sc = pipeline_.bodies[i];
    const double drift = update_global_rotation(b.ref.mass.data(), sc.start.x.data(), b.state.x.data(), b.ref.X.data(),
                                                b.ref.node_count(), Vec3(b.ref.com), sc.center_start, sc.torque, h,
                                                b.state.global, pool);
    sc.tally.drift = std::max(sc.tally.drift, drift);
}

void World::body_forces(uint32_t i, ThreadPool* pool) {
    Body& b = bodies_.slot(i);
    update_elastic_forces(b, b.state, pool);
}

// The contact (and attachment) forces that moved a rigid body this sub-step, node by node as
// the deformable commit reports them, m dx / (h h_mid) for the correction's displacement dx of
// each node (dc + dtheta x r): their resultant and moment are the correction's force and torque.
// A body that holds them reports its last step's velocity (synchronized_velocities).
static void record_rigid_contact_force(Body& b, const BodyScratch& sc, double h, double h_mid) {
    std::vector<double>& f = b.state.contact_force;
    const uint32_t n = b.ref.node_count();
    if (!sc.touched || n == 0 || h_mid <= 0.0) {
        std::vector<double>().swap(f);
        return;
    }
    f.resize(3 * std::size_t(n));
    const Vec3 c(b.state.global.center);
    for (uint32_t i = 0; i < n; ++i) {
        const Vec3 dx = sc.rigid.dc + sc.rigid.dtheta.cross(Vec3(&b.state.x[3 * i]) - c);
        const Vec3 fi = b.ref.mass[i] / (h * h_mid) * dx;
        for (int k = 0; k < 3; ++k) f[3 * i + k] = fi[k];
    }
}

void World::commit_rigid_bodies(double h) {
    for (uint32_t i : pipeline_.stages.rigid) {
        Body& b = bodies_.slot(i);
        BodyScratch& sc = pipeline_.bodies[i];
        const RigidBodyView view = rigid_view(b);
        sc.tally.contact_work += commit_rigid(view, h, sc.rigid.dc, sc.rigid.dtheta, b.state.global, b.state.x);
        b.state.h_last = h;
        record_rigid_contact_force(b, sc, h, pipeline_.h_mid[i]);
        // Work of gravity and node forces on the moving centre (node forces' torques act
        // through eq. 2; their work is booked with the translation only).
        const Vec3 dc = Vec3(b.state.global.center) - sc.center_start;
        Vec3 force = b.ref.total_mass * Vec3(def_.gravity);
        const Span<const double> f = b.loads();
        for (std::size_t k = 0; k < f.size(); k += 3) force += Vec3(&f[k]);
        sc.tally.work += force.dot(dc);
        sc.tally.kinetic += rigid_kinetic_energy(view, b.state.global);
        for (std::size_t k = 0; k < b.state.x.size(); ++k) b.state.v_half[k] = (b.state.x[k] - sc.x_start[k]) / h;
    }
}

void World::commit_rotate_and_load(double h) {
    {
        PhaseTimer timer(profile_.commit, pipeline_.stages.deformable.size() + pipeline_.stages.rigid.size());
        commit_rigid_bodies(h);
        for (uint32_t i : pipeline_.stages.on_pool) body_commit(i, h, pipeline_.stages.pool);
    }
    {
        PhaseTimer timer(profile_.global_rotation, pipeline_.stages.paper.size(), !pipeline_.stages.paper.empty());
        for (uint32_t i : pipeline_.stages.on_pool) body_rotation(i, h, pipeline_.stages.pool);
    }
    {
        PhaseTimer timer(profile_.internal_forces, pipeline_.stages.deformable.size());
        for (uint32_t i : pipeline_.stages.on_pool) body_forces(i, pipeline_.stages.pool);
    }
    const uint32_t n = uint32_t(pipeline_.stages.side_by_side.size());
    if (n == 0) return;
    const auto round_start = std::chrono::steady_clock::now();
    parallel_for(pipeline_.stages.pool, n, [&](uint32_t k) {
        const uint32_t i = pipeline_.stages.side_by_side[k];
        BodyScratch& sc = pipeline_.bodies[i];
        const uint64_t t0 = ticks();
        body_commit(i, h, nullptr);
        const uint64_t t1 = ticks();
        uint64_t t2 = t1;  // no rotation update but for the "paper" model: no reading
        if (bodies_.slot(i).is_paper()) {
            body_rotation(i, h, nullptr);
            t2 = ticks();
        }
        body_forces(i, nullptr);
        const uint64_t t3 = ticks();
        sc.phase_ticks[0] = t1 - t0, sc.phase_ticks[1] = t2 - t1, sc.phase_ticks[2] = t3 - t2;
    });
    double cpu[3] = {0, 0, 0};
    for (uint32_t i : pipeline_.stages.side_by_side)
        for (int p = 0; p < 3; ++p) cpu[p] += double(pipeline_.bodies[i].phase_ticks[p]);
    PhaseTime* phases[3] = {&profile_.commit, &profile_.global_rotation, &profile_.internal_forces};
    share_wall_time(seconds_since(round_start), cpu, phases, 3);
}

// kinetic, strain: of the new state; work: what gravity, forces, supports and contacts did
// over the step (added to `work`). The tallies are added up in slot order (the bodies may have
// run side by side).
void World::add_up_energy(double h, double& kinetic, double& strain, double& work) {
    SubstepTally tally;
    for (const BodyScratch& sc : pipeline_.bodies) {
        const SubstepTally& t = sc.tally;
        tally.kinetic += t.kinetic;
        tally.work += t.work;
        tally.contact_work += t.contact_work;
        tally.damping += t.damping;
        tally.drift = std::max(tally.drift, t.drift);
    }
    for (uint32_t i : pipeline_.stages.deformable) strain += bodies_.slot(i).state.strain_energy;
    kinetic = tally.kinetic;
    work += tally.work + tally.contact_work;
    WorldCounters& c = state_.counters;
    c.external_work += tally.work;
    c.dissipated_energy += tally.damping - tally.contact_work;
    c.rotation_drift = tally.drift;
    c.time += h;
    c.steps += 1;
    c.step_size = h;
}

// After add_up_energy: the times are those at the end of the sub-step. A body's inverted
// tets count once per sub-step; it is reported as staying inverted once per spell, when the
// spell reaches kStaysInverted.
void World::count_warnings(double h) {
    WorldCounters& c = state_.counters;
    Warnings& w = c.warnings;
    for (uint32_t i : pipeline_.stages.deformable) {
        BodyState& s = bodies_.slot(i).state;
        const uint32_t generation = bodies_.handle_of(i).generation;
        if (s.inverted_tets == 0) {
            s.inverted_since = -1.0;
            continue;
        }
        w.inverted_tets.note(1, c.time, i, generation);
        if (s.inverted_since < 0.0) s.inverted_since = c.time - h;  // it began in this sub-step
        const double before = c.time - h - s.inverted_since, now = c.time - s.inverted_since;
        if (before < kStaysInverted && now >= kStaysInverted) w.stays_inverted.note(1, c.time, i, generation);
    }
    const FallenIn& fallen = pipeline_.fallen;
    if (fallen.nodes)
        w.fallen_in.note(fallen.nodes, c.time, fallen.last_slot, bodies_.handle_of(fallen.last_slot).generation);
    if (pipeline_.unconverged) w.unconverged.note(1, c.time, 0, 0);
}

void World::substep(double h, double& kinetic, double& strain, double& work) {
    plan_stages(h);
    profile_.substeps += 1;
    predict(h);
    move_kinematic_bodies(h);
    detect();
    solve(h);
    commit_rotate_and_load(h);
    add_up_energy(h, kinetic, strain, work);
    count_warnings(h);
}

}  // namespace lfem
