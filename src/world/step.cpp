// The step pipeline (DESIGN.md section 1). Per sub-step:
//   1. move kinematic bodies; predictor for every deformable body (central difference,
//      eqs. 1 and 3, with the elastic forces computed element by element at x^n);
//   2. contact: detect node-triangle pairs between x^n and x* (eqs. 5, 6) and solve the
//      forward increment multipliers (friction by eq. 7);
//   3. commit: velocities, global rotation (eq. 2, "paper" model), elastic forces at x^{n+1}.
// A call is split into equal sub-steps; if the state blows up the world is restored from a
// snapshot taken at the start of the call.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "common/error.h"
#include "common/profile.h"
#include "common/thread_pool.h"
#include "contact/solve_contact_multipliers.h"
#include "fem/internal_forces.h"
#include "fem/material.h"
#include "fem/tet_element.h"
#include "rigid/global_rotation.h"
#include "world/world.h"

namespace lfem {
namespace {

std::string seconds(double s) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g s", s);
    return buf;
}

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

Eigen::Quaterniond load_q(const double* q) { return {q[0], q[1], q[2], q[3]}; }

double external_force(const Body& b, const double g[3], uint32_t i, int k) {
    return b.ref.mass[i] * g[k] + (b.node_force.empty() ? 0.0 : b.node_force[3 * i + k]);
}

// Predictor, central difference (eqs. 1 and 3) written with the mid-step velocity
// v^{n+1/2} = (x^{n+1} - x^n)/h, which also handles a change of step size:
//   (m/h_mid + c/2) v^{n+1/2} = (m/h_mid - c/2) v^{n-1/2} + R^n,  h_mid = (h_prev + h)/2,
// R^n = gravity + node forces + elastic forces at x^n, c = alpha m. With constant h this is
// exactly x* = (R + 2m/h^2 x^n - (m/h^2 - c/2h) x^{n-1}) / (m/h^2 + c/2h). After a reset
// (h_prev = 0, v^{n-1/2} holds the synchronized velocity) it is the velocity-Verlet start,
// exact for a constant force. Also records 1/mhat per node for the contact solve.
template <class Scratch>
void predict_positions(Body& body, const double gravity[3], double h, Scratch& scratch,
                       ThreadPool* pool) {
    BodyState& s = body.state;
    const BodyReference& ref = body.ref;
    const uint32_t n = ref.node_count();
    const double h_mid = s.h_last > 0.0 ? 0.5 * (s.h_last + h) : 0.5 * h;
    const double alpha = body.def.damping;
    const bool paper = body.def.model == LFEM_MODEL_PAPER;
    scratch.x_start.resize(s.x.size());
    scratch.v_old.resize(s.v_half.size());
    scratch.inv_mass.resize(n);
    // "paper": the centre at the start of the step, about which eq. (2) takes its torque; the
    // commit and the rotation update use it too.
    Vec3 c = Vec3::Zero();
    if (paper) c = center_of_mass(ref.mass.data(), s.x.data(), n, pool);
    for (int k = 0; k < 3; ++k) scratch.center_start[k] = c[k];
    // sums: support work, support torque (3).
    double sums[4] = {0, 0, 0, 0};
    blocked_sum<4>(n, pool, sums, [&](uint32_t i, double* out) {
        for (int k = 0; k < 3; ++k) {
            scratch.x_start[3 * i + k] = s.x[3 * i + k];
            scratch.v_old[3 * i + k] = s.v_half[3 * i + k];
        }
        const double m = ref.mass[i];
        const double lhs = m / h_mid + 0.5 * alpha * m, rhs = m / h_mid - 0.5 * alpha * m;
        const NodeMode mode = body.node_mode[i];
        scratch.inv_mass[i] = mode == NodeMode::free ? h / lhs : 0.0;  // dx = (h/lhs) lambda
        Vec3 reaction;
        for (int k = 0; k < 3; ++k) {
            const double R = external_force(body, gravity, i, k) + s.elastic[3 * i + k];
            double v_new;
            switch (mode) {
                case NodeMode::free: v_new = (rhs * s.v_half[3 * i + k] + R) / lhs; break;
                case NodeMode::fixed: v_new = 0.0; break;
                default: v_new = body.prescribed_velocity[3 * i + k]; break;
            }
            // The support force that makes a fixed or prescribed node follow its motion (zero
            // for free nodes): it does work and exerts torque like an external force.
            reaction[k] = lhs * v_new - rhs * s.v_half[3 * i + k] - R;
            s.v_half[3 * i + k] = v_new;
            s.x[3 * i + k] += h * v_new;
        }
        if (mode != NodeMode::free) {
            const Vec3 dx = Vec3(&s.x[3 * i]) - Vec3(&scratch.x_start[3 * i]);
            out[0] += reaction.dot(dx);
            if (paper) {
                const Vec3 t = (Vec3(&scratch.x_start[3 * i]) - c).cross(reaction);
                for (int k = 0; k < 3; ++k) out[1 + k] += t[k];
            }
        }
    });
    scratch.support_work = sums[0];
    for (int k = 0; k < 3; ++k) scratch.support_torque[k] = sums[1 + k];
}

// Commit: velocities from the corrected positions, energy bookkeeping, and ("paper") the
// torque about the step-start centre that eq. (2) needs.
template <class Scratch>
void commit_step(Body& body, const double gravity[3], double h, Scratch& scratch,
                 bool touched, SubstepTally& tally, ThreadPool* pool) {
    BodyState& s = body.state;
    const BodyReference& ref = body.ref;
    const uint32_t n = ref.node_count();
    const double alpha = body.def.damping;
    const bool paper = body.def.model == LFEM_MODEL_PAPER;
    const Vec3 c_old(scratch.center_start);
    // Every entry is written in the node loop below (zero where no contact acts), so the
    // array is not cleared first: no serial pass over all nodes.
    if (touched) s.contact_force.resize(3 * std::size_t(n));
    else std::vector<double>().swap(s.contact_force);  // nothing held while not touching
    // sums: kinetic energy, work of external forces, contact work, damping, torque (3).
    double sums[7] = {0.0, scratch.support_work, 0.0, 0.0, scratch.support_torque[0],
                      scratch.support_torque[1], scratch.support_torque[2]};
    blocked_sum<7>(n, pool, sums, [&](uint32_t i, double* out) {
        const double m = ref.mass[i];
        Vec3 f_ext, f_contact = Vec3::Zero(), dx;
        for (int k = 0; k < 3; ++k) {
            dx[k] = s.x[3 * i + k] - scratch.x_start[3 * i + k];
            f_ext[k] = external_force(body, gravity, i, k);
            if (touched && scratch.inv_mass[i] > 0.0) {
                // The solve moved the node by (x - x*) = lambda / mhat: its contact force.
                const double correction = dx[k] - h * s.v_half[3 * i + k];
                f_contact[k] = correction / scratch.inv_mass[i];
                s.v_half[3 * i + k] = dx[k] / h;
            }
            if (touched) s.contact_force[3 * i + k] = f_contact[k];
            const double v = s.v_half[3 * i + k];
            out[0] += 0.5 * m * v * v;
            out[3] += alpha * m * 0.5 * (v + scratch.v_old[3 * i + k]) * v * h;
        }
        out[1] += f_ext.dot(dx);
        out[2] += f_contact.dot(dx);
        if (paper) {
            const Vec3 t = (Vec3(&scratch.x_start[3 * i]) - c_old).cross(f_ext + f_contact);
            for (int k = 0; k < 3; ++k) out[4 + k] += t[k];
        }
    });
    const double kinetic = sums[0], work = sums[1], contact_work = sums[2], damping = sums[3];
    const Vec3 torque(sums + 4);
    tally.kinetic += kinetic;
    tally.work += work;
    tally.contact_work += contact_work;
    tally.damping += damping;
    for (int k = 0; k < 3; ++k) scratch.torque[k] = torque[k];
    s.h_last = h;
}

// "paper" model: eq. (2) predicts the frame's rotation from the torque of the step; re-fitting
// it to the nodes keeps it free of drift. Their difference is reported as an error indicator.
template <class Scratch>
void update_global_rotation(Body& body, double h, const Scratch& scratch, SubstepTally& tally,
                            ThreadPool* pool) {
    BodyState& s = body.state;
    const BodyReference& ref = body.ref;
    const uint32_t n = ref.node_count();
    const Vec3 c_old(scratch.center_start);
    const Eigen::Matrix3d inertia = inertia_tensor(ref.mass.data(), scratch.x_start.data(), n, c_old, pool);
    const Vec3 torque(scratch.torque);
    {
        Vec3 L(s.angular_momentum);
        Eigen::Quaterniond q = load_q(s.rotation);
        integrate_global_rotation(inertia, torque, h, L, q);
        const Eigen::Quaterniond predicted = q;
        const Vec3 c_new = center_of_mass(ref.mass.data(), s.x.data(), n, pool);
        fit_global_rotation(ref.mass.data(), s.x.data(), ref.X.data(), n, c_new, Vec3(ref.com), q,
                            pool);
        tally.drift = std::max(tally.drift, predicted.angularDistance(q));
        s.rotation[0] = q.w(), s.rotation[1] = q.x(), s.rotation[2] = q.y(), s.rotation[3] = q.z();
        for (int k = 0; k < 3; ++k) s.angular_momentum[k] = L[k];
    }
}

// Kinematic bodies move rigidly: centre by v h, nodes rotated by omega h about it.
void advance_kinematic(Body& body, double h) {
    BodyState& s = body.state;
    const Vec3 lin(body.def.linear_velocity), ang(body.def.angular_velocity);
    const Vec3 c_old(s.center);
    const Vec3 c_new = c_old + h * lin;
    const double angle = h * ang.norm();
    const Eigen::Matrix3d Rot =
        angle > 0.0 ? Eigen::AngleAxisd(angle, ang.normalized()).toRotationMatrix()
                    : Eigen::Matrix3d::Identity();
    for (uint32_t i = 0; i < body.ref.node_count(); ++i) {
        const Vec3 x = c_new + Rot * (Vec3(&s.x[3 * i]) - c_old);
        for (int k = 0; k < 3; ++k) s.x[3 * i + k] = x[k];
    }
    const Eigen::Quaterniond turn(Rot);
    for (std::size_t j = 0; j < s.shape_pose.size(); j += 7) {
        ShapePose pose = ShapePose::load(&s.shape_pose[j]);
        pose.center = c_new + Rot * (pose.center - c_old);
        pose.rotation = (turn * pose.rotation).normalized();
        pose.store(&s.shape_pose[j]);
    }
    for (int k = 0; k < 3; ++k) s.center[k] = c_new[k];
}

}  // namespace

