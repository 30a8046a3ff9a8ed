#include "contact/face_shape.h"

#include <algorithm>
#include <cmath>

#include "common/closest_point.h"
#include "contact/detection_tolerances.h"

namespace lfem {
namespace {

// The triangle's prism in the shape's local frame: the points whose projection along n lies in
// the triangle, m_e . (x - p_e) >= 0 for its three edges (m_e = n x (p_{e+1} - p_e) points
// inward for a triangle turned counter-clockwise about its outward normal). Widened by the edge
// tolerance of the node test (a barycentric weight down to -0.01, detection_tolerances.h): a
// point on the edge between two faces belongs to both, so that the one holding it keeps it
// while rounding moves it from side to side (else the load went from one face's constraint to
// the other's at every sub-step, each time starting afresh, and a block balanced on a sphere
// crept off it).
struct Prism {
    Vec3 p[3], m[3], n;
    double slack[3];  // on each side: the tolerance times twice the area (m_e has the edge's length)
    Prism(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& normal) : p{p0, p1, p2}, n(normal) {
        const double area2 = n.dot((p[1] - p[0]).cross(p[2] - p[0]));
        for (int e = 0; e < 3; ++e) {
            m[e] = n.cross(p[(e + 1) % 3] - p[e]);
            slack[e] = kEdgeTolerance * std::fabs(area2);
        }
    }
    double side(int e, const Vec3& x) const { return m[e].dot(x - p[e]) + slack[e]; }
    bool contains(const Vec3& x) const {
        for (int e = 0; e < 3; ++e)
            if (side(e, x) < 0.0) return false;
        return true;
    }
    // Clips segment a + u (b - a), u in [lo, hi], to the prism; false when nothing is left.
    bool clip(const Vec3& a, const Vec3& b, double& lo, double& hi) const {
        for (int e = 0; e < 3; ++e) {
            const double f0 = side(e, a), f1 = side(e, b);
            if (f0 < 0.0 && f1 < 0.0) return false;
            if (f0 < 0.0) lo = std::max(lo, f0 / (f0 - f1));
            if (f1 < 0.0) hi = std::min(hi, f0 / (f0 - f1));
        }
        return lo <= hi;
    }
};

// The candidate points of a flat-sided shape under a face (its vertices there, its edges where
// they cross the prism's sides, the prism's edges where they enter it): the lowest (height along
// n), and the one farthest from it among those at most `rise` higher, when at least `sep` away.
// A box's edge under a face gives its two ends there: the face held above both is above the
// whole edge (the gap is linear along it), where the lowest point alone jumped from one end to
// the other as the face tilted, and a cube on two knife edges sank through them.
struct Ends {
    const Vec3& n;
    Vec3 points[64];
    int count = 0;
    explicit Ends(const Vec3& normal) : n(normal) {}
    void add(const Vec3& x) {
        if (count < 64) points[count++] = x;
    }
    int pick(double rise, double sep, Vec3 out[2]) const {
        if (count == 0) return 0;
        int low = 0;
        for (int i = 1; i < count; ++i)
            if (n.dot(points[i]) < n.dot(points[low])) low = i;
        out[0] = points[low];
        double far2 = sep * sep;
        int far = -1;
        for (int i = 0; i < count; ++i) {
            const double d2 = (points[i] - points[low]).squaredNorm();
            if (n.dot(points[i]) <= n.dot(points[low]) + rise && d2 > far2) far2 = d2, far = i;
        }
        if (far < 0) return 1;
        out[1] = points[far];
        return 2;
    }
};

void box_candidates(const double h[3], const Prism& prism, Ends& low) {
    Vec3 v[8];
    for (int i = 0; i < 8; ++i) v[i] = Vec3(i & 1 ? h[0] : -h[0], i & 2 ? h[1] : -h[1], i & 4 ? h[2] : -h[2]);
    for (const Vec3& x : v)
        if (prism.contains(x)) low.add(x);
    // The box's edges where they cross the prism's sides.
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue;
            const Vec3 &a = v[i], &b = v[i | bit];
            for (int e = 0; e < 3; ++e) {
                const double f0 = prism.side(e, a), f1 = prism.side(e, b);
                if ((f0 < 0.0) == (f1 < 0.0)) continue;
                const Vec3 x = a + (f0 / (f0 - f1)) * (b - a);
                if (prism.contains(x)) low.add(x);
            }
        }
    // The prism's edges (the lines through the triangle's corners along n) where they enter
    // the box: the lowest point of the box on each line.
    for (int k = 0; k < 3; ++k) {
        double lo = -HUGE_VAL, hi = HUGE_VAL;
        bool meets = true;
        for (int d = 0; d < 3 && meets; ++d) {
            if (std::fabs(prism.n[d]) < 1e-300) {
                meets = std::fabs(prism.p[k][d]) <= h[d];
                continue;
            }
            double s0 = (-h[d] - prism.p[k][d]) / prism.n[d], s1 = (h[d] - prism.p[k][d]) / prism.n[d];
            if (s0 > s1) std::swap(s0, s1);
            lo = std::max(lo, s0), hi = std::min(hi, s1);
        }
        if (meets && lo <= hi) low.add(prism.p[k] + lo * prism.n);
    }
}

// A ball of radius r about c, as seen from the prism: its lowest point over the triangle, or
// where the prism's side nearest to c cuts it.
bool ball_point(const Vec3& c, double r, const Prism& prism, Vec3& point) {
    const Vec3 in_plane = c - prism.n * prism.n.dot(c - prism.p[0]);
    if (prism.contains(in_plane)) {
        point = c - r * prism.n;
        return true;
    }
    double w[3];
    const Vec3 q = closest_on_triangle(in_plane, prism.p[0], prism.p[1], prism.p[2], w);
    const double off2 = (in_plane - q).squaredNorm();
    if (off2 >= r * r) return false;
    point = q + (prism.n.dot(c - q) - std::sqrt(r * r - off2)) * prism.n;
    return true;
}

// A flat-sided shape whose nearest points to the three nodes p lie on one of its faces (the same
// normal): that face spans the whole triangle under it (it is convex), and the nodes hold the
// triangle above it, as on a floor. Decided before the search under the face.
bool on_one_flat_face(const RigidShape& shape, const ShapePose& pose, const Vec3 p[3], double reach) {
    if (shape.type != ShapeType::box && shape.type != ShapeType::convex_hull) return false;
    Vec3 normals[3];
    for (int v = 0; v < 3; ++v) {
        double d = 0.0;
        if (!shape_signed_distance(shape, pose, p[v], reach, d, normals[v])) return false;
    }
    return normals[0].dot(normals[1]) > 1.0 - 1e-12 && normals[0].dot(normals[2]) > 1.0 - 1e-12;
}

}  // namespace

