// The small dense algebra every folder shares (Eigen, fixed size): 3-vectors, 3x3 matrices, and
// unit quaternions kept in the library's flat arrays as (w, x, y, z).
#pragma once

#include <cstddef>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace lfem {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

// A quaternion stored as 4 doubles (w, x, y, z), and back.
// The unit normal of triangle tri (3 node indices into x, 3 doubles per node), (b - a) x (c - a)
// normalised; zero for a collapsed one.
inline Vec3 unit_triangle_normal(const double* x, const uint32_t* tri) {
    const Vec3 a(x + 3 * std::size_t(tri[0]));
    const Vec3 n = (Vec3(x + 3 * std::size_t(tri[1])) - a).cross(Vec3(x + 3 * std::size_t(tri[2])) - a);
    const double norm = n.norm();
    return norm > 0.0 ? Vec3(n / norm) : Vec3(Vec3::Zero());
}

inline Quat load_quaternion(const double* q) { return Quat(q[0], q[1], q[2], q[3]); }
inline void store_quaternion(const Quat& q, double* out) {
    out[0] = q.w(), out[1] = q.x(), out[2] = q.y(), out[3] = q.z();
}

// A 3x3 matrix stored row-major as 9 doubles.
inline Mat3 load_row_major(const double* m) {
    return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(m);
}

}  // namespace lfem