// Contact stage: detection between x^n and x*, then the multiplier solve, which moves the
// predicted positions to x^{n+1}. Warm start from the last sub-step's multipliers of the same
// (node, body) pair.
void World::solve_contacts(double h) {
    contact_bodies_.clear();
    contact_body_of_slot_.assign(slots_.size(), UINT32_MAX);
    uint32_t movable = 0;
    for (uint32_t i = 0; i < slots_.size(); ++i) {
        Body& b = slots_[i].body;
        if (b.generation == 0 || !b.has_geometry()) continue;
        ContactBody cb;
        cb.slot = i;
        cb.triangles = b.ref.boundary.data();
        cb.triangle_count = uint32_t(b.ref.boundary.size() / 3);
        // Slave nodes: every boundary node of a deformable body; only the edge and corner
        // nodes of a static or kinematic one (its flat faces are enforced by the other pass).
        const std::vector<uint32_t>& slaves = b.is_dynamic() ? b.ref.boundary_nodes : b.ref.feature_nodes;
        cb.nodes = slaves.data();
        cb.node_count = uint32_t(slaves.size());
        cb.total_nodes = b.ref.node_count();
        cb.x = b.state.x.data();
        cb.x_start = b.def.type == LFEM_BODY_STATIC ? b.state.x.data() : scratch_[i].x_start.data();
        cb.inv_mass = b.is_deformable() ? scratch_[i].inv_mass.data() : nullptr;
        cb.rigid = b.is_rigid() ? &rigid_responses_[i] : nullptr;
        cb.friction = b.def.friction;
        cb.category = b.def.category_bits;
        cb.mask = b.def.mask_bits;
        cb.edge_length = b.ref.edge_length;
        cb.shapes = b.shapes.data();
        cb.shape_count = uint32_t(b.shapes.size());
        cb.shape_pose = b.state.shape_pose.data();
        cb.shape_pose_start = b.def.type == LFEM_BODY_KINEMATIC ? scratch_[i].shape_pose_start.data()
                                                                 : b.state.shape_pose.data();
        contact_body_of_slot_[i] = uint32_t(contact_bodies_.size());
        contact_bodies_.push_back(cb);
        movable += b.is_dynamic();
    }
    detected_.clear();
    counters_.solver_iterations = 0;
    counters_.solver_residual = 0.0;
    counters_.max_penetration = 0.0;
    if (movable > 0 && contact_bodies_.size() > 1) {
        detect_node_triangle(contact_bodies_, contacts_, counters_.scan_overlaps, detection_, detected_,
                             profile_, pool_.get());
        counters_.scan_overlaps = false;
    }
    // Warm start: both lists are ordered by (body_a, node, body_b). Timed with the solve.
    double motion = 0.0, length = HUGE_VAL;
    PhaseTimer warm_start_timer(profile_.normal_solve, 0, !detected_.empty());
    std::size_t k = 0;
    for (ContactRecord& r : detected_) {
        while (k < contacts_.size() &&
               std::tie(contacts_[k].body_a, contacts_[k].node, contacts_[k].body_b) <
                   std::tie(r.body_a, r.node, r.body_b))
            ++k;
        if (k < contacts_.size() && contacts_[k].body_a == r.body_a && contacts_[k].node == r.node &&
            contacts_[k].body_b == r.body_b) {
            r.lambda_n = contacts_[k].lambda_n;
            for (int d = 0; d < 3; ++d) r.lambda_t[d] = contacts_[k].lambda_t[d];
        }
        // The scale of the pair's relative motion sets the stopping tolerance: the relative
        // velocity at the start of the step (last step's mid-step velocities) times h. Not the
        // predicted motion, which under a resting load is mostly the sag that contact undoes.
        const ContactBody& a = contact_bodies_[contact_body_of_slot_[r.body_a]];
        const ContactBody& b = contact_bodies_[contact_body_of_slot_[r.body_b]];
        const double w[3] = {1.0 - r.t1 - r.t2, r.t2, r.t1};
        for (int d = 0; d < 3; ++d) {
            double rel = step_velocity(r.body_a, r.node, d, h);
            if (r.shape != UINT32_MAX)
                rel -= (r.point_end[d] - r.point_start[d]) / h;  // the shape's surface moves rigidly
            else
                for (int v = 0; v < 3; ++v) rel -= w[v] * step_velocity(r.body_b, r.triangle[v], d, h);
            motion = std::max(motion, std::fabs(rel) * h);
        }
        length = std::min({length, a.edge_length, b.edge_length});
    }
    warm_start_timer.stop();
    if (!detected_.empty()) {
        // Stop when a sweep moves no node by more than contact_tolerance times the relative
        // motion, or 1e-9 of the finest boundary edge when nothing moves (resting contact).
        const double tolerance = std::max(def_.contact_tolerance * motion, 1e-9 * length);
        const ContactSolveResult res = solve_contact_multipliers(
            contact_bodies_, contact_body_of_slot_, detected_, def_.contact_iterations, tolerance,
            profile_, pool_.get());
        counters_.solver_iterations = res.iterations;
        counters_.solver_residual = res.residual;
        counters_.max_penetration = res.max_penetration;
    }
    // Keep every detected pair, also those at zero force: the next step warm-starts from all
    // of them, so redundant pairs (a node of each body pressing the other's face) keep the
    // same split of the load from step to step instead of trading it back and forth. Only
    // pairs that carry force are reported as contacts.
    contacts_.swap(detected_);
}