Aabb shape_box(const RigidShape& shape, const ShapePose& pose) {
    Aabb box = empty_box();
    const Mat3 r = pose.rotation.toRotationMatrix();
    const auto add = [&](const Vec3& local, double grow) {
        const Vec3 x = pose.center + r * local;
        for (int d = 0; d < 3; ++d) box.lo[d] = std::min(box.lo[d], x[d] - grow), box.hi[d] = std::max(box.hi[d], x[d] + grow);
    };
    switch (shape.type) {
        case ShapeType::sphere: add(Vec3::Zero(), shape.radius); break;
        case ShapeType::capsule:
            add(Vec3(0.0, 0.0, -shape.half_length), shape.radius);
            add(Vec3(0.0, 0.0, shape.half_length), shape.radius);
            break;
        case ShapeType::box: {
            const Vec3 h(shape.half_extents[0], shape.half_extents[1], shape.half_extents[2]);
            const Vec3 extent = r.cwiseAbs() * h;
            for (int d = 0; d < 3; ++d) box.lo[d] = pose.center[d] - extent[d], box.hi[d] = pose.center[d] + extent[d];
            break;
        }
        case ShapeType::convex_hull:
            for (std::size_t i = 0; i + 2 < shape.points.size(); i += 3)
                add(Vec3(shape.points[i], shape.points[i + 1], shape.points[i + 2]), 0.0);
            break;
        default: break;  // a plane
    }
    return box;
}

