// The points a constraint of the multiplier solve moves: a free node, moved directly by
// Mhat^-1 G^T lambda, or a point of a rigid body, moved through the body's centre and rotation
// corrections. Shared by contact pairs (solve_contact_multipliers.cpp) and attachment links
// (link_constraint.cpp).
#pragma once

#include <algorithm>
#include <cstdint>

#include "common/math.h"
#include "contact/contact_body.h"

namespace lfem {

// The inverse effective mass along unit direction n of a rigid body's point at `arm` from its
// predicted centre.
inline double rigid_response(const RigidResponse& rigid, const Vec3& arm, const Vec3& n) {
    const Vec3 rn = arm.cross(n);
    return rigid.inv_mass + rn.dot(rigid.inv_inertia * rn);
}

// One of the four points of a constraint (the node, or a triangle node): a free node that the
// solve moves directly, or a point of a rigid body, moved through the body's centre and
// rotation corrections (its position is evaluated from them when asked). Four words: the
// solve's sweeps stream over tens of thousands of these, and a rigid point's predicted place
// and arm are read from its body's positions (never written during the solve) rather than kept.
struct PointRef {
    double* x = nullptr;         // free node: its position (x*, corrected in place); rigid
                                 // point: its predicted position (read only)
    const double* x0 = nullptr;  // position at the start of the step
    double w = 0;                // free node: 1/mhat
    RigidResponse* rigid = nullptr;

    // The free node's path is written inline: the solve's sweeps call these a few times per
    // pair and pass, and a call per point cost more than the arithmetic.
    Vec3 position() const {
        if (__builtin_expect(rigid != nullptr, 0)) return rigid_position();
        return Vec3(x[0], x[1], x[2]);
    }
    // Inverse effective mass along unit direction n.
    double response(const Vec3& n) const { return rigid ? rigid_response(*rigid, arm(), n) : w; }
    // A rigid point: predicted position minus predicted centre.
    Vec3 arm() const { return Vec3(x[0], x[1], x[2]) - rigid->center; }
    // Apply the force increment d (N) to this point; returns how far it moved.
    double push(const Vec3& d) {
        if (__builtin_expect(rigid != nullptr, 0)) return push_rigid(d);
        // An immovable point (static, kinematic or fixed) is not written at all: the contact
        // groups solved side by side may share it (a static floor's nodes).
        if (w == 0.0) return 0.0;
        for (int k = 0; k < 3; ++k) x[k] += w * d[k];
        return w * d.cwiseAbs().maxCoeff();
    }

private:
    Vec3 rigid_position() const { return Vec3(x[0], x[1], x[2]) + rigid->dc + rigid->dtheta.cross(arm()); }
    __attribute__((noinline)) double push_rigid(const Vec3& d) {
        const Vec3 before = rigid_position();
        rigid->dc += rigid->inv_mass * d;
        rigid->dtheta += rigid->inv_inertia * arm().cross(d);
        return (rigid_position() - before).cwiseAbs().maxCoeff();
    }
};

// A node of body b as a constraint point.
inline PointRef point_of(const ContactBody& b, uint32_t i) {
    PointRef p;
    p.x = b.x + 3 * std::size_t(i);
    p.x0 = b.x_start + 3 * std::size_t(i);
    if (b.rigid) {
        p.rigid = b.rigid;
    } else {
        p.w = b.inv_mass ? b.inv_mass[i] : 0.0;
    }
    return p;
}

}  // namespace lfem