// Velocity of node i of the body in `slot` over the last step (before this step's predictor).
double World::step_velocity(uint32_t slot, uint32_t i, int k, double h) const {
    const Body& b = slots_[slot].body;
    if (b.is_deformable()) return scratch_[slot].v_old[3 * i + k];
    if (b.def.type == LFEM_BODY_KINEMATIC || b.is_rigid())
        return (b.state.x[3 * i + k] - scratch_[slot].x_start[3 * i + k]) / h;
    return 0.0;
}

// A body that is big, or that holds more than one thread's share of the tets of all the
// deformable bodies, runs its node and element loops on the pool, one such body after another.
// The others run side by side, one body per task, each on one thread: a 6000-tet body has only
// about 3 element blocks per colour and one node block, too little work per round of the pool
// to be worth handing out, while sixteen of them keep two threads busy. A lone small body also
// runs on the pool (there is nothing to put beside it). Either way every loop has the same
// fixed blocks, so the split changes the speed only, never a bit of the result.
void World::plan_deformable_loops() {
    const uint64_t threads = pool_ ? pool_->size() : 1;
    uint64_t total = 0;
    for (const Slot& s : slots_)
        if (s.body.generation != 0 && s.body.has_mesh() && s.body.is_deformable()) total += s.body.ref.tet_count();
    on_pool_.clear();
    side_by_side_.clear();
    for (uint32_t i = 0; i < slots_.size(); ++i) {
        const Body& b = slots_[i].body;
        if (b.generation == 0 || !b.has_mesh() || !b.is_deformable()) continue;
        const uint64_t tets = b.ref.tet_count();
        (tets >= 32 * 1024 || tets * threads > total ? on_pool_ : side_by_side_).push_back(i);
    }
    if (side_by_side_.size() == 1) {  // nothing to put beside it
        on_pool_.push_back(side_by_side_[0]);
        side_by_side_.clear();
    }
}