void box_edge_boxes(const RigidShape& shape, const ShapePose& pose, std::vector<Aabb>& out) {
    const double* h = shape.half_extents;
    const auto corner = [&](int i) {
        return Vec3(pose.center + pose.rotation * Vec3(i & 1 ? h[0] : -h[0], i & 2 ? h[1] : -h[1], i & 4 ? h[2] : -h[2]));
    };
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue;
            const Vec3 a = corner(i), b = corner(i | bit);
            Aabb e;
            for (int d = 0; d < 3; ++d) e.lo[d] = std::min(a[d], b[d]), e.hi[d] = std::max(a[d], b[d]);
            out.push_back(e);
        }
}

// Two ends under a face closer than a third of its size (sqrt of twice its area) are one point.
constexpr double kEndSeparation = 1.0 / 3.0;

int points_under(const RigidShape& shape, const ShapePose& pose, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                 const Vec3& n, double rise, double sep, Vec3 points[2], Vec3 cores[2]) {
    const Quat inverse = pose.rotation.conjugate();
    const auto local = [&](const Vec3& x) { return Vec3(inverse * (x - pose.center)); };
    const Prism prism(local(p0), local(p1), local(p2), inverse * n);
    int count = 0;
    switch (shape.type) {
        case ShapeType::sphere:
            if (!ball_point(Vec3::Zero(), shape.radius, prism, points[0])) return 0;
            cores[0] = Vec3::Zero();
            count = 1;
            break;
        case ShapeType::capsule: {
            // The axis where it runs under the face: both ends of that part (one if it is short).
            const Vec3 a(0.0, 0.0, -shape.half_length), b(0.0, 0.0, shape.half_length);
            double lo = 0.0, hi = 1.0;
            if (!prism.clip(a, b, lo, hi)) return 0;
            cores[0] = a + lo * (b - a), cores[1] = a + hi * (b - a);  // in the axis' order
            count = (cores[1] - cores[0]).norm() > sep ? 2 : 1;
            if (count == 1) cores[0] = 0.5 * (cores[0] + cores[1]);
            for (int e = 0; e < count; ++e) points[e] = cores[e] - shape.radius * prism.n;
            break;
        }
        case ShapeType::box:
        case ShapeType::convex_hull: {
            Ends ends(prism.n);
            if (shape.type == ShapeType::box) {
                box_candidates(shape.half_extents, prism, ends);
            } else {
                for (std::size_t i = 0; i + 2 < shape.points.size(); i += 3) {
                    const Vec3 x(shape.points[i], shape.points[i + 1], shape.points[i + 2]);
                    if (prism.contains(x)) ends.add(x);
                }
            }
            count = ends.pick(rise, sep, points);
            // The ends in a fixed order (along the face's first edge), so that each keeps its
            // record from step to step whichever is the lower.
            if (count == 2 && (points[1] - points[0]).dot(prism.p[1] - prism.p[0]) < 0.0) std::swap(points[0], points[1]);
            for (int e = 0; e < count; ++e) cores[e] = points[e];
            break;
        }
        default:
            return 0;  // a plane
    }
    for (int e = 0; e < count; ++e) {
        points[e] = pose.center + pose.rotation * points[e];
        cores[e] = pose.center + pose.rotation * cores[e];
    }
    return count;
}

