// libFuzzer target: bytes become a world definition and then a sequence of C API calls on that
// world: bodies of every type, model and flag (category and mask bits, self-contact, composite
// and 10-node tets, sleep), meshes of every builder and of arbitrary numbers, shapes, node
// constraints, forces and velocities, steps with arbitrary dt, attachments (to a frame or a
// body, moved, read, broken, destroyed), events, sleep and wake, every getter with arbitrary
// buffers, skins, rays and boxes, checkpoints (also corrupted ones), VTK frames, worlds re-created
// with other definitions (1 to 3 threads, sleep, mass scaling), and arguments that must be
// refused: NaNs, null pointers, out-of-range indices, stale and foreign handles, small buffers.
//
// Checked after every call:
// - the status is one of lfem's, not LFEM_INTERNAL_ERROR, and a failure leaves a message;
// - a failed call leaves the world as it was: statistics, every body's validity, counts,
//   sleep state, positions and velocities, every attachment's validity and force, and the
//   warnings, bit for bit (a digest taken before each call);
// - a failed call leaves its outputs untouched (buffers filled with a pattern beforehand);
// - what the documentation promises of a result: a buffer too small gives a count above its
//   capacity, node and triangle indices are in range, contacts name live bodies, is_awake is
//   -1 exactly for an invalid handle, a destroyed body's attachments are gone, a def not made by
//   *_def_default or a corrupted checkpoint is refused, and so on (see one_call);
// - nothing crashes, leaks or reads out of bounds (the sanitizers watch).
// Sub-step counts are capped (max_substeps <= 64) and meshes are tiny, so an input runs in
// milliseconds.
//
// Every exported function is called somewhere below. Only lfem_mesh_load_gmsh is called with
// nothing to read (no path, a missing file): the Gmsh reader has its own target, fuzz_gmsh.
//
// The byte format: see read_world_def and one_call; tests/fuzz/make_api_seeds.py writes
// programs in it (the seeds and the regression inputs). Changing what a call reads, or the
// number of calls, changes what every input means: run make_api_seeds.py again, and re-express
// any raw regression input as a program there.
#include <dirent.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "lfem.h"

using lfem_fuzz::Input;

namespace {

[[noreturn]] void broken(const char* what, const char* detail = "") {
    std::fprintf(stderr, "fuzz_api: %s %s\n", what, detail);
    std::abort();
}

struct BodyInfo {
    lfem_body handle;
    uint32_t epoch;   // the world it was made in (Session::epoch)
    void* user_data;  // what lfem_body_get_user_data must return while the body lives
};

struct AttachmentInfo {
    lfem_attachment handle;
    uint32_t epoch;
    lfem_body body, target;
};

struct Session {
    lfem_world* world = nullptr;
    uint32_t epoch = 0;                       // bumped when the world is replaced by a new one
    std::vector<BodyInfo> bodies;             // every handle ever returned, live or stale
    std::vector<AttachmentInfo> attachments;  // the same for attachments
    int null_arg = -1;                        // this call passes NULL for its pointer number null_arg
    std::string note;                         // what the call found, printed with LFEM_FUZZ_VERBOSE
};

// LFEM_FUZZ_VERBOSE=1 prints each call (to see what an input does, e.g. a crash's or a seed's).
const bool verbose = std::getenv("LFEM_FUZZ_VERBOSE") != nullptr;

void note(Session& s, const char* what, long long value) {
    if (verbose) s.note += std::string(s.note.empty() ? "" : " ") + what + std::to_string(value);
}

// A pointer argument of the current call, or NULL when the call's selector asked for it.
template <class T>
T* arg(const Session& s, int k, T* p) {
    return s.null_arg == k ? nullptr : p;
}

lfem_body pick_body(Session& s, Input& in) {
    const uint8_t how = in.byte();
    if (how < 220 && !s.bodies.empty()) return s.bodies[in.below(uint32_t(s.bodies.size()))].handle;
    return lfem_body{in.u32() % 8, in.u32()};  // made up: null, stale or foreign
}

lfem_attachment pick_attachment(Session& s, Input& in) {
    const uint8_t how = in.byte();
    if (how < 220 && !s.attachments.empty())
        return s.attachments[in.below(uint32_t(s.attachments.size()))].handle;
    return lfem_attachment{in.u32() % 8, in.u32()};
}

bool is_null(lfem_body b) { return b.index == 0 && b.generation == 0; }

std::vector<uint32_t> node_list(Input& in) {
    std::vector<uint32_t> nodes(in.below(6));
    for (uint32_t& n : nodes) n = in.below(40);
    return nodes;
}

// A builder's length: what the input says, but a finite positive one is kept in [lo, hi] so
// that no mesh grows beyond a few hundred tets (the builders accept up to millions, which take
// seconds a step); zero, negative and non-finite values go through (they must be refused).
double length(Input& in, double lo, double hi) {
    const double v = in.number(lo, hi);
    return std::isfinite(v) && v > 0 ? std::min(std::max(v, lo), hi) : v;
}

// A buffer filled with a pattern, to see whether a call wrote to it.
template <class T>
struct Buffer {
    std::vector<T> v;
    explicit Buffer(std::size_t n) : v(n) {
        if (n) std::memset(static_cast<void*>(v.data()), 0xA5, n * sizeof(T));
    }
    T* data() { return v.empty() ? nullptr : v.data(); }
    bool untouched() const {
        const auto* p = reinterpret_cast<const unsigned char*>(v.data());
        for (std::size_t i = 0; i < v.size() * sizeof(T); ++i)
            if (p[i] != 0xA5) return false;
        return true;
    }
};

void check(lfem_status s, const char* call) {
    if (s < LFEM_OK || s > LFEM_UNSUPPORTED) broken("unknown status from", call);
    if (s == LFEM_INTERNAL_ERROR) broken("internal error:", lfem_last_error());
    if (s != LFEM_OK && !*lfem_last_error()) broken("no message after a failed", call);
}

void expect(bool ok, const char* what, const char* call) {
    if (!ok) broken(what, call);
}

// A failed call must not have written its output.
template <class T>
void untouched_on_failure(lfem_status st, const Buffer<T>& out, const char* call) {
    if (st != LFEM_OK && !out.untouched()) broken("a failed call wrote its output:", call);
}

uint32_t node_count_of(const lfem_world* w, lfem_body b) {
    uint32_t n = 0;
    return lfem_body_get_node_count(w, b, &n) == LFEM_OK ? n : 0;
}

template <class T>
void append(std::vector<unsigned char>& d, const T* p, std::size_t n) {
    const auto* b = reinterpret_cast<const unsigned char*>(p);
    d.insert(d.end(), b, b + n * sizeof(T));
}

// What the next call must leave as it is if it fails, read through the API. Also checks what
// must hold between any two calls.
std::vector<unsigned char> digest(const Session& s, const lfem_world* w) {
    std::vector<unsigned char> d;
    lfem_world_stats st;
    std::memset(&st, 0, sizeof st);
    if (lfem_world_get_stats(w, &st) != LFEM_OK) broken("get_stats failed");
    append(d, &st, 1);
    for (const BodyInfo& b : s.bodies) {
        const int valid = lfem_body_is_valid(w, b.handle), awake = lfem_body_is_awake(w, b.handle);
        if (valid != 0 && valid != 1) broken("body_is_valid gave neither 0 nor 1");
        if ((awake == -1) != (valid == 0) || awake < -1 || awake > 1)
            broken("body_is_awake disagrees with body_is_valid");
        append(d, &valid, 1);
        append(d, &awake, 1);
        if (!valid) continue;
        uint32_t counts[4] = {};
        if (lfem_body_get_node_count(w, b.handle, &counts[0]) != LFEM_OK ||
            lfem_body_get_tet_count(w, b.handle, &counts[1]) != LFEM_OK ||
            lfem_body_get_nodes_per_tet(w, b.handle, &counts[2]) != LFEM_OK ||
            lfem_body_get_skin_count(w, b.handle, &counts[3]) != LFEM_OK)
            broken("a count of a valid body could not be read");
        if (counts[2] != 0 && counts[2] != 4 && counts[2] != 10) broken("nodes_per_tet is not 0, 4 or 10");
        append(d, counts, 4);
        std::vector<double> x(3 * std::size_t(counts[0]) + 1), v(x.size());
        if (lfem_body_get_positions(w, b.handle, x.data(), counts[0]) != LFEM_OK ||
            lfem_body_get_velocities(w, b.handle, v.data(), counts[0]) != LFEM_OK)
            broken("positions or velocities of a valid body could not be read");
        append(d, x.data(), x.size() - 1);
        append(d, v.data(), v.size() - 1);
    }
    for (const AttachmentInfo& a : s.attachments) {
        const int valid = lfem_attachment_is_valid(w, a.handle);
        if (valid != 0 && valid != 1) broken("attachment_is_valid gave neither 0 nor 1");
        append(d, &valid, 1);
        if (!valid) continue;
        // Destroying a body or a target destroys its attachments.
        if (a.epoch == s.epoch &&
            (!lfem_body_is_valid(w, a.body) || (!is_null(a.target) && !lfem_body_is_valid(w, a.target))))
            broken("an attachment outlived its body or target");
        double f[3];
        if (lfem_attachment_get_force(w, a.handle, f) != LFEM_OK) broken("attachment_get_force failed");
        append(d, f, 3);
    }
    for (int k = 0; k < LFEM_WARNING_KIND_COUNT; ++k) {
        lfem_warning warning;
        std::memset(&warning, 0, sizeof warning);
        if (lfem_world_get_warning(w, lfem_warning_kind(k), &warning) != LFEM_OK) broken("get_warning failed");
        append(d, &warning, 1);
    }
    return d;
}

// The world definition: the input's first bytes, and what world_create reads.
lfem_world_def read_world_def(Input& in) {
    lfem_world_def def = lfem_world_def_default();
    def.max_substeps = 1 + in.below(64);
    def.contact_iterations = 1 + in.below(50);
    def.step_safety = in.number(0.05, 0.99);
    def.thread_count = 1 + in.below(3);
    const uint8_t f = in.byte();
    def.enable_sleep = f & 1;
    if (f & 2) def.mass_scaling_step = in.number(0, 2e-4);
    if (f & 4) def.sleep_velocity = in.number(0, 0.5), def.sleep_time = in.number(0, 0.1);
    if (f & 8)
        for (double& g : def.gravity) g = in.number(-20, 20);
    if (f & 16) def.time_step = in.number(0, 1e-3), def.allow_unstable_step = in.byte() & 1;
    if (f & 32) def.contact_tolerance = in.number(1e-6, 0.1);
    if (f & 64) {  // raw values, mostly refused (more than 4 threads would only be slow: 4)
        def.thread_count = in.u32();
        if (def.thread_count > 4 && def.thread_count <= 64) def.thread_count = 4;
        def.enable_sleep = in.byte();
        def.allow_unstable_step = in.byte();
    }
    if (f & 128) def.internal_value ^= 1u + in.byte();  // not made by lfem_world_def_default
    return def;
}

// A world def that lfem_world_create must refuse (the numbers are checked by the library).
bool def_refusable(const lfem_world_def& d, const lfem_world_def& made) {
    return d.internal_value != made.internal_value || d.thread_count < 1 || d.thread_count > 64 ||
           d.enable_sleep > 1 || d.allow_unstable_step > 1;
}

// Reads a corrupted or intact checkpoint and, when it loads, reads everything of it (a loaded
// world must be consistent whatever the file said; it is not stepped, since a consistent file
// may still ask for 2^32 contact sweeps a sub-step).
void read_loaded(const Session& s, lfem_world* loaded) {
    digest(s, loaded);
    uint32_t count = 0;
    lfem_world_query_contacts(loaded, nullptr, 0, &count);
    lfem_world_get_events(loaded, nullptr, 0, &count);
    const double o[3] = {0.01, 0.02, 2}, dir[3] = {0, 0, -1}, lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    lfem_world_cast_ray_all(loaded, o, dir, 5, lfem_query_filter_default(), nullptr, 0, &count);
    lfem_world_overlap_box(loaded, lo, hi, lfem_query_filter_default(), nullptr, 0, &count);
    double h = 0;
    lfem_world_get_stable_step(loaded, &h);
}

uint64_t fnv1a(const std::string& data, std::size_t from) {
    uint64_t h = 1469598103934665603ull;
    for (std::size_t i = from; i < data.size(); ++i) h = (h ^ uint8_t(data[i])) * 1099511628211ull;
    return h;
}

void remove_folder(const std::string& dir) {
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d))
            if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0)
                unlink((dir + "/" + e->d_name).c_str());
        closedir(d);
    }
    rmdir(dir.c_str());
}