template <class Work>
void World::for_each_deformable(const Work& work) {
    for (uint32_t i : on_pool_) work(i, pool_.get());
    parallel_for(pool_.get(), uint32_t(side_by_side_.size()),
                 [&](uint32_t k) { work(side_by_side_[k], nullptr); });
}

void World::substep(double h, double& kinetic, double& strain, double& work) {
    // kinetic, strain: of the new state; work: what gravity, forces, supports and contacts
    // did over the step (added to `work`).
    scratch_.resize(slots_.size());
    // Per body, added up in slot order below (the bodies may run side by side).
    tallies_.assign(slots_.size(), SubstepTally{});
    plan_deformable_loops();
    profile_.substeps += 1;
    uint64_t kinematic = 0;
    PhaseTimer predictor_timer(profile_.predictor, 0);
    uint64_t predicted = 0;
    for (uint32_t i = 0; i < slots_.size(); ++i) {
        Body& b = slots_[i].body;
        if (b.generation == 0 || !b.has_geometry()) continue;
        predicted += b.is_dynamic();
        if (b.is_rigid()) {
            scratch_[i].x_start.assign(b.state.x.begin(), b.state.x.end());
            scratch_[i].support_torque[0] = b.state.center[0];  // the centre at the start
            scratch_[i].support_torque[1] = b.state.center[1];
            scratch_[i].support_torque[2] = b.state.center[2];
            rigid_responses_.resize(slots_.size());
            predict_rigid(b, def_.gravity, h, rigid_responses_[i]);
        }
        kinematic += b.def.type == LFEM_BODY_KINEMATIC;
    }
    for_each_deformable([&](uint32_t i, ThreadPool* pool) {
        predict_positions(slots_[i].body, def_.gravity, h, scratch_[i], pool);
    });
    predictor_timer.set_calls(predicted);
    predictor_timer.stop();
    if (kinematic > 0) {
        PhaseTimer timer(profile_.kinematic_motion, kinematic);
        for (uint32_t i = 0; i < slots_.size(); ++i) {
            Body& b = slots_[i].body;
            if (b.generation == 0 || !b.has_geometry() || b.def.type != LFEM_BODY_KINEMATIC) continue;
            scratch_[i].x_start.assign(b.state.x.begin(), b.state.x.end());
            scratch_[i].shape_pose_start.assign(b.state.shape_pose.begin(), b.state.shape_pose.end());
            advance_kinematic(b, h);
        }
    }
    // Static bodies: nothing to do.
    solve_contacts(h);
    touched_.assign(slots_.size(), 0);
    for (const ContactRecord& r : contacts_)
        if (r.active()) touched_[r.body_a] = touched_[r.body_b] = 1;
    // Commit every moving body; then eq. (2) and the re-fit for "paper" bodies; then the
    // elastic forces at x^{n+1} (they need the re-fitted rotation).
    uint64_t committed = 0, paper = 0;
    PhaseTimer commit_timer(profile_.commit, 0);
    for (uint32_t i = 0; i < slots_.size(); ++i) {
        Body& b = slots_[i].body;
        if (b.generation == 0 || !b.has_mesh()) continue;
        committed += b.is_dynamic();
        paper += b.is_deformable() && b.def.model == LFEM_MODEL_PAPER;
        if (b.is_rigid()) {
            SubstepTally& tally = tallies_[i];
            tally.contact_work += commit_rigid(b, h, rigid_responses_[i]);
            // Work of gravity and node forces on the moving centre (node forces' torques act
            // through eq. 2; their work is booked with the translation only).
            const Vec3 dc = Vec3(b.state.center) - Vec3(scratch_[i].support_torque);
            Vec3 force = b.ref.total_mass * Vec3(def_.gravity);
            for (std::size_t k = 0; k < b.node_force.size(); k += 3) force += Vec3(&b.node_force[k]);
            tally.work += force.dot(dc);
            tally.kinetic += rigid_kinetic_energy(b);
            for (std::size_t k = 0; k < b.state.x.size(); ++k)
                b.state.v_half[k] = (b.state.x[k] - scratch_[i].x_start[k]) / h;
        }
    }
    for_each_deformable([&](uint32_t i, ThreadPool* pool) {
        commit_step(slots_[i].body, def_.gravity, h, scratch_[i], touched_[i] != 0, tallies_[i], pool);
    });
    commit_timer.set_calls(committed);
    commit_timer.stop();
    if (paper > 0) {
        PhaseTimer timer(profile_.global_rotation, paper);
        for_each_deformable([&](uint32_t i, ThreadPool* pool) {
            Body& b = slots_[i].body;
            if (b.def.model == LFEM_MODEL_PAPER) update_global_rotation(b, h, scratch_[i], tallies_[i], pool);
        });
    }
    PhaseTimer elastic_timer(profile_.internal_forces, 0);
    uint64_t deformable = 0;
    for_each_deformable([&](uint32_t i, ThreadPool* pool) {
        Body& b = slots_[i].body;
        compute_elastic_forces(b, b.state, pool);
    });
    SubstepTally tally;
    for (uint32_t i = 0; i < slots_.size(); ++i) {
        const Body& b = slots_[i].body;
        const SubstepTally& t = tallies_[i];
        tally.kinetic += t.kinetic;
        tally.work += t.work;
        tally.contact_work += t.contact_work;
        tally.damping += t.damping;
        tally.drift = std::max(tally.drift, t.drift);
        if (b.generation == 0 || !b.has_mesh() || !b.is_deformable()) continue;
        strain += b.state.strain_energy;
        deformable += 1;
    }
    elastic_timer.set_calls(deformable);
    elastic_timer.stop();
    kinetic = tally.kinetic;
    work += tally.work + tally.contact_work;
    counters_.external_work += tally.work;
    counters_.dissipated_energy += tally.damping - tally.contact_work;
    counters_.rotation_drift = tally.drift;
    counters_.time += h;
    counters_.steps += 1;
    counters_.step_size = h;
}
void World::step(double dt) {
    const double limit = stable_step();
    double h_allowed;
    if (def_.time_step > 0.0) {
        if (def_.time_step > limit && !def_.allow_unstable_step)
            throw Error(LFEM_INVALID_ARGUMENT,
                        "fixed time_step " + seconds(def_.time_step) +
                            " exceeds the stable limit " + seconds(limit) +
                            " of central differences (2/omega_max); use a step below it, 0 "
                            "for automatic, or set allow_unstable_step");
        h_allowed = def_.time_step;
    } else {
        h_allowed = def_.step_safety * limit;
    }
    double count = std::isfinite(h_allowed) ? std::ceil(dt / h_allowed * (1.0 - 1e-12)) : 1.0;
    if (count < 1.0) count = 1.0;
    if (!(count <= double(def_.max_substeps)))  // also a NaN count; count may exceed 2^64
        throw Error(LFEM_INVALID_ARGUMENT,
                    "dt " + seconds(dt) + " needs " + number(count) +
                        " sub-steps of at most " + seconds(h_allowed) + ", more than max_substeps " +
                        std::to_string(def_.max_substeps));
    uint32_t substeps = uint32_t(count);

    // Snapshot for rollback: every body's state and the world's counters. Taking it may throw
    // (out of memory) before anything has changed; restoring it only moves, so cannot.
    // Body by body on the pool (a copy of every node and tet array: with one sub-step a call,
    // as much memory traffic as a fifth of the step).
    std::vector<BodyState> saved(slots_.size());
    parallel_for(pool_.get(), uint32_t(slots_.size()), [&](uint32_t i) { saved[i] = slots_[i].body.state; });
    const WorldCounters saved_counters = counters_;
    const lfem_profile saved_profile = profile_;
    std::vector<ContactRecord> saved_contacts = contacts_;
    auto roll_back = [&] {
        for (std::size_t i = 0; i < slots_.size(); ++i) slots_[i].body.state = std::move(saved[i]);
        counters_ = saved_counters;
        profile_ = saved_profile;
        contacts_ = std::move(saved_contacts);
    };

    // Energy of the moving bodies at the start, for the blow-up test below: per body on the
    // pool, added up in slot order.
    std::vector<double> body_energy(slots_.size(), 0.0);
    parallel_for(pool_.get(), uint32_t(slots_.size()), [&](uint32_t j) {
        const Body& b = slots_[j].body;
        if (b.generation == 0 || !b.is_dynamic() || !b.has_mesh()) return;
        double e = 0.0;
        for (uint32_t i = 0; i < b.ref.node_count(); ++i)
            for (int k = 0; k < 3; ++k) e += 0.5 * b.ref.mass[i] * b.state.v_half[3 * i + k] * b.state.v_half[3 * i + k];
        body_energy[j] = e;
    });
    double start_energy = 0.0, scale = 0.0;
    for (uint32_t j = 0; j < slots_.size(); ++j) {
        const Body& b = slots_[j].body;
        if (b.generation == 0 || !b.is_dynamic() || !b.has_mesh()) continue;
        start_energy += b.state.strain_energy + body_energy[j];
        // m c_d^2 * 1e-12: the energy of a uniform strain of 1e-6, a floor below which energy
        // changes are too small to call a blow-up.
        const double cd = dilatational_wave_speed(b.lame, b.def.density);
        scale += 1e-12 * b.ref.total_mass * cd * cd;
    }

    // Under the automatic step a call is retried from the snapshot, with more sub-steps, when
    // a body stiffened within it beyond its sub-step (the neo-Hookean limit is re-estimated at
    // the current shape after every sub-step) or the state blew up: up to kMaxRetries times,
    // each with at least twice the sub-steps. A fixed time_step is the caller's choice: no
    // retry, and a blow-up fails the call at once.
    constexpr int kMaxRetries = 4;
    const bool automatic = def_.time_step == 0.0;
    for (int attempt = 0;; ++attempt) {
        const double h = dt / substeps;
        double work = 0.0, work_flow = 0.0, limit_seen = limit;
        uint32_t blew_up_at = 0, outran_at = 0;  // 1-based sub-step, 0 = none
        for (uint32_t k = 0; k < substeps && blew_up_at == 0 && outran_at == 0; ++k) {
            double kinetic = 0.0, strain = 0.0, step_work = 0.0, limit_now = limit_seen;
            try {
                substep(h, kinetic, strain, step_work);
                if (automatic) limit_now = stable_step();
            } catch (...) {
                // Whatever failed inside (out of memory in detection, say), the caller gets the
                // world as it was before the call, and the failure's own status.
                roll_back();
                throw;
            }
            work += step_work;
            work_flow += std::fabs(step_work);
            // A stable explicit step cannot create energy: kinetic + strain - work stays near
            // the starting energy (minus damping). Measured with mid-step velocities it still
            // wobbles, by up to a few times the energy that entered the fastest modes (a sudden
            // load near the stable limit), so the test allows ten times the energy present or
            // moved. An unstable step multiplies the energy every step (by about 47 at 1.5x the
            // limit, 6 at 1.1x), so it passes that bound within a few steps of becoming visible.
            const double balance = kinetic + strain - work;
            if (!std::isfinite(balance) || balance > 10.0 * (start_energy + work_flow) + scale)
                blew_up_at = k + 1;
            if (automatic) {
                limit_seen = std::min(limit_seen, limit_now);
                if (h > limit_seen) outran_at = k + 1;
            }
        }
        if (blew_up_at == 0 && outran_at == 0) break;
        const double wanted = std::max(2.0 * substeps, std::ceil(dt / (def_.step_safety * limit_seen)));
        if (!automatic || attempt == kMaxRetries || !(wanted <= double(def_.max_substeps))) {
            roll_back();
            const std::string where = std::to_string(blew_up_at ? blew_up_at : outran_at) + " of " +
                                      std::to_string(substeps) + " (step " + seconds(h) +
                                      ", stable limit " + seconds(limit_seen) + ", after " +
                                      std::to_string(attempt) + " retries with more sub-steps)";
            throw Error(LFEM_UNSTABLE,
                        (blew_up_at ? "the state blew up at sub-step " + where
                                    : "a body stiffened beyond the sub-step at sub-step " + where +
                                          "; the next retry would need " + number(wanted) +
                                          " sub-steps (max_substeps " +
                                          std::to_string(def_.max_substeps) + ")") +
                            "; the world was rolled back to its state before this call");
        }
        try {  // back to the snapshot, keeping it for a later failure (copies may allocate)
            for (std::size_t i = 0; i < slots_.size(); ++i) slots_[i].body.state = saved[i];
            counters_ = saved_counters;
            contacts_ = saved_contacts;
        } catch (...) {
            roll_back();
            throw;
        }
        substeps = uint32_t(wanted);
    }
    counters_.substeps_last_call = substeps;
}

}  // namespace lfem