bool test_face_shape(const ContactBody& a, uint32_t t, const ContactBody& o, uint32_t k, double band, int end,
                     const double* held, FaceShapeHit& hit) {
    hit.ends = 0;
    const uint32_t* tri = &a.triangles[3 * std::size_t(t)];
    const Vec3 p[3] = {Vec3(a.x + 3 * std::size_t(tri[0])), Vec3(a.x + 3 * std::size_t(tri[1])),
                       Vec3(a.x + 3 * std::size_t(tri[2]))};
    Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]);
    const double area2 = n.norm();
    if (!(area2 > 0.0)) return false;  // a collapsed face: no plane
    n /= area2;
    const RigidShape& shape = o.shapes[k];
    const ShapePose pose = ShapePose::load(o.shape_pose + 7 * std::size_t(k));
    // Far in front of the face, or wholly behind its plane: nothing to find under it.
    const double centre_height = n.dot(pose.center - p[0]), reach = shape_bounding_radius(shape);
    if (centre_height > reach + band || centre_height < -reach) return false;
    if (on_one_flat_face(shape, pose, p, band + reach)) return false;
    Vec3 points[2], cores[2];
    const double sep = kEndSeparation * std::sqrt(area2);
    hit.ends = points_under(shape, pose, p[0], p[1], p[2], n, band, sep, points, cores);
    if (hit.ends <= end) return false;
    Vec3 point = points[end], core = cores[end];
    double w[3];
    // A sphere or a capsule: the constraint joins the face's point nearest to the core (the
    // centre, the axis point) and the shape's surface point on that line, along it: the
    // shape's own normal there, as for a node against it; the point moves smoothly over the
    // face as a body rolls on the shape. (Along the face's normal, from the deepest point, a
    // block balanced on a sphere's crown rang at 8e-3 m/s.) A flat-sided shape (box, hull),
    // or a core on or behind the face's plane: along the face's normal, from the deepest point.
    Vec3 normal = -n;
    const double radius = shape.type == ShapeType::sphere || shape.type == ShapeType::capsule ? shape.radius : 0.0;
    if (held) {
        // The face's point where the pair stuck at the last step (its weights), against the
        // shape as a node is: its nearest point of the core.
        for (int v = 0; v < 3; ++v) w[v] = held[v];
        const Vec3 x = w[0] * p[0] + w[1] * p[1] + w[2] * p[2];
        if (shape.type == ShapeType::capsule) {
            const Vec3 axis = pose.rotation * Vec3(0.0, 0.0, shape.half_length);
            double u[2];
            core = closest_on_segment(x, pose.center - axis, pose.center + axis, u);
        }
        const Vec3 d = x - core;
        const double distance = d.norm();
        if (radius > 0.0 && n.dot(core - x) > 1e-6 * distance && distance > 0.0) {
            normal = d / distance;
            point = core + radius * normal;
            hit.gap = distance - radius;
        } else {
            hit.gap = n.dot(point - x);
        }
    } else if (radius > 0.0) {
        const Vec3 q = closest_on_triangle(core, p[0], p[1], p[2], w);
        const Vec3 d = q - core;
        const double distance = d.norm();
        if (n.dot(core - q) > 1e-6 * distance && distance > 0.0) {
            normal = d / distance;
            point = core + radius * normal;
            hit.gap = distance - radius;
        } else {
            hit.gap = n.dot(point - p[0]);
            closest_on_triangle(point - n * hit.gap, p[0], p[1], p[2], w);
        }
    } else {
        hit.gap = n.dot(point - p[0]);
        // The point's weights: its projection onto the face, inside it but for rounding.
        closest_on_triangle(point - n * hit.gap, p[0], p[1], p[2], w);
    }
    if (!(hit.gap < band)) return false;
    // How far the face's own nodes see the shape at that point (their signed distances,
    // weighted): where that is no deeper than the point itself, the nodes hold the face.
    double seen = 0.0;
    for (int v = 0; v < 3; ++v) {
        double d = 0.0;
        Vec3 normal;
        if (!shape_signed_distance(shape, pose, p[v], band + reach, d, normal)) d = band + reach;
        seen += w[v] * d;
    }
    hit.unseen = seen - hit.gap;
    // The same material point of the shape at the start of the step, and the face there.
    const ShapePose start = ShapePose::load(o.shape_pose_start + 7 * std::size_t(k));
    hit.point_end = point;
    hit.point_start = start.center + start.rotation * (pose.rotation.conjugate() * (point - pose.center));
    Vec3 face_start = Vec3::Zero();
    for (int v = 0; v < 3; ++v) face_start += w[v] * Vec3(a.x_start + 3 * std::size_t(tri[v]));
    hit.start_gap = normal.dot(face_start - hit.point_start);
    if (radius > 0.0 && normal != -n) {
        // Along the shape's own normal: the face's point's distance from the shape where both
        // were at the start of the step (the point may have slid round a thin rod by a good part
        // of its radius since; measured along the end's normal, it was found millimetres deep).
        Vec3 core_start = start.center;
        if (shape.type == ShapeType::capsule) {
            const Vec3 axis = start.rotation * Vec3(0.0, 0.0, shape.half_length);
            double u[2];
            core_start = closest_on_segment(face_start, start.center - axis, start.center + axis, u);
        }
        hit.start_gap = (face_start - core_start).norm() - radius;
    }
    for (int v = 0; v < 3; ++v) hit.weights[v] = w[v];
    hit.normal = normal;
    return true;
}

}  // namespace lfem