// Teleports, poses, impulses and settings (a variant of call 24, flag bit 2): set_positions
// (nodes at random, perhaps the wrong count), set_transform (any pose, perhaps a zero
// quaternion), the two getters (whose outputs are finite, or untouched when refused), an impulse
// at a point, a setting changed (friction, damping, filter, user data), a skin removed.
lfem_status teleport(Session& s, Input& in, lfem_world* w, lfem_body b, uint8_t f, const char*& name) {
    switch (in.below(7)) {
        case 0: {
            name = "body_set_positions";
            uint32_t n = node_count_of(w, b);
            if (f & 1) n = in.below(40);
            std::vector<double> x(3 * std::size_t(n));
            for (double& v : x) v = in.number(-1, 1);
            const lfem_status st = lfem_body_set_positions(w, b, arg(s, 0, x.data()), n);
            if (st == LFEM_OK) {
                expect(n == node_count_of(w, b), "positions of the wrong count were accepted:", name);
                std::vector<double> back(x.size());
                expect(lfem_body_get_positions(w, b, back.data(), n) == LFEM_OK && back == x,
                       "the positions set are not the positions read:", name);
            }
            return st;
        }
        case 1: {
            name = "body_set_transform";
            double t[7];
            for (int k = 0; k < 3; ++k) t[k] = in.number(-2, 2);
            for (int k = 3; k < 7; ++k) t[k] = (f & 1) ? 0.0 : in.number(-1, 1);
            const lfem_status st = lfem_body_set_transform(w, b, arg(s, 0, t));
            if (st == LFEM_OK) {
                double back[7];
                expect(lfem_body_get_transform(w, b, back) == LFEM_OK, "a teleported body has no transform:", name);
                for (double v : back) expect(std::isfinite(v), "a teleported body's transform is not finite:", name);
            }
            return st;
        }
        case 3: {
            name = "body_apply_impulse";
            double p[3], j[3], P0[3] = {0, 0, 0}, P1[3] = {0, 0, 0};
            for (double& v : p) v = in.number(-1, 1);
            for (double& v : j) v = in.number(-5, 5);
            const bool read = lfem_body_get_momentum(w, b, P0, nullptr) == LFEM_OK;
            const lfem_status st = lfem_body_apply_impulse(w, b, arg(s, 0, p), arg(s, 1, j));
            if (st == LFEM_OK && read && lfem_body_get_momentum(w, b, P1, nullptr) == LFEM_OK)
                for (int k = 0; k < 3; ++k)  // no more than the impulse (held nodes pass theirs on),
                    // to the rounding of sums as large as the whole momentum, impulse and spin: a
                    // rigid body's node momenta sum omega x (m r) over its nodes, about zero to
                    // 1e-16 of the spin (a 3e101 N s impulse along y moved x by 1e83; one along y
                    // on a body of 6e298 kg m/s along z moved x by 2e282; 5 N s at 9e61 m from
                    // the body, by 6e46)
                    expect(std::isfinite(P1[k]) &&
                               std::fabs(P1[k] - P0[k]) <=
                                   std::fabs(j[k]) * (1 + 1e-9) +
                                       1e-9 * (1 + std::hypot(P0[0], P0[1], P0[2]) +
                                               std::hypot(j[0], j[1], j[2]) * (1 + std::hypot(p[0], p[1], p[2]))),
                           "an impulse changed the momentum by more than itself:", name);
            return st;
        }
        case 4: {
            const double value = in.number(-1, 10);
            switch (in.below(6)) {
                case 0: name = "body_set_friction"; return lfem_body_set_friction(w, b, value);
                case 4:  // any int, not the double (a huge one does not convert)
                    name = "body_set_sleep_allowed";
                    return lfem_body_set_sleep_allowed(w, b, static_cast<int>(in.u32()));
                case 1:
                    if (f & 1) {
                        name = "body_set_material";
                        return lfem_body_set_material(w, b, 1e3 + 1e6 * std::fabs(value), in.number(-1.2, 0.6));
                    }
                    name = "body_set_damping";
                    return lfem_body_set_damping(w, b, value);
                case 2: name = "body_set_filter"; return lfem_body_set_filter(w, b, in.u32(), in.u32());
                case 5: {
                    name = "body_set_type";
                    const lfem_body_type type = lfem_body_type(in.below(5));  // 4: no type
                    const lfem_status st = lfem_body_set_type(w, b, type);
                    lfem_body_type now = LFEM_BODY_TYPE_FORCE32;
                    if (st == LFEM_OK)
                        expect(lfem_body_get_type(w, b, &now) == LFEM_OK && now == type, "the type set is not the one read:",
                               name);
                    return st;
                }
                default: {
                    name = "body_set_user_data";
                    // The session's record of the body's user data stays the truth: set it back.
                    void* was = nullptr;
                    if (lfem_body_get_user_data(w, b, &was) != LFEM_OK) return lfem_body_set_user_data(w, b, nullptr);
                    const lfem_status st = lfem_body_set_user_data(w, b, reinterpret_cast<void*>(uintptr_t(0xABC0)));
                    void* now = nullptr;
                    expect(st != LFEM_OK || (lfem_body_get_user_data(w, b, &now) == LFEM_OK && now == reinterpret_cast<void*>(uintptr_t(0xABC0))),
                           "the user data set is not the one read:", name);
                    return st == LFEM_OK ? lfem_body_set_user_data(w, b, was) : st;
                }
            }
        }
        case 5: {
            name = "body_remove_skin";
            uint32_t before = 0;
            const bool counted = lfem_body_get_skin_count(w, b, &before) == LFEM_OK;
            const lfem_status st = lfem_body_remove_skin(w, b, in.below(4));
            uint32_t after = 0;
            if (st == LFEM_OK)
                expect(counted && lfem_body_get_skin_count(w, b, &after) == LFEM_OK && after + 1 == before,
                       "a skin removed did not lower the count by one:", name);
            return st;
        }
        case 6: {
            if (f & 1) {
                name = "body_set_user_id";
                const uint64_t high = in.u32();  // two reads in sequence (an | does not order them)
                const uint64_t id = high << 32 | in.u32();
                const lfem_status st = lfem_body_set_user_id(w, b, id);
                uint64_t back = 7;
                const lfem_status sb = lfem_body_get_user_id(w, b, arg(s, 0, &back));
                expect(st != LFEM_OK || sb != LFEM_OK || back == id, "the user id set is not the one read:", name);
                expect(sb == LFEM_OK || back == 7, "a refused user id read wrote its output:", name);
                return st;
            }
            name = "body_apply_force";
            double p[3], F[3], P0[3] = {0, 0, 0}, P1[3] = {0, 0, 0};
            for (double& v : p) v = in.number(-1, 1);
            for (double& v : F) v = in.number(-50, 50);
            const bool read = lfem_body_get_momentum(w, b, P0, nullptr) == LFEM_OK;
            const lfem_status st = lfem_body_apply_force(w, b, arg(s, 0, p), arg(s, 1, F));
            if (st == LFEM_OK && read)  // a force acts in the next call: the momentum is as it was
                expect(lfem_body_get_momentum(w, b, P1, nullptr) == LFEM_OK && P1[0] == P0[0] && P1[1] == P0[1] &&
                           P1[2] == P0[2],
                       "a force for the next call changed the momentum now:", name);
            return st;
        }
        default: {
            name = "body_get_transform/center_of_mass";
            double t[7] = {7, 7, 7, 7, 7, 7, 7}, c[3] = {7, 7, 7};
            const lfem_status sc = lfem_body_get_center_of_mass(w, b, arg(s, 1, c));
            {
                const double p[3] = {0.1, -0.2, 0.3};
                double q[3] = {7, 7, 7}, d = 7;
                uint32_t tri = 7;
                const lfem_status sq = lfem_body_closest_point(w, b, p, arg(s, 2, q), &tri, &d);
                for (double v : q) expect(sq == LFEM_OK ? std::isfinite(v) : v == 7, "a closest point read is wrong:", name);
                expect(sq == LFEM_OK ? d >= 0 && std::isfinite(d) : d == 7 && tri == 7, "a closest distance is wrong:", name);
            }
            const lfem_status st = lfem_body_get_transform(w, b, arg(s, 0, t));  // its message last
            for (double v : t) expect(st == LFEM_OK ? std::isfinite(v) : v == 7, "a transform read is wrong:", name);
            for (double v : c) expect(sc == LFEM_OK ? std::isfinite(v) : v == 7, "a centre read is wrong:", name);
            return st;
        }
    }
}

