// Checkpoint file: a fixed header, then the payload, protected by a checksum.
//
//   "LFEMCKPT"  u32 format version  u32 byte-order mark  u32 x4 layout sizes
//   u64 payload size  u64 FNV-1a checksum of the payload  payload
//
// The payload lists every field a step reads, in one order that serves both directions: the
// `fields` functions below are called with a Writer to save and with a Reader to load, so the
// two can never disagree. A loaded image is then checked for consistency (sizes, indices,
// enums), since a well-formed checksum does not make a file trustworthy.
#include "world/checkpoint.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <system_error>
#include <type_traits>

#include "common/error.h"
#include "contact/hull_edges.h"

namespace lfem {
namespace {

constexpr char kMagic[8] = {'L', 'F', 'E', 'M', 'C', 'K', 'P', 'T'};
constexpr uint32_t kFormatVersion = 15; // 2: thread_count in the def, float tet rotations,
                                        // stiffening; 3: the node and tet numbering; 4: mass
                                        // scaling (the world def's step, a body's added mass);
                                        // 5: inverted tets and the warnings; 6: attachments,
                                        // sleeping, the touching pairs; 7: 10-node tets (nodes
                                        // per tet, quadrature volumes, 6-node faces); 8: skins;
                                        // 9: contacts' plane gap and gentle flag; 10: the
                                        // definitions field by field, no Lame parameters
                                        // (derived from the body's def); 11: a body's
                                        // report_contacts; 12: forces for the next
                                        // call, a body's user id; 13: the contacts'
                                        // kinds (edges, faces against shapes); 14: a
                                        // body's edge_contacts; 15: edges against a
                                        // convex hull's edges
constexpr uint32_t kByteOrderMark = 0x01020304u;
constexpr std::size_t kHeaderSize = 8 + 4 + 4 + 4 * 4 + 8 + 8;

// A new field in these structs must be added to the `fields` functions below (and the format
// version raised): their sizes are pinned here (64-bit Linux) so that it cannot be forgotten.
#if defined(__x86_64__) || defined(__aarch64__)
static_assert(sizeof(BodyReference) == 792,  // colouring, node-triangle lists, sharp edges, folds, triangle edges, triangle elements, tree: derived
              "BodyReference changed: update the checkpoint");
static_assert(sizeof(BodyState) == 312, "BodyState changed: update the checkpoint");
static_assert(sizeof(Attachment) == 360, "Attachment changed: update the checkpoint");
static_assert(sizeof(WorldCounters) == 192, "WorldCounters changed: update the checkpoint");
static_assert(sizeof(ContactRecord) == 224, "ContactRecord changed: update the checkpoint");
static_assert(sizeof(RigidShape) == 120, "RigidShape changed: update the checkpoint");  // hull edges: derived
static_assert(sizeof(Skin) == 80, "Skin changed: update the checkpoint");
#endif

uint64_t fnv1a(const char* data, std::size_t n) {
    uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= uint8_t(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw Error(Status::io_error, "checkpoint " + path + ": " + what);
}

class Writer {
public:
    static constexpr bool loading = false;
    template <class T>
    void operator()(const T& v) {
        static_assert(std::is_trivially_copyable<T>::value, "plain data only");
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    template <class T>
    void operator()(const std::vector<T>& v) {
        operator()(uint64_t(v.size()));
        bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
};

class Reader {
public:
    static constexpr bool loading = true;
    Reader(const std::string& path, const char* data, std::size_t size)
        : path_(path), data_(data), size_(size) {}
    template <class T>
    void operator()(T& v) {
        static_assert(std::is_trivially_copyable<T>::value, "plain data only");
        take(&v, sizeof v);
    }
    // A flag is one byte that must be 0 or 1: any other value would be a bool no code may
    // read (undefined behaviour), so an altered file is refused instead.
    void operator()(bool& v) {
        unsigned char byte = 0;
        static_assert(sizeof(bool) == 1, "a flag is one byte in the file");
        take(&byte, 1);
        if (byte > 1) fail(path_, "bad flag (neither 0 nor 1)");
        v = byte == 1;
    }
    template <class T>
    void operator()(std::vector<T>& v) {
        uint64_t n = 0;
        operator()(n);
        // Checked against what is left before allocating: a corrupted count cannot ask for
        // terabytes.
        if (n > (size_ - pos_) / sizeof(T)) fail(path_, "truncated (an array runs past the end)");
        v.resize(std::size_t(n));
        take(v.data(), std::size_t(n) * sizeof(T));
    }
    bool at_end() const { return pos_ == size_; }

private:
    void take(void* out, std::size_t n) {
        if (n > size_ - pos_) fail(path_, "truncated");
        if (n) std::memcpy(out, data_ + pos_, n);
        pos_ += n;
    }
    const std::string& path_;
    const char* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

// Field lists, one per struct, used for both saving (Writer, const_cast-free through the
// template) and loading (Reader).
template <class A, class C>
void counter_fields(A& a, C& c) {
    a(c.time), a(c.steps), a(c.step_size), a(c.substeps_last_call), a(c.external_work);
    a(c.dissipated_energy), a(c.initial_energy), a(c.rotation_drift), a(c.solver_iterations);
    a(c.solver_residual), a(c.max_penetration), a(c.scan_overlaps);
    for (auto* w : {&c.warnings.inverted_tets, &c.warnings.stays_inverted, &c.warnings.fallen_in, &c.warnings.unconverged})
        a(w->count), a(w->last_time), a(w->last_slot), a(w->last_generation);
}

template <class A, class T>
void attachment_fields(A& a, T& t) {
    a(t.generation);
    if (t.generation == 0) return;  // a free slot
    a(t.body), a(t.body_generation), a(t.target), a(t.target_generation), a(t.nodes_per_point), a(t.nodes);
    a(t.weights), a(t.target_nodes_per_point), a(t.target_nodes), a(t.target_weights), a(t.offsets), a(t.lambda);
    a(t.target_end), a(t.stiffness), a(t.damping), a(t.frame_start), a(t.frame_end), a(t.break_force), a(t.force);
}

template <class A, class C>
void contact_fields(A& a, C& c) {
    a(c.body_a), a(c.node), a(c.body_b), a(c.triangle), a(c.shape), a(c.point_start);
    a(c.point_end), a(c.t1), a(c.t2), a(c.normal), a(c.lambda_n), a(c.lambda_t), a(c.offset);
    a(c.gap_after), a(c.plane_gap), a(c.sliding), a(c.gentle), a(c.kind), a(c.end), a(c.nodes_a), a(c.weights_a);
}

template <class A, class S>
void shape_fields(A& a, S& s) {
    a(s.type), a(s.half_extents), a(s.radius), a(s.half_length), a(s.points);
}

template <class A, class D>
void world_def_fields(A& a, D& d) {
    a(d.gravity), a(d.time_step), a(d.step_safety), a(d.contact_iterations), a(d.thread_count);
    a(d.contact_tolerance), a(d.max_substeps), a(d.allow_unstable_step), a(d.enable_sleep);
    a(d.mass_scaling_step), a(d.sleep_velocity), a(d.sleep_time);
}

// user_data is a pointer into the saving process: never written, NULL after loading (user_id,
// the caller's opaque number, is kept).
template <class A, class D>
void body_def_fields(A& a, D& d) {
    a(d.type), a(d.model), a(d.young_modulus), a(d.poisson_ratio), a(d.density), a(d.damping);
    a(d.friction), a(d.linear_velocity), a(d.angular_velocity), a(d.category_bits), a(d.mask_bits);
    a(d.enable_sleep), a(d.self_contact), a(d.composite_tets), a(d.report_contacts), a(d.user_id),
        a(d.edge_contacts);
}

template <class A, class B>
void body_fields(A& a, B& b) {
    a(b.generation);
    if (b.generation == 0) return;  // a free slot
    body_def_fields(a, b.def);
    auto& r = b.ref;
    a(r.nodes_per_tet), a(r.X), a(r.mass), a(r.tets), a(r.Dm_inv), a(r.volume), a(r.qp_volume);
    a(r.surface.triangles), a(r.surface.quadratic_faces), a(r.surface.nodes);
    a(r.surface.feature_nodes), a(r.surface.edge_length), a(r.total_mass), a(r.added_mass), a(r.com), a(r.stable_step);
    a(r.inertia);
    a(r.numbering.node_of_api), a(r.numbering.api_of_node), a(r.numbering.api_of_tet);
    auto& s = b.state;
    a(s.x), a(s.v_half), a(s.elastic), a(s.tet_rotation), a(s.contact_force), a(s.h_last);
    a(s.strain_energy), a(s.inverted_tets), a(s.min_jacobian), a(s.inverted_since), a(s.stiffening), a(s.sleep_timer);
    a(s.asleep), a(s.global.rotation), a(s.global.angular_momentum), a(s.global.center);
    a(s.global.velocity);
    a(s.shape_pose);
    a(b.node_mode), a(b.prescribed_velocity), a(b.node_force), a(b.call_force);
    uint64_t shapes = b.shapes.size();
    a(shapes);
    if constexpr (A::loading) {
        if (shapes > (1u << 20)) throw Error(Status::io_error, "checkpoint: implausible shape count");
        b.shapes.resize(std::size_t(shapes));
    }
    for (auto& shape : b.shapes) shape_fields(a, shape);
    if constexpr (A::loading)
        for (auto& shape : b.shapes) compute_hull_edges(shape);  // derived, like the surface's lists
    uint64_t skins = b.skins.size();
    a(skins);
    if constexpr (A::loading) {
        if (skins > (1u << 20)) throw Error(Status::io_error, "checkpoint: implausible skin count");
        b.skins.resize(std::size_t(skins));
    }
    for (auto& skin : b.skins) a(skin.nodes_per_vertex), a(skin.nodes), a(skin.weights), a(skin.triangles);
}

// An enum of the file within its values (from `first` to `last`): each is an int32_t, which a
// corrupted file may set to anything.
template <class E>
bool in_range(E e, E first, E last) {
    return int32_t(e) >= int32_t(first) && int32_t(e) <= int32_t(last);
}

// A requirement on one body of the file: fails naming the file and the body's slot.
struct BodyCheck {
    const std::string& path;
    std::string where;
    void operator()(bool ok, const char* what) const {
        if (!ok) fail(path, where + what);
    }
};

// A body's skins against its n nodes and t tets.
void check_skins(const Body& b, std::size_t n, std::size_t t, const BodyCheck& require) {
    for (const Skin& sk : b.skins) {
        const std::size_t per = sk.nodes_per_vertex;  // the tets' nodes: checked before dividing by it
        require(per == b.ref.nodes_per_tet, "a skin of another kind of tet than its body's");
        require(sk.weights.size() % per == 0 && sk.nodes.size() == sk.weights.size() && sk.triangles.size() % 3 == 0 &&
                    sk.weights.size() / per <= UINT32_MAX && sk.triangles.size() / 3 <= UINT32_MAX,
                "bad skin");
        for (uint32_t i : sk.nodes) require(i < n, "skin node out of range");
        for (uint32_t v : sk.triangles) require(v < sk.weights.size() / per, "skin vertex index out of range");
        for (double w : sk.weights) require(std::isfinite(w), "a non-finite number");
    }
    require(b.skins.empty() || t > 0, "skins on a body without tets");
}

// Consistency of what a Reader produced: every size and index a step relies on.
void check_body(const Body& b, const std::string& path, std::size_t slot) {
    const BodyCheck require{path, "body in slot " + std::to_string(slot) + ": "};
    const BodyReference& r = b.ref;
    const BodyState& s = b.state;
    require(in_range(b.def.type, BodyKind::deformable, BodyKind::rigid), "bad body type");
    require(in_range(b.def.model, Model::paper, Model::linear), "bad model");
    require(!b.def.self_contact || b.is_deformable(), "bad self-contact flag");
    require(r.X.size() % 3 == 0, "bad reference positions");
    require(r.nodes_per_tet == 4 || r.nodes_per_tet == 10, "bad nodes per tet");
    const bool quadratic = r.nodes_per_tet == 10;
    const std::size_t n = r.X.size() / 3, t = r.tets.size() / r.nodes_per_tet, points = quadratic ? 4 : 1;
    require(r.tets.size() % r.nodes_per_tet == 0 && r.mass.size() == n && r.Dm_inv.size() == 9 * points * t &&
                r.volume.size() == t && r.qp_volume.size() == (quadratic ? points * t : 0) &&
                r.surface.triangles.size() % 3 == 0 && r.surface.quadratic_faces.size() % 6 == 0 &&
                (!quadratic || r.surface.triangles.size() == 2 * r.surface.quadratic_faces.size()),
            "array sizes disagree");
    for (uint32_t i : r.tets) require(i < n, "tet node index out of range");
    for (uint32_t i : r.surface.triangles) require(i < n, "boundary node index out of range");
    for (uint32_t i : r.surface.quadratic_faces) require(i < n, "boundary node index out of range");
    for (uint32_t i : r.surface.nodes) require(i < n, "boundary node out of range");
    for (uint32_t i : r.surface.feature_nodes) require(i < n, "feature node out of range");
    require(n <= UINT32_MAX && t <= UINT32_MAX &&
                r.numbering.consistent(uint32_t(n), uint32_t(t)),
            "bad node or tet numbering");
    require(s.x.size() == 3 * n && s.v_half.size() == 3 * n && s.elastic.size() == 3 * n,
            "state size disagrees with the mesh");
    const bool corotational = b.is_deformable() && b.def.model == Model::corotational;
    require(s.tet_rotation.size() == (corotational ? 4 * points * t : 0), "tet rotations disagree with the mesh");
    for (float v : s.tet_rotation) require(std::isfinite(v), "a non-finite number");
    require(s.contact_force.empty() || s.contact_force.size() == 3 * n, "bad contact forces");
    require(b.node_mode.size() == n, "bad node modes");
    for (NodeMode m : b.node_mode) require(uint8_t(m) <= uint8_t(NodeMode::prescribed), "bad node mode");
    require(b.prescribed_velocity.empty() || b.prescribed_velocity.size() == 3 * n,
            "bad prescribed velocities");
    require(b.node_force.empty() || b.node_force.size() == 3 * n, "bad node forces");
    require(b.call_force.empty() || (b.call_force.size() == 3 * n && b.is_dynamic()), "bad forces for the next call");
    require(s.shape_pose.size() == 7 * b.shapes.size(), "shape poses disagree with the shapes");
    for (const RigidShape& sh : b.shapes)
        require(in_range(sh.type, ShapeType::plane, ShapeType::convex_hull) &&
                    sh.points.size() % 3 == 0,
                "bad shape");
    check_skins(b, n, t, require);
    bool prescribed = false;
    for (NodeMode m : b.node_mode) prescribed = prescribed || m == NodeMode::prescribed;
    require(!prescribed || b.prescribed_velocity.size() == 3 * n, "prescribed nodes without velocities");
    require(b.shapes.empty() || b.def.type == BodyKind::static_body || b.def.type == BodyKind::kinematic,
            "shapes on a body that cannot have them");
    require(!b.is_deformable() || n == 0 || (std::isfinite(r.stable_step) && r.stable_step > 0.0),
            "bad stable step");
    require(s.stiffening >= 1.0 && s.stiffening < HUGE_VAL, "bad stiffening");  // also NaN
    require(r.added_mass >= 0.0 && r.added_mass < HUGE_VAL, "bad added mass");
    for (const std::vector<double>* a : {&r.X, &r.mass, &r.Dm_inv, &r.volume, &r.qp_volume, &s.x, &s.v_half,
                                         &s.elastic, &s.contact_force,
                                         &s.shape_pose, &b.prescribed_velocity, &b.node_force, &b.call_force})
        for (double v : *a) require(std::isfinite(v), "a non-finite number");
}

// Whether a contact's nodes, shape and feature name parts of bodies a and b.
bool contact_in_range(const ContactRecord& c, const Body& a, const Body& b) {
    const bool feature = c.kind == ContactKind::face_shape || c.kind == ContactKind::edge_edge;
    bool in_range = feature ? c.node == kFeatureNode : c.kind == ContactKind::node_face && c.node < a.ref.node_count();
    if (feature)
        for (uint32_t v : c.nodes_a) in_range = in_range && v < a.ref.node_count();
    if (c.shape == UINT32_MAX)
        for (uint32_t v : c.triangle) in_range = in_range && v < b.ref.node_count();
    else
        in_range = in_range && c.shape < b.shapes.size();
    // A face's point under a shape is one of two (end); an edge against a box's edge names
    // the box's edge (end, one of twelve), against a hull's edge its points (triangle[0..1],
    // an edge of the hull).
    const bool shape_edge = c.kind == ContactKind::edge_edge && c.shape != UINT32_MAX;
    const RigidShape* sh = shape_edge && in_range ? &b.shapes[c.shape] : nullptr;
    in_range = in_range && (c.kind != ContactKind::face_shape || c.shape != UINT32_MAX) && c.end < (shape_edge ? 12 : 2);
    bool hull_edge = false;
    for (std::size_t e = 0; sh && e + 1 < sh->hull_edges.size() && !hull_edge; e += 2)
        hull_edge = sh->hull_edges[e] == c.triangle[0] && sh->hull_edges[e + 1] == c.triangle[1] && c.end == 0;
    return in_range && (!sh || sh->type == ShapeType::box || hull_edge);
}

void check_image(const WorldImage& im, const std::string& path) {
    for (std::size_t i = 0; i < im.bodies.size(); ++i)
        if (im.bodies[i].generation != 0) check_body(im.bodies[i], path, i);
    for (uint32_t f : im.free_slots)
        if (f >= im.bodies.size() || im.bodies[f].generation != 0) fail(path, "bad free slot list");
    for (const ContactRecord& c : im.state.contacts) {
        const bool ok = c.body_a < im.bodies.size() && c.body_b < im.bodies.size() &&
                        im.bodies[c.body_a].generation != 0 && im.bodies[c.body_b].generation != 0;
        if (!ok) fail(path, "a contact names a missing body");
        if (!contact_in_range(c, im.bodies[c.body_a], im.bodies[c.body_b])) fail(path, "a contact index is out of range");
    }
    auto live = [&](uint32_t slot, uint32_t generation) {
        return slot < im.bodies.size() && im.bodies[slot].generation != 0 && im.bodies[slot].generation == generation;
    };
    const Attachments& all = im.state.attachments;
    for (const Attachment& t : all.slots) {
        if (t.generation == 0) continue;
        if (!live(t.body, t.body_generation) || !im.bodies[t.body].is_deformable())
            fail(path, "an attachment names a missing body");
        if (t.target != kFrameTarget && !live(t.target, t.target_generation))
            fail(path, "an attachment names a missing target");
        const bool deformable_target = t.target != kFrameTarget && im.bodies[t.target].is_deformable();
        const std::size_t points = t.lambda.size() / 3;
        bool ok = points > 0 && t.lambda.size() == 3 * points && t.target_end.size() == 3 * points &&
                  (t.nodes_per_point == 1 || t.nodes_per_point == 4 || t.nodes_per_point == 10) &&
                  t.nodes.size() == t.nodes_per_point * points && t.weights.size() == t.nodes.size() &&
                  (deformable_target ? (t.target_nodes_per_point == 4 || t.target_nodes_per_point == 10) &&
                                           t.target_nodes.size() == t.target_nodes_per_point * points &&
                                           t.target_weights.size() == t.target_nodes.size() && t.offsets.empty()
                                     : t.target_nodes_per_point == 0 && t.target_nodes.empty() &&
                                           t.target_weights.empty() && t.offsets.size() == 3 * points) &&
                  std::isfinite(t.stiffness) && t.stiffness >= 0.0 && std::isfinite(t.damping) && t.damping >= 0.0;
        for (uint32_t n : t.nodes) ok = ok && n < im.bodies[t.body].ref.node_count();
        for (uint32_t n : t.target_nodes) ok = ok && deformable_target && n < im.bodies[t.target].ref.node_count();
        for (const std::vector<double>* v : {&t.offsets, &t.lambda, &t.weights, &t.target_weights, &t.target_end})
            for (double x : *v) ok = ok && std::isfinite(x);
        if (!ok) fail(path, "an attachment's nodes or offsets are inconsistent");
    }
    for (uint32_t f : all.free_slots)
        if (f >= all.slots.size() || all.slots[f].generation != 0) fail(path, "bad free attachment list");
    for (uint64_t key : im.state.touching)
        if (uint32_t(key >> 32) >= im.bodies.size() || uint32_t(key) >= im.bodies.size())
            fail(path, "a touching pair names a missing body");
}

void put_u32(std::string& s, uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); }
void put_u64(std::string& s, uint64_t v) { s.append(reinterpret_cast<const char*>(&v), 8); }
template <class T>
T get(const char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

const uint32_t kLayout[4] = {uint32_t(sizeof(WorldDef)), uint32_t(sizeof(BodyDef)),
                             uint32_t(sizeof(Body)), uint32_t(sizeof(ContactRecord))};

}  // namespace

void save_checkpoint(const World& world, const std::string& path) {
    Writer w;
    world_def_fields(w, world.def());
    counter_fields(w, world.state().counters);
    const std::vector<Body>& slots = world.bodies().slots();
    w(uint64_t(slots.size()));
    for (const Body& b : slots) body_fields(w, b);
    w(world.bodies().free_slots());
    w(uint64_t(world.state().contacts.size()));
    for (const ContactRecord& c : world.state().contacts) contact_fields(w, c);
    const Attachments& attachments = world.state().attachments;
    w(uint64_t(attachments.slots.size()));
    for (const Attachment& t : attachments.slots) attachment_fields(w, t);
    w(attachments.free_slots);
    w(world.state().touching);

    std::string file(kMagic, sizeof kMagic);
    put_u32(file, kFormatVersion);
    put_u32(file, kByteOrderMark);
    for (uint32_t v : kLayout) put_u32(file, v);
    const std::string& payload = w.bytes();
    put_u64(file, payload.size());
    put_u64(file, fnv1a(payload.data(), payload.size()));
    const std::string tmp = path + ".tmp";
    // std::filesystem::rename, not std::rename: on Windows the latter refuses to replace an
    // existing file; the former replaces it there too (on POSIX both are rename(2)). Its paths
    // are made before the file, so that running out of memory leaves no .tmp behind.
    const std::filesystem::path from(tmp), to(path);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) fail(path, "cannot open " + tmp + " for writing");
        out.write(file.data(), std::streamsize(file.size()));
        out.write(payload.data(), std::streamsize(payload.size()));
        out.flush();
        if (!out) {
            out.close();
            std::remove(tmp.c_str());
            fail(path, "write failed (disk full?)");
        }
    }
    std::error_code renamed;
    std::filesystem::rename(from, to, renamed);
    if (renamed) {
        std::remove(tmp.c_str());
        fail(path, "cannot rename " + tmp + " to it");
    }
}

WorldImage read_checkpoint(const std::string& path) {
    std::string file;
    {
        std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(path.c_str(), "rb"), &std::fclose);
        if (!in) fail(path, "cannot open it for reading");
        char chunk[1 << 16];
        std::size_t got;
        while ((got = std::fread(chunk, 1, sizeof chunk, in.get())) > 0) file.append(chunk, got);
        // A directory, say, opens but cannot be read.
        if (std::ferror(in.get())) fail(path, "cannot be read");
    }
    if (file.size() < kHeaderSize) fail(path, "truncated (shorter than its header)");
    if (std::memcmp(file.data(), kMagic, sizeof kMagic) != 0) fail(path, "not an lfem checkpoint");
    const char* p = file.data() + sizeof kMagic;
    if (get<uint32_t>(p) != kFormatVersion)
        fail(path, "format version " + std::to_string(get<uint32_t>(p)) + (get<uint32_t>(p) < kFormatVersion ? " (an older lfem's)" : " (a newer lfem's)") +
                       "; this library reads version " + std::to_string(kFormatVersion) +
                       " only: save the scene again with this version");
    if (get<uint32_t>(p + 4) != kByteOrderMark) fail(path, "written on a machine of other byte order");
    for (int i = 0; i < 4; ++i)
        if (get<uint32_t>(p + 8 + 4 * i) != kLayout[i])
            fail(path, "written by a build of lfem with another data layout");
    const uint64_t size = get<uint64_t>(p + 24), checksum = get<uint64_t>(p + 32);
    if (size != file.size() - kHeaderSize)
        fail(path, size > file.size() - kHeaderSize ? "truncated" : "has trailing bytes");
    const char* payload = file.data() + kHeaderSize;
    if (fnv1a(payload, std::size_t(size)) != checksum) fail(path, "corrupted (checksum mismatch)");

    Reader r(path, payload, std::size_t(size));
    WorldImage im;
    world_def_fields(r, im.def);
    counter_fields(r, im.state.counters);
    uint64_t slots = 0;
    r(slots);
    if (slots > size) fail(path, "truncated (slot count)");
    im.bodies.resize(std::size_t(slots));
    for (Body& b : im.bodies) body_fields(r, b);
    r(im.free_slots);
    uint64_t contacts = 0;
    r(contacts);
    if (contacts > size) fail(path, "truncated (contact count)");
    im.state.contacts.resize(std::size_t(contacts));
    for (ContactRecord& c : im.state.contacts) contact_fields(r, c);
    uint64_t attachments = 0;
    r(attachments);
    if (attachments > size) fail(path, "truncated (attachment count)");
    im.state.attachments.slots.resize(std::size_t(attachments));
    for (Attachment& t : im.state.attachments.slots) attachment_fields(r, t);
    r(im.state.attachments.free_slots);
    r(im.state.touching);
    if (!r.at_end()) fail(path, "has bytes after its last record");
    check_image(im, path);
    for (Body& b : im.bodies) {  // derived: the loads of the next call (the sizes checked above)
        b.applied_force.resize(b.call_force.size());
        b.refresh_loads();
    }
    return im;
}

}  // namespace lfem