// The number of calls one_call knows.
constexpr uint32_t kCalls = 29;

// One call chosen by the input: a u32 selector, whose low 24 bits (mod kCalls) choose the call
// and whose top byte may ask for a NULL world (0xFF) or a NULL pointer argument (0xF0..0xFE: the
// argument numbered (byte & 7) in the call's arg(s, k, p)). Returns the status that says whether
// the world may have changed (LFEM_OK) or must be as it was, and the call's name.
lfem_status one_call(Session& s, Input& in, const char*& name) {
    const uint32_t op = in.u32();
    const uint32_t top = op >> 24;
    lfem_world* w = top == 0xFF ? nullptr : s.world;
    s.null_arg = top >= 0xF0 && top < 0xFF ? int(top & 7) : -1;
    switch ((op & 0xFFFFFF) % kCalls) {
        case 0: {
            name = "body_create";
            lfem_body_def d = lfem_body_def_default();
            const lfem_body_def made = d;
            d.type = lfem_body_type(in.below(5));
            d.model = lfem_model(in.below(5));
            d.young_modulus = in.number(1e3, 1e8);
            d.poisson_ratio = in.number(-0.2, 0.5);
            d.density = in.number(10, 2e4);
            d.damping = in.number(0, 10);
            d.friction = in.number(0, 1);
            for (int k = 0; k < 3; ++k) d.linear_velocity[k] = in.number(-10, 10);
            for (int k = 0; k < 3; ++k) d.angular_velocity[k] = in.number(-5, 5);
            const uint8_t f = in.byte();
            if (f & 1) d.mask_bits = in.u32();
            if (f & 2) d.category_bits = in.u32();
            d.self_contact = (f >> 2) & 1;
            d.composite_tets = (f >> 3) & 1;
            d.enable_sleep = ((f >> 4) & 1) ^ 1;
            d.report_contacts = (f >> 7) & 1;
            d.edge_contacts = ((f >> 2) ^ (f >> 3) ^ 1) & 1;  // off with one of the two bits above
            if (f & 32)
                d.self_contact = in.byte(), d.composite_tets = in.byte(), d.enable_sleep = in.byte(),
                d.edge_contacts = in.byte();
            if (f & 64) d.internal_value ^= 1u + in.byte();
            void* user_data = reinterpret_cast<void*>(uintptr_t(0x1000 + 8 * s.bodies.size()));
            d.user_data = user_data;
            lfem_body b{12345, 678};
            const lfem_status st = lfem_body_create(w, arg(s, 0, &d), arg(s, 1, &b));
            if (st != LFEM_OK) {
                expect(b.index == 12345 && b.generation == 678, "a failed call wrote its output:", name);
                return st;
            }
            expect(d.internal_value == made.internal_value && d.self_contact <= 1 && d.composite_tets <= 1 &&
                       d.enable_sleep <= 1 && d.edge_contacts <= 1,
                   "a def that must be refused was accepted:", name);
            s.bodies.push_back({b, s.epoch, user_data});
            expect(lfem_body_is_valid(w, b) == 1 && lfem_body_is_awake(w, b) == 1 && node_count_of(w, b) == 0,
                   "a new body is not valid, awake and empty:", name);
            return st;
        }
        case 1: {
            name = "body_add_mesh(builder)";
            lfem_mesh* m = nullptr;
            lfem_status st;
            switch (in.below(4)) {
                case 0: {
                    const double size[3] = {length(in, 0.01, 1), length(in, 0.01, 1), length(in, 0.01, 1)};
                    const uint32_t cells[3] = {in.below(4), in.below(4), in.below(4)};  // 0: refused
                    st = lfem_mesh_create_box(arg(s, 0, size), arg(s, 1, cells), arg(s, 2, &m));
                    break;
                }
                case 1: {
                    const double r = length(in, 0.02, 0.3), h = length(in, 0.02, 0.3);
                    const uint32_t segments = in.below(7), rings = in.below(3), layers = in.below(3);
                    st = lfem_mesh_create_cylinder(r, h, segments, rings, layers, arg(s, 2, &m));
                    break;
                }
                case 2: {
                    // The cup's cells are as small as its cavity is shallow: a bottom of at
                    // most half the height keeps it below a thousand tets.
                    const double r = length(in, 0.03, 0.08), h = length(in, 0.06, 0.12);
                    const double wall = length(in, 0.01, 0.03);
                    double bottom = length(in, 0.01, 0.03);
                    if (std::isfinite(h) && h > 0 && bottom > 0.5 * h) bottom = 0.5 * h;
                    const uint32_t segments = in.below(7), layers = in.below(3);
                    st = lfem_mesh_create_cup(r, h, wall, bottom, segments, layers, arg(s, 2, &m));
                    break;
                }
                default: {
                    const double hl = length(in, 0.05, 0.3), hw = length(in, 0.02, 0.1);
                    const double el = length(in, 0.05, 0.2), ew = length(in, 0.02, 0.1);
                    st = lfem_mesh_create_hammer(hl, hw, el, ew, length(in, 0.05, 0.2), arg(s, 2, &m));
                    break;
                }
            }
            if (st != LFEM_OK) {
                expect(m == nullptr, "a failed call wrote its output:", "mesh_create_*");
                return st;
            }
            const double offset[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-0.2, 1)};
            const uint8_t f = in.byte();
            if (f & 2) {
                const double axis[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
                st = lfem_mesh_rotate(m, arg(s, 3, axis), in.number(-4, 4));
                check(st, "mesh_rotate");
            }
            if (st == LFEM_OK) st = lfem_mesh_translate(m, arg(s, 4, offset));
            check(st, "mesh_translate");
            if (st == LFEM_OK && (f & 1)) {
                st = lfem_mesh_make_quadratic(m);
                check(st, "mesh_make_quadratic");
                if (st == LFEM_OK) {  // a second time: refused, the mesh unchanged
                    const uint32_t n = lfem_mesh_get_node_count(m);
                    expect(lfem_mesh_make_quadratic(m) == LFEM_INVALID_ARGUMENT &&
                               lfem_mesh_get_node_count(m) == n && lfem_mesh_get_nodes_per_tet(m) == 10,
                           "a quadratic mesh made quadratic again:", name);
                }
            }
            if (st == LFEM_OK) {
                const lfem_body b = pick_body(s, in);
                const uint32_t before = node_count_of(w, b);
                const uint32_t per_tet = lfem_mesh_get_nodes_per_tet(m), n = lfem_mesh_get_node_count(m);
                // f & 4: a 10-node mesh given as 4-node tets (it reads fewer indices than there
                // are; the other way round would read past the caller's array).
                const bool quadratic = per_tet == 10 && !(f & 4);
                if (quadratic) name = "body_add_quadratic_mesh(builder)";
                st = (quadratic ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh)(
                    w, b, arg(s, 5, lfem_mesh_get_positions(m)), n, arg(s, 6, lfem_mesh_get_tets(m)),
                    lfem_mesh_get_tet_count(m));
                if (st == LFEM_OK)
                    expect(node_count_of(w, b) == before + n, "the node count did not grow by the mesh's:", name);
            }
            lfem_mesh_destroy(m);
            return st;
        }
        case 2: {
            name = "body_add_mesh(raw)";
            const bool quadratic = in.byte() & 1;
            const uint32_t per_tet = quadratic ? 10 : 4;
            const uint32_t n = in.below(12), t = in.below(6);
            std::vector<double> x(3 * n);
            std::vector<uint32_t> tets(per_tet * t);
            for (double& v : x) v = in.number(-0.5, 0.5);
            for (uint32_t& v : tets) v = in.below(14);
            if (quadratic) name = "body_add_quadratic_mesh(raw)";
            return (quadratic ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh)(
                w, pick_body(s, in), arg(s, 0, x.data()), n, arg(s, 1, tets.data()), t);
        }
        case 3: {
            name = "body_add_triangle_mesh";
            const uint32_t n = in.below(8), t = in.below(5);
            std::vector<double> x(3 * n);
            std::vector<uint32_t> tris(3 * t);
            for (double& v : x) v = in.number(-1, 1);
            for (uint32_t& v : tris) v = in.below(10);
            return lfem_body_add_triangle_mesh(w, pick_body(s, in), arg(s, 0, x.data()), n, arg(s, 1, tris.data()),
                                               t);
        }
        case 4: {
            name = "world_step";
            const double dt = in.byte() < 200 ? in.number(1e-5, 0.02) : in.number(-1, 1);
            const lfem_status st = lfem_world_step(w, dt);
            expect(st != LFEM_OK || (dt > 0 && std::isfinite(dt)), "a step of dt <= 0 or NaN was taken:", name);
            return st;
        }
        case 5: {
            name = "world_query_contacts";
            const uint32_t capacity = in.below(40);
            Buffer<lfem_contact> out(capacity);
            uint32_t count = 0xA5A5A5A5u;
            const lfem_status st = lfem_world_query_contacts(w, arg(s, 0, out.data()), capacity, arg(s, 1, &count));
            untouched_on_failure(st, out, name);
            if (st == LFEM_BUFFER_TOO_SMALL) expect(count > capacity, "too small, yet the count fits:", name);
            if (st != LFEM_OK) return st;
            expect(count <= capacity, "the count exceeds the capacity:", name);
            note(s, "contacts ", count);
            lfem_world_stats stats;
            lfem_world_get_stats(w, &stats);
            expect(count == stats.contact_count, "contacts listed differ from stats.contact_count:", name);
            for (uint32_t i = 0; i < count; ++i) {
                const lfem_contact& c = out.v[i];
                expect(lfem_body_is_valid(w, c.body_a) && lfem_body_is_valid(w, c.body_b),
                       "a contact names a body that is not valid:", name);
                expect(c.node < node_count_of(w, c.body_a), "a contact's node is out of range:", name);
                if (c.shape == UINT32_MAX)
                    for (uint32_t k : c.triangle)
                        expect(k < node_count_of(w, c.body_b), "a contact's triangle is out of range:", name);
            }
            return st;
        }
        case 6: {
            name = "body_get_positions/velocities";
            const bool velocities = in.byte() & 1;
            const uint32_t capacity = in.below(60);
            Buffer<double> out(3 * std::size_t(capacity));
            const lfem_body b = pick_body(s, in);
            const lfem_status st = (velocities ? lfem_body_get_velocities : lfem_body_get_positions)(
                w, b, arg(s, 0, out.data()), capacity);
            untouched_on_failure(st, out, name);
            if (st == LFEM_OK) expect(node_count_of(w, b) <= capacity, "more nodes than the capacity:", name);
            return st;
        }
        case 7: {
            name = "body_fix_nodes";
            const std::vector<uint32_t> nodes = node_list(in);
            return lfem_body_fix_nodes(w, pick_body(s, in), arg(s, 0, nodes.data()), uint32_t(nodes.size()));
        }
        case 8: {
            name = "body_prescribe_node_velocity";
            const std::vector<uint32_t> nodes = node_list(in);
            const double v[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
            return lfem_body_prescribe_node_velocity(w, pick_body(s, in), arg(s, 0, nodes.data()),
                                                     uint32_t(nodes.size()), arg(s, 1, v));
        }
        case 9: {
            name = "body_set_node_forces";
            const std::vector<uint32_t> nodes = node_list(in);
            std::vector<double> f(3 * nodes.size());
            for (double& v : f) v = in.number(-100, 100);
            if (nodes.empty() && (in.byte() & 1)) {
                name = "body_clear_node_forces";
                return lfem_body_clear_node_forces(w, pick_body(s, in));
            }
            return lfem_body_set_node_forces(w, pick_body(s, in), arg(s, 0, nodes.data()), uint32_t(nodes.size()),
                                             arg(s, 1, f.data()));
        }
        case 10: {
            name = "body_destroy";
            const lfem_body b = pick_body(s, in);
            const lfem_status st = lfem_body_destroy(w, b);
            if (st == LFEM_OK) expect(lfem_body_is_valid(w, b) == 0, "a destroyed body is still valid:", name);
            return st;
        }
        case 11: {
            name = "body_add_shape";
            lfem_shape_def d = lfem_shape_def_default();
            d.type = lfem_shape_type(in.below(6));
            for (int k = 0; k < 3; ++k) d.center[k] = in.number(-1, 1);
            for (int k = 0; k < 4; ++k) d.rotation[k] = in.number(-1, 1);
            for (int k = 0; k < 3; ++k) d.half_extents[k] = in.number(0, 0.5);
            d.radius = in.number(0, 0.5);
            d.half_length = in.number(0, 0.5);
            std::vector<double> points(3 * in.below(8));
            for (double& v : points) v = in.number(-0.3, 0.3);
            d.point_count = uint32_t(points.size() / 3);
            d.points = points.empty() ? nullptr : points.data();
            if (in.byte() == 255) d.internal_value ^= 1;
            uint32_t index = 0xA5A5A5A5u;
            const lfem_status st = lfem_body_add_shape(w, pick_body(s, in), arg(s, 0, &d), arg(s, 1, &index));
            if (st != LFEM_OK) expect(index == 0xA5A5A5A5u, "a failed call wrote its output:", name);
            return st;
        }
        case 12: {
            name = "world_set_gravity/time_step";
            if (in.byte() & 1) {
                const double g[3] = {in.number(-20, 20), in.number(-20, 20), in.number(-20, 20)};
                const lfem_status st = lfem_world_set_gravity(w, arg(s, 0, g));
                expect(st != LFEM_OK || (std::isfinite(g[0]) && std::isfinite(g[1]) && std::isfinite(g[2])),
                       "a gravity that is not finite was accepted:", name);
                return st;
            }
            const double h = in.byte() < 128 ? 0.0 : in.number(0, 1e-3);
            const lfem_status st = lfem_world_set_time_step(w, h);
            expect(st != LFEM_OK || (std::isfinite(h) && h >= 0), "a time step < 0 or NaN was accepted:", name);
            return st;
        }
        case 13: {
            name = "body_set_kinematic_velocity";
            const double lin[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
            const double ang[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
            return lfem_body_set_kinematic_velocity(w, pick_body(s, in), arg(s, 0, lin), arg(s, 1, ang));
        }
        case 14: {
            // Save, then load what was saved (and go on with the loaded world), or a copy of the
            // file truncated, with a byte changed, or with a byte changed and the checksum made
            // right again (so that the loader's own checks of the content are what stands).
            name = "world_save/load";
            const uint8_t how = in.byte() % 4;
            const uint32_t where = in.u32();
            const uint8_t value = in.byte();
            char path[] = "/tmp/lfem_fuzz_XXXXXX";
            const int fd = mkstemp(path);
            if (fd < 0) return LFEM_OK;
            close(fd);
            lfem_status st = lfem_world_save(w, arg(s, 0, static_cast<const char*>(path)));
            if (st == LFEM_OK && how != 0) {
                std::string file;
                {
                    std::ifstream f(path, std::ios::binary);
                    file.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
                }
                constexpr std::size_t header = 48, checksum_at = 40;  // src/world/checkpoint.cpp
                const bool changed = file.size() > header && how != 3;  // must then be refused
                if (file.size() > header) {
                    if (how == 1) {
                        file.resize(where % file.size());
                    } else if (how == 2) {
                        file[where % file.size()] ^= char(1 + value % 255);
                    } else {
                        file[header + where % (file.size() - header)] = char(value);
                        const uint64_t h = fnv1a(file, header);
                        std::memcpy(&file[checksum_at], &h, sizeof h);
                    }
                    std::ofstream(path, std::ios::binary | std::ios::trunc).write(file.data(),
                                                                                 std::streamsize(file.size()));
                }
                lfem_world* loaded = reinterpret_cast<lfem_world*>(&s);
                const lfem_status lst = lfem_world_load(path, &loaded);
                check(lst, "world_load(corrupted)");
                note(s, "load of the changed file: status ", lst);
                if (lst != LFEM_OK) {
                    expect(loaded == reinterpret_cast<lfem_world*>(&s), "a failed call wrote its output:", name);
                } else {
                    expect(!changed, "a truncated or changed checkpoint was loaded:", name);
                    read_loaded(s, loaded);
                    lfem_world_destroy(loaded);
                }
                unlink(path);
                return st;
            }
            if (st == LFEM_OK) {
                lfem_world* loaded = nullptr;
                st = lfem_world_load(arg(s, 1, static_cast<const char*>(path)), arg(s, 2, &loaded));
                if (st == LFEM_OK) {
                    // Continue with the loaded world: its handles are the same, user data NULL.
                    lfem_world_destroy(s.world);
                    s.world = loaded;
                    for (BodyInfo& b : s.bodies) b.user_data = nullptr;
                }
            }
            unlink(path);
            return st;
        }
        case 15: {
            name = "body_add_skin";
            const uint32_t n = in.below(12), t = in.below(6);
            std::vector<double> x(3 * n);
            std::vector<uint32_t> tris(3 * t);
            for (double& v : x) v = in.number(-0.5, 1);
            for (uint32_t& v : tris) v = in.below(14);
            const lfem_body b = pick_body(s, in);
            uint32_t before = 0, after = 0, index = 0xA5A5A5A5u;
            lfem_body_get_skin_count(w, b, &before);
            const lfem_status st = lfem_body_add_skin(w, b, arg(s, 0, x.data()), n, arg(s, 1, tris.data()), t,
                                                      arg(s, 2, &index));
            if (st != LFEM_OK) {
                expect(index == 0xA5A5A5A5u, "a failed call wrote its output:", name);
                return st;
            }
            lfem_body_get_skin_count(w, b, &after);
            expect(after == before + 1 && (s.null_arg == 2 || index == before), "the skin count or index is wrong:",
                   name);
            return st;
        }
        case 16: {
            name = "body_get_skin_*";
            const lfem_body b = pick_body(s, in);
            const uint32_t skin = in.below(3), capacity = in.below(20);
            const uint32_t stride = in.below(8), normal_stride = in.below(8);
            const uint8_t f = in.byte();
            Buffer<double> p(3 * std::size_t(capacity)), nrm(3 * std::size_t(capacity));
            Buffer<float> fl(8 * std::size_t(capacity) + 8);
            Buffer<uint32_t> tri(3 * std::size_t(capacity));
            uint32_t sizes[2] = {0xA5A5A5A5u, 0xA5A5A5A5u};
            lfem_status st;
            switch (in.below(5)) {
                case 0:
                    st = lfem_body_get_skin_vertices(w, b, skin, arg(s, 0, p.data()), f & 1 ? nrm.data() : nullptr,
                                                     capacity);
                    break;
                case 1:
                    // The buffer holds 8 floats a vertex: at most capacity / 8 + 1 vertices of
                    // a stride of up to 7, normals 3 floats on.
                    st = lfem_body_get_skin_vertices_f32(w, b, skin, arg(s, 0, fl.data()), stride,
                                                         f & 1 ? fl.data() + 3 : nullptr, normal_stride,
                                                         std::min(capacity, 1u + capacity / 8));
                    break;
                case 2:
                    st = lfem_body_get_skin_triangles(w, b, skin, arg(s, 0, tri.data()), capacity);
                    if (st == LFEM_OK) {
                        uint32_t vertices = 0, triangles = 0;
                        lfem_body_get_skin_sizes(w, b, skin, &vertices, &triangles);
                        for (uint32_t i = 0; i < 3 * triangles; ++i)
                            expect(tri.v[i] < vertices, "a skin triangle's vertex is out of range:", name);
                    }
                    break;
                case 3:
                    st = lfem_body_get_skin_sizes(w, b, skin, f & 1 ? nullptr : &sizes[0],
                                                  f & 2 ? nullptr : &sizes[1]);
                    if (st != LFEM_OK)
                        expect(sizes[0] == 0xA5A5A5A5u && sizes[1] == 0xA5A5A5A5u,
                               "a failed call wrote its output:", name);
                    break;
                default: {
                    uint32_t count = 0xA5A5A5A5u;
                    st = lfem_body_get_skin_count(w, b, arg(s, 0, &count));
                    if (st != LFEM_OK) expect(count == 0xA5A5A5A5u, "a failed call wrote its output:", name);
                    break;
                }
            }
            untouched_on_failure(st, p, name);
            untouched_on_failure(st, nrm, name);
            untouched_on_failure(st, fl, name);
            untouched_on_failure(st, tri, name);
            return st;
        }
        case 17: {
            name = "world_cast_ray(_all)/_sphere/overlap_box/_sphere/_capsule";
            const double a[3] = {in.number(-2, 2), in.number(-2, 2), in.number(-2, 2)};
            const double b[3] = {in.number(-2, 2), in.number(-2, 2), in.number(-2, 2)};
            lfem_query_filter f = lfem_query_filter_default();
            if (in.byte() < 64) f.category_bits = in.u32(), f.mask_bits = in.u32();
            const uint32_t capacity = in.below(8);
            Buffer<lfem_ray_hit> hits(capacity + 1);
            Buffer<lfem_body> found(capacity);
            Buffer<lfem_overlap> overlaps(capacity);
            uint32_t count = 0xA5A5A5A5u;
            lfem_status st;
            const uint32_t which = in.below(6);
            switch (which) {
                case 0: {
                    int hit = 2;
                    st = lfem_world_cast_ray(w, arg(s, 0, a), arg(s, 1, b), in.number(0, 5), f, arg(s, 2, hits.data()),
                                             arg(s, 3, &hit));
                    if (st == LFEM_OK) {
                        expect(hit == 0 || hit == 1, "cast_ray's hit is neither 0 nor 1:", name);
                        expect(hit == 1 || hits.untouched(), "a ray that hit nothing wrote a hit:", name);
                    }
                    break;
                }
                case 1:
                    st = lfem_world_cast_ray_all(w, arg(s, 0, a), arg(s, 1, b), in.number(0, 5), f,
                                                 arg(s, 2, capacity ? hits.data() : nullptr), capacity,
                                                 arg(s, 3, &count));
                    break;
                case 2:
                    st = lfem_world_overlap_box(w, arg(s, 0, a), arg(s, 1, b), f,
                                                arg(s, 2, capacity ? found.data() : nullptr), capacity,
                                                arg(s, 3, &count));
                    if (st == LFEM_OK)
                        for (uint32_t i = 0; i < count; ++i)
                            expect(lfem_body_is_valid(w, found.v[i]), "a box found a body that is not valid:", name);
                    break;
                case 5: {  // a sphere of radius 0.1 cast from a along b (the limit read as for a ray)
                    int hit = 2;
                    st = lfem_world_cast_sphere(w, arg(s, 0, a), arg(s, 1, b), 0.1, in.number(0, 5), f,
                                                arg(s, 2, hits.data()), arg(s, 3, &hit));
                    if (st == LFEM_OK) {
                        expect(hit == 0 || hit == 1, "cast_sphere's hit is neither 0 nor 1:", name);
                        expect(hit == 1 || hits.untouched(), "a sphere that hit nothing wrote a hit:", name);
                        if (hit == 1) expect(hits.v[0].distance >= 0, "a sphere cast hit behind its origin:", name);
                    }
                    break;
                }
                default: {  // 3: a sphere at a, 4: a capsule from a to b; the radius read as a ray's limit
                    const double radius = in.number(0, 5);
                    lfem_overlap* out = arg(s, 2, capacity ? overlaps.data() : nullptr);
                    st = which == 3
                             ? lfem_world_overlap_sphere(w, arg(s, 0, a), radius, f, out, capacity, arg(s, 3, &count))
                             : lfem_world_overlap_capsule(w, arg(s, 0, a), arg(s, 1, b), radius, f, out, capacity,
                                                          arg(s, 3, &count));
                    if (st == LFEM_OK)
                        for (uint32_t i = 0; i < count; ++i) {
                            const lfem_overlap& o = overlaps.v[i];
                            expect(lfem_body_is_valid(w, o.body), "an overlap names a body that is not valid:", name);
                            expect(o.distance >= 0 && o.distance <= radius * (1 + 1e-9) + 1e-12,
                                   "an overlap lies beyond the radius:", name);
                            for (double v : o.point) expect(std::isfinite(v), "an overlap's point is not finite:", name);
                        }
                    break;
                }
            }
            untouched_on_failure(st, hits, name);
            untouched_on_failure(st, found, name);
            untouched_on_failure(st, overlaps, name);
            if (st == LFEM_BUFFER_TOO_SMALL) expect(count > capacity, "too small, yet the count fits:", name);
            if (st == LFEM_OK && count != 0xA5A5A5A5u) expect(count <= capacity, "the count exceeds the capacity:", name);
            return st;
        }
        case 18: {
            name = "body_release_nodes";
            const std::vector<uint32_t> nodes = node_list(in);
            return lfem_body_release_nodes(w, pick_body(s, in), arg(s, 0, nodes.data()), uint32_t(nodes.size()));
        }
        case 19: {
            // A new world replaces the current one; the old handles become foreign.
            name = "world_create";
            const lfem_world_def def = read_world_def(in);
            lfem_world* created = reinterpret_cast<lfem_world*>(&s);
            const lfem_status st = lfem_world_create(arg(s, 0, &def), arg(s, 1, &created));
            if (st != LFEM_OK) {
                expect(created == reinterpret_cast<lfem_world*>(&s), "a failed call wrote its output:", name);
                return st;
            }
            expect(!def_refusable(def, lfem_world_def_default()), "a def that must be refused was accepted:", name);
            lfem_world_destroy(s.world);
            s.world = created;
            ++s.epoch;
            return st;
        }
        case 20: {
            name = "attachment_create";
            lfem_attachment_def d = lfem_attachment_def_default();
            d.body = pick_body(s, in);
            const uint8_t f = in.byte();
            if (f & 1) d.target = pick_body(s, in);
            const std::vector<uint32_t> nodes = node_list(in);
            d.nodes = arg(s, 0, nodes.data());
            d.node_count = uint32_t(nodes.size());
            if (f & 2) {
                for (int k = 0; k < 3; ++k) d.frame[k] = in.number(-1, 1);
                for (int k = 3; k < 7; ++k) d.frame[k] = in.number(-1, 1);
            }
            if (f & 4) d.break_force = in.number(0, 50);
            if (f & 8) d.internal_value ^= 1;
            std::vector<double> points;
            if (f & 16) {  // points by position instead of (or, refused, beside) nodes
                points.resize(3 * std::size_t(in.below(5)));
                for (double& v : points) v = in.number(-0.2, 0.3);
                d.points = arg(s, 3, points.data());
                d.point_count = uint32_t(points.size() / 3);
                if (!(f & 64)) d.nodes = nullptr, d.node_count = 0;
            }
            if (f & 32) d.stiffness = in.number(0, 1e4), d.damping = in.number(0, 20);
            lfem_attachment a{12345, 678};
            const lfem_status st = lfem_attachment_create(w, arg(s, 1, &d), arg(s, 2, &a));
            if (st != LFEM_OK) {
                expect(a.index == 12345 && a.generation == 678, "a failed call wrote its output:", name);
                return st;
            }
            expect(!(f & 8), "a def that must be refused was accepted:", name);
            expect(lfem_attachment_is_valid(w, a) == 1, "a new attachment is not valid:", name);
            s.attachments.push_back({a, s.epoch, d.body, d.target});
            return st;
        }
        case 21: {
            const lfem_attachment a = pick_attachment(s, in);
            switch (in.below(4)) {
                case 0: {
                    name = "attachment_destroy";
                    const lfem_status st = lfem_attachment_destroy(w, a);
                    if (st == LFEM_OK)
                        expect(lfem_attachment_is_valid(w, a) == 0, "a destroyed attachment is still valid:", name);
                    return st;
                }
                case 1: {
                    name = "attachment_set_frame";
                    double frame[7];
                    for (double& v : frame) v = in.number(-1, 1);
                    const lfem_status st = lfem_attachment_set_frame(w, a, arg(s, 0, frame));
                    double back[7];
                    if (st == LFEM_OK)
                        expect(lfem_attachment_get_frame(w, a, back) == LFEM_OK && std::equal(back, back + 7, frame),
                               "the frame set is not the frame read:", name);
                    return st;
                }
                case 2: {
                    name = "attachment_get_force";
                    Buffer<double> force(3);
                    const lfem_status st = lfem_attachment_get_force(w, a, arg(s, 0, force.data()));
                    untouched_on_failure(st, force, name);
                    return st;
                }
                default: {
                    name = "attachment_is_valid";
                    const int valid = lfem_attachment_is_valid(w, a);
                    note(s, "valid ", valid);
                    expect(valid == 0 || valid == 1, "attachment_is_valid gave neither 0 nor 1", "");
                    return LFEM_OK;
                }
            }
        }
        case 22: {
            name = "world_get_events";
            const uint32_t capacity = in.below(4);
            Buffer<lfem_event> out(capacity);
            uint32_t count = 0xA5A5A5A5u;
            const lfem_status st = lfem_world_get_events(w, arg(s, 0, out.data()), capacity, arg(s, 1, &count));
            untouched_on_failure(st, out, name);
            if (st == LFEM_BUFFER_TOO_SMALL) expect(count > capacity, "too small, yet the count fits:", name);
            if (st != LFEM_OK) return st;
            expect(count <= capacity, "the count exceeds the capacity:", name);
            note(s, "events ", count);
            for (uint32_t i = 0; i < count; ++i) {
                const lfem_event& e = out.v[i];
                note(s, "type ", e.type);
                expect(e.type >= LFEM_EVENT_CONTACT_BEGIN && e.type <= LFEM_EVENT_CONTACT_PERSIST,
                       "an event of no known type:", name);
                if (e.type == LFEM_EVENT_ATTACHMENT_BROKEN)
                    expect(lfem_attachment_is_valid(w, e.attachment) == 0, "a broken attachment is still valid:", name);
            }
            return st;
        }
        case 23: {
            const lfem_body b = pick_body(s, in);
            if (in.byte() & 1) {
                name = "body_is_awake";
                note(s, "awake ", lfem_body_is_awake(w, b));
                return LFEM_OK;  // the digest compares it with body_is_valid before every call
            }
            name = "body_wake";
            const lfem_status st = lfem_body_wake(w, b);
            if (st == LFEM_OK) expect(lfem_body_is_awake(w, b) == 1, "a woken body is not awake:", name);
            return st;
        }
        case 24: {
            name = "body_set_velocities";
            const lfem_body b = pick_body(s, in);
            const uint8_t f = in.byte();
            if (f & 2) return teleport(s, in, w, b, f, name);
            uint32_t n = node_count_of(w, b);
            if (f & 1) n = in.below(40);  // most likely the wrong count
            std::vector<double> v(3 * std::size_t(n));
            for (double& x : v) x = in.number(-2, 2);
            const lfem_status st = lfem_body_set_velocities(w, b, arg(s, 0, v.data()), n);
            if (st == LFEM_OK) {
                expect(n == node_count_of(w, b), "velocities of the wrong count were accepted:", name);
                for (double x : v) expect(std::isfinite(x), "a velocity that is not finite was accepted:", name);
            }
            return st;
        }
        case 25: {
            const lfem_body b = pick_body(s, in);
            const uint32_t capacity = in.below(200);
            const uint32_t n = node_count_of(w, b);
            switch (in.below(12)) {
                case 0: {
                    name = "body_get_node/tet_count/nodes_per_tet";
                    uint32_t out = 0xA5A5A5A5u;
                    const lfem_status st = (capacity % 3 == 0   ? lfem_body_get_node_count
                                            : capacity % 3 == 1 ? lfem_body_get_tet_count
                                                                : lfem_body_get_nodes_per_tet)(w, b, arg(s, 0, &out));
                    if (st != LFEM_OK) expect(out == 0xA5A5A5A5u, "a failed call wrote its output:", name);
                    return st;
                }
                case 1: {
                    name = "body_get_user_data";
                    void* out = &s;
                    const lfem_status st = lfem_body_get_user_data(w, b, arg(s, 0, &out));
                    if (st != LFEM_OK) {
                        expect(out == &s, "a failed call wrote its output:", name);
                        return st;
                    }
                    for (const BodyInfo& info : s.bodies)
                        if (info.epoch == s.epoch && info.handle.index == b.index &&
                            info.handle.generation == b.generation && s.null_arg != 0)
                            expect(out == info.user_data, "the user data is not the one given:", name);
                    return st;
                }
                case 2: {
                    name = "body_get_mass/added_mass";
                    double mass = -1, added = -1;
                    const lfem_status st = lfem_body_get_mass(w, b, arg(s, 0, &mass));
                    if (st != LFEM_OK) return st;
                    const lfem_status st2 = lfem_body_get_added_mass(w, b, arg(s, 1, &added));
                    if (st2 != LFEM_OK) return st2;
                    expect(std::isfinite(mass) && added >= 0 && added <= mass * (1 + 1e-12) + 1e-300,
                           "mass or added mass out of range:", name);
                    return st2;
                }
                case 3: {
                    name = "body_get_inversion";
                    uint32_t inverted = 0xA5A5A5A5u;
                    double j = -7, for_ = -7;
                    const lfem_status st =
                        lfem_body_get_inversion(w, b, capacity & 1 ? nullptr : &inverted, capacity & 2 ? nullptr : &j,
                                                capacity & 4 ? nullptr : &for_);
                    if (st != LFEM_OK)
                        expect(inverted == 0xA5A5A5A5u && j == -7 && for_ == -7, "a failed call wrote its output:", name);
                    return st;
                }
                case 4: {
                    name = "body_get_momentum";
                    Buffer<double> lin(3), ang(3);
                    const lfem_status st = lfem_body_get_momentum(w, b, capacity & 1 ? nullptr : lin.data(),
                                                                  capacity & 2 ? nullptr : ang.data());
                    untouched_on_failure(st, lin, name);
                    untouched_on_failure(st, ang, name);
                    return st;
                }
                case 5:
                case 6: {
                    const bool faces = in.below(2);
                    name = faces ? "body_get_boundary_faces" : "body_get_boundary_triangles";
                    uint32_t count = 0xA5A5A5A5u;
                    lfem_status st = (faces ? lfem_body_get_boundary_face_count : lfem_body_get_boundary_triangle_count)(
                        w, b, arg(s, 0, &count));
                    if (st != LFEM_OK) {
                        expect(count == 0xA5A5A5A5u, "a failed call wrote its output:", name);
                        return st;
                    }
                    // Mostly the count's own capacity, else the input's.
                    const uint32_t cap = capacity < 150 ? count : capacity - 150;
                    Buffer<uint32_t> out(6 * std::size_t(cap));
                    st = (faces ? lfem_body_get_boundary_faces : lfem_body_get_boundary_triangles)(
                        w, b, arg(s, 1, out.data()), cap);
                    untouched_on_failure(st, out, name);
                    if (st == LFEM_OK) {
                        uint32_t per_face = 3, per_tet = 0;
                        lfem_body_get_nodes_per_tet(w, b, &per_tet);
                        if (faces && per_tet == 10) per_face = 6;
                        for (uint32_t i = 0; i < per_face * count; ++i)
                            expect(out.v[i] < n, "a boundary node index is out of range:", name);
                    } else {
                        expect(st != LFEM_BUFFER_TOO_SMALL || cap < count, "too small, yet the count fits:", name);
                    }
                    return st;
                }
                case 7: {
                    name = "body_get_von_mises_stress";
                    uint32_t tets = 0;
                    lfem_body_get_tet_count(w, b, &tets);
                    const uint32_t cap = capacity < 150 ? tets : capacity - 150;
                    Buffer<double> out(cap);
                    const lfem_status st = lfem_body_get_von_mises_stress(w, b, arg(s, 0, out.data()), cap);
                    untouched_on_failure(st, out, name);
                    if (st == LFEM_OK)
                        for (uint32_t i = 0; i < tets; ++i)
                            expect(!(out.v[i] < 0), "a negative von Mises stress:", name);
                    return st;
                }
                case 8: {
                    name = "body_get_rotation";
                    Buffer<double> out(9);
                    const lfem_status st = lfem_body_get_rotation(w, b, arg(s, 0, out.data()));
                    untouched_on_failure(st, out, name);
                    return st;
                }
                case 9: {
                    name = "body_find_nodes_in_box";
                    const double lo[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
                    const double hi[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
                    const uint32_t cap = capacity % 50;
                    Buffer<uint32_t> out(cap);
                    uint32_t count = 0xA5A5A5A5u;
                    const lfem_status st = lfem_body_find_nodes_in_box(w, b, arg(s, 0, lo), arg(s, 1, hi),
                                                                       arg(s, 2, out.data()), cap, arg(s, 3, &count));
                    untouched_on_failure(st, out, name);
                    if (st == LFEM_BUFFER_TOO_SMALL) expect(count > cap && count <= n, "a wrong count:", name);
                    if (st == LFEM_OK) {
                        expect(count <= cap && count <= n, "the count exceeds the capacity:", name);
                        for (uint32_t i = 0; i < count; ++i) expect(out.v[i] < n, "a node index out of range:", name);
                    }
                    return st;
                }
                case 10: {
                    name = "body_is_valid";
                    const int valid = lfem_body_is_valid(w, b);
                    expect(valid == 0 || valid == 1, "body_is_valid gave neither 0 nor 1", "");
                    return LFEM_OK;
                }
                default: {
                    name = "body_get_positions(exact capacity)";
                    Buffer<double> out(3 * std::size_t(n));
                    const lfem_status st = lfem_body_get_positions(w, b, arg(s, 0, out.data()), n);
                    untouched_on_failure(st, out, name);
                    return st;
                }
            }
        }
        case 26: {
            switch (in.below(6)) {
                case 0: {
                    name = "world_get_stable_step";
                    double h = -1;
                    const lfem_status st = lfem_world_get_stable_step(w, arg(s, 0, &h));
                    if (st == LFEM_OK) expect(h > 0, "a stable step that is not > 0:", name);
                    else expect(h == -1, "a failed call wrote its output:", name);
                    return st;
                }
                case 1: {
                    name = "world_get_stats";
                    Buffer<lfem_world_stats> out(1);
                    const lfem_status st = lfem_world_get_stats(w, arg(s, 0, out.data()));
                    untouched_on_failure(st, out, name);
                    return st;
                }
                case 2: {
                    name = "world_get_profile";
                    Buffer<lfem_profile> out(1);
                    const lfem_status st = lfem_world_get_profile(w, arg(s, 0, out.data()));
                    untouched_on_failure(st, out, name);
                    return st;
                }
                case 3: {
                    name = "world_reset_profile";
                    const lfem_status st = lfem_world_reset_profile(w);
                    if (st == LFEM_OK) {
                        lfem_profile p;
                        lfem_world_get_profile(w, &p);
                        expect(p.substeps == 0 && p.queries == 0 && p.internal_forces.calls == 0,
                               "the profile was not reset:", name);
                    }
                    return st;
                }
                case 4: {
                    name = "world_get_warning";
                    const uint32_t kind = in.below(6);
                    Buffer<lfem_warning> out(1);
                    const lfem_status st = lfem_world_get_warning(w, lfem_warning_kind(kind), arg(s, 0, out.data()));
                    untouched_on_failure(st, out, name);
                    expect(st != LFEM_OK || kind < LFEM_WARNING_KIND_COUNT, "a warning of no kind was read:", name);
                    return st;
                }
                default: {
                    name = "world_clear_warnings";
                    const lfem_status st = lfem_world_clear_warnings(w);
                    if (st == LFEM_OK) {
                        lfem_warning warning;
                        lfem_world_get_warning(w, LFEM_WARNING_FALLEN_IN, &warning);
                        expect(warning.count == 0, "the warnings were not cleared:", name);
                    }
                    return st;
                }
            }
        }
        case 27: {
            // Calls without a world: status strings, versions, the NULL objects.
            name = "status/version/null objects";
            const uint32_t status = in.u32() % 12;
            const char* text = lfem_status_string(lfem_status(status));
            expect(text && *text, "lfem_status_string gave nothing", "");
            char version[32];
            std::snprintf(version, sizeof version, "%d.%d.%d", LFEM_VERSION_MAJOR, LFEM_VERSION_MINOR,
                          LFEM_VERSION_PATCH);
            expect(lfem_version() == uint32_t((LFEM_VERSION_MAJOR << 16) | (LFEM_VERSION_MINOR << 8) |
                                              LFEM_VERSION_PATCH) &&
                       std::strcmp(lfem_version_string(), version) == 0,
                   "the version is not the header's", "");
            expect(lfem_last_error() != nullptr, "lfem_last_error gave NULL", "");
            expect(lfem_mesh_get_node_count(nullptr) == 0 && lfem_mesh_get_tet_count(nullptr) == 0 &&
                       lfem_mesh_get_nodes_per_tet(nullptr) == 0 && lfem_mesh_get_positions(nullptr) == nullptr &&
                       lfem_mesh_get_tets(nullptr) == nullptr,
                   "a NULL mesh has content", "");
            lfem_mesh_destroy(nullptr);
            lfem_world_destroy(nullptr);
            lfem_vtk_series_destroy(nullptr);
            lfem_mesh* m = reinterpret_cast<lfem_mesh*>(&s);
            const lfem_status st =
                lfem_mesh_load_gmsh(status & 1 ? nullptr : "/nonexistent-lfem-fuzz/mesh.msh", &m);
            expect(st != LFEM_OK && m == reinterpret_cast<lfem_mesh*>(&s), "a missing mesh file was loaded", "");
            return st;
        }
        default: {
            // Frames of a VTK series in a folder of its own (or in one that does not exist).
            name = "vtk_series_create/write_frame";
            const uint8_t f = in.byte();
            const uint32_t frames = in.below(3);
            char dir[] = "/tmp/lfem_fuzz_vtk_XXXXXX";
            if (!mkdtemp(dir)) return LFEM_OK;
            const std::string pvd = (f & 1 ? std::string("/nonexistent-lfem-fuzz") : std::string(dir)) + "/s.pvd";
            lfem_vtk_series* series = nullptr;
            lfem_status st = lfem_vtk_series_create(arg(s, 0, pvd.c_str()), arg(s, 1, &series));
            for (uint32_t i = 0; st == LFEM_OK && i < frames; ++i) {
                st = lfem_vtk_series_write_frame(arg(s, 2, series), w);
                check(st, name);
                expect(st != LFEM_OK || !(f & 1), "a frame was written into a folder that does not exist", "");
            }
            lfem_vtk_series_destroy(series);
            remove_folder(dir);
            return st;
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Input in(data, size);
    Session s;
    const lfem_world_def def = read_world_def(in);
    const lfem_status created = lfem_world_create(&def, &s.world);
    check(created, "world_create");
    if (created != LFEM_OK) return 0;
    for (int calls = 0; calls < 64 && !in.empty(); ++calls) {
        const std::vector<unsigned char> before = digest(s, s.world);
        const char* name = "";
        s.note.clear();
        const lfem_status st = one_call(s, in, name);
        check(st, name);
        if (verbose)
            std::fprintf(stderr, "%-36s %-22s %s\n", name, lfem_status_string(st),
                         st == LFEM_OK ? s.note.c_str() : lfem_last_error());
        if (st != LFEM_OK && digest(s, s.world) != before) broken("a failed call changed the world:", name);
    }
    digest(s, s.world);
    lfem_world_destroy(s.world);
    return 0;
}
