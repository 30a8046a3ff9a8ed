// libFuzzer target: bytes become a sequence of C API calls on one world (create, bodies, meshes
// with arbitrary numbers, shapes, node constraints and forces, steps with arbitrary dt, queries
// with arbitrary buffers, skins and their reads, rays and boxes, checkpoints, destroy). Checked
// after every call:
// - the status is one of lfem's, and a failure leaves a message;
// - a failed call leaves the world's statistics bit for bit as they were;
// - nothing crashes, leaks or reads out of bounds (the sanitizers watch).
// Sub-step counts are capped (max_substeps) so that a single input cannot run for minutes.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>
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

struct Session {
    lfem_world* world = nullptr;
    std::vector<lfem_body> bodies;  // every handle ever returned, live or stale
};

lfem_body pick_body(Session& s, Input& in) {
    const uint8_t how = in.byte();
    if (how < 220 && !s.bodies.empty()) return s.bodies[in.below(uint32_t(s.bodies.size()))];
    return lfem_body{in.u32() % 8, in.u32()};  // made up: null, stale or foreign
}

std::vector<uint32_t> node_list(Input& in) {
    std::vector<uint32_t> nodes(in.below(6));
    for (uint32_t& n : nodes) n = in.below(40);
    return nodes;
}

lfem_world_stats stats_of(lfem_world* w) {
    lfem_world_stats st;
    std::memset(&st, 0, sizeof st);
    if (w && lfem_world_get_stats(w, &st) != LFEM_OK) broken("get_stats failed");
    return st;
}

void check(lfem_status s, const char* call) {
    if (s < LFEM_OK || s > LFEM_UNSUPPORTED) broken("unknown status from", call);
    if (s == LFEM_INTERNAL_ERROR) broken("internal error:", lfem_last_error());
    if (s != LFEM_OK && !*lfem_last_error()) broken("no message after a failed", call);
}

// One call chosen by the input. Returns the status and the call's name.
lfem_status one_call(Session& s, Input& in, const char*& name) {
    lfem_world* w = s.world;
    switch (in.below(19)) {
        case 0: {
            name = "body_create";
            lfem_body_def d = lfem_body_def_default();
            d.type = lfem_body_type(in.below(5));
            d.model = lfem_model(in.below(5));
            d.young_modulus = in.number(1e3, 1e8);
            d.poisson_ratio = in.number(-0.2, 0.5);
            d.density = in.number(10, 2e4);
            d.damping = in.number(0, 10);
            d.friction = in.number(0, 1);
            for (int k = 0; k < 3; ++k) d.linear_velocity[k] = in.number(-10, 10);
            for (int k = 0; k < 3; ++k) d.angular_velocity[k] = in.number(-5, 5);
            d.mask_bits = in.byte() < 128 ? 0xFFFFFFFFu : in.u32();
            lfem_body b{};
            const lfem_status st = lfem_body_create(w, &d, &b);
            if (st == LFEM_OK) s.bodies.push_back(b);
            return st;
        }
        case 1: {
            name = "body_add_mesh(box)";
            const double size[3] = {in.number(0.01, 1), in.number(0.01, 1), in.number(0.01, 1)};
            const uint32_t cells[3] = {1 + in.below(3), 1 + in.below(3), 1 + in.below(3)};
            lfem_mesh* m = nullptr;
            if (lfem_mesh_create_box(size, cells, &m) != LFEM_OK) return LFEM_INVALID_ARGUMENT;
            const double offset[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-0.2, 1)};
            lfem_status st = lfem_mesh_translate(m, offset);
            // A box of one cell comes as 10-node tets: the quadratic bodies' whole path (mesh,
            // steps, contact, checkpoints) without a byte more to read.
            const bool quadratic = cells[0] == 1 && cells[1] == 1 && cells[2] == 1;
            if (quadratic) {
                name = "body_add_quadratic_mesh(box)";
                if (st == LFEM_OK) st = lfem_mesh_make_quadratic(m);
            }
            if (st == LFEM_OK)
                st = (quadratic ? lfem_body_add_quadratic_mesh : lfem_body_add_mesh)(
                    w, pick_body(s, in), lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                    lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m));
            lfem_mesh_destroy(m);
            return st;
        }
        case 2: {
            name = "body_add_mesh(raw)";
            const uint32_t n = in.below(10), t = in.below(6);
            std::vector<double> x(3 * n);
            std::vector<uint32_t> tets(4 * t);
            for (double& v : x) v = in.number(-0.5, 0.5);
            for (uint32_t& v : tets) v = in.below(12);
            return lfem_body_add_mesh(w, pick_body(s, in), x.data(), n, tets.data(), t);
        }
        case 3: {
            name = "body_add_triangle_mesh";
            const uint32_t n = in.below(8), t = in.below(5);
            std::vector<double> x(3 * n);
            std::vector<uint32_t> tris(3 * t);
            for (double& v : x) v = in.number(-1, 1);
            for (uint32_t& v : tris) v = in.below(10);
            return lfem_body_add_triangle_mesh(w, pick_body(s, in), x.data(), n, tris.data(), t);
        }
        case 4: {
            name = "world_step";
            const double dt = in.byte() < 200 ? in.number(1e-5, 0.02) : in.number(-1, 1);
            return lfem_world_step(w, dt);
        }
        case 5: {
            name = "world_query_contacts";
            const uint32_t capacity = uint32_t(in.below(40));
            std::vector<lfem_contact> out(capacity);
            uint32_t count = 0;
            return lfem_world_query_contacts(w, capacity ? out.data() : nullptr, capacity, &count);
        }
        case 6: {
            name = "body_get_positions";
            const uint32_t capacity = in.below(60);
            std::vector<double> out(3 * std::size_t(capacity));
            return lfem_body_get_positions(w, pick_body(s, in), capacity ? out.data() : nullptr,
                                           capacity);
        }
        case 7: {
            name = "body_fix_nodes";
            const std::vector<uint32_t> nodes = node_list(in);
            return lfem_body_fix_nodes(w, pick_body(s, in), nodes.data(), uint32_t(nodes.size()));
        }
        case 8: {
            name = "body_prescribe_node_velocity";
            const std::vector<uint32_t> nodes = node_list(in);
            const double v[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
            return lfem_body_prescribe_node_velocity(w, pick_body(s, in), nodes.data(),
                                                     uint32_t(nodes.size()), v);
        }
        case 9: {
            name = "body_set_node_forces";
            const std::vector<uint32_t> nodes = node_list(in);
            std::vector<double> f(3 * nodes.size());
            for (double& v : f) v = in.number(-100, 100);
            return lfem_body_set_node_forces(w, pick_body(s, in), nodes.data(),
                                             uint32_t(nodes.size()), f.data());
        }
        case 10: {
            name = "body_destroy";
            return lfem_body_destroy(w, pick_body(s, in));
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
            return lfem_body_add_shape(w, pick_body(s, in), &d, NULL);
        }
        case 12: {
            name = "world_set_gravity/time_step";
            if (in.byte() & 1) {
                const double g[3] = {in.number(-20, 20), in.number(-20, 20), in.number(-20, 20)};
                return lfem_world_set_gravity(w, g);
            }
            return lfem_world_set_time_step(w, in.byte() < 128 ? 0.0 : in.number(0, 1e-3));
        }
        case 13: {
            name = "body_set_kinematic_velocity";
            const double lin[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
            const double ang[3] = {in.number(-1, 1), in.number(-1, 1), in.number(-1, 1)};
            return lfem_body_set_kinematic_velocity(w, pick_body(s, in), lin, ang);
        }
        case 14: {
            name = "world_save/load";
            char path[] = "/tmp/lfem_fuzz_XXXXXX";
            const int fd = mkstemp(path);
            if (fd < 0) return LFEM_OK;
            close(fd);
            lfem_status st = lfem_world_save(w, path);
            if (st == LFEM_OK) {
                lfem_world* loaded = nullptr;
                st = lfem_world_load(path, &loaded);
                if (st == LFEM_OK) {
                    // Continue with the loaded world: its handles are the same.
                    lfem_world_destroy(s.world);
                    s.world = loaded;
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
            uint32_t index = 0;
            return lfem_body_add_skin(w, pick_body(s, in), x.data(), n, tris.data(), t, &index);
        }
        case 16: {
            name = "body_get_skin_vertices(_f32)/triangles";
            const lfem_body b = pick_body(s, in);
            const uint32_t skin = in.below(3), capacity = in.below(20);
            const uint32_t stride = in.below(8), normal_stride = in.below(8);
            std::vector<double> p(3 * std::size_t(capacity)), nrm(3 * std::size_t(capacity));
            std::vector<float> f(8 * std::size_t(capacity) + 8);
            std::vector<uint32_t> tri(3 * std::size_t(capacity));
            switch (in.below(3)) {
                case 0: return lfem_body_get_skin_vertices(w, b, skin, capacity ? p.data() : nullptr,
                                                           in.byte() & 1 ? nrm.data() : nullptr, capacity);
                case 1: return lfem_body_get_skin_vertices_f32(w, b, skin, f.data(), stride,
                                                               in.byte() & 1 ? f.data() + 3 : nullptr,
                                                               normal_stride, std::min(capacity, 1u + capacity / 8));
                default: return lfem_body_get_skin_triangles(w, b, skin, capacity ? tri.data() : nullptr, capacity);
            }
        }
        case 17: {
            name = "world_cast_ray(_all)/overlap_box";
            const double a[3] = {in.number(-2, 2), in.number(-2, 2), in.number(-2, 2)};
            const double b[3] = {in.number(-2, 2), in.number(-2, 2), in.number(-2, 2)};
            lfem_query_filter f = lfem_query_filter_default();
            if (in.byte() < 64) f.category_bits = in.u32(), f.mask_bits = in.u32();
            const uint32_t capacity = in.below(8);
            std::vector<lfem_ray_hit> hits(capacity);
            std::vector<lfem_body> found(capacity);
            uint32_t count = 0;
            switch (in.below(3)) {
                case 0: {
                    int hit = 0;
                    return lfem_world_cast_ray(w, a, b, in.number(0, 5), f, &hits.emplace_back(), &hit);
                }
                case 1: return lfem_world_cast_ray_all(w, a, b, in.number(0, 5), f,
                                                       capacity ? hits.data() : nullptr, capacity, &count);
                default: return lfem_world_overlap_box(w, a, b, f, capacity ? found.data() : nullptr, capacity,
                                                       &count);
            }
        }
        default: {
            name = "body_release_nodes";
            const std::vector<uint32_t> nodes = node_list(in);
            return lfem_body_release_nodes(w, pick_body(s, in), nodes.data(), uint32_t(nodes.size()));
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Input in(data, size);
    Session s;
    lfem_world_def def = lfem_world_def_default();
    def.max_substeps = 1 + in.below(64);
    def.contact_iterations = 1 + in.below(50);
    def.step_safety = in.number(0.05, 0.99);
    if (lfem_world_create(&def, &s.world) != LFEM_OK) {
        check(LFEM_INVALID_ARGUMENT, "world_create");
        return 0;
    }
    // LFEM_FUZZ_VERBOSE=1 prints each call (to see what an input does, e.g. a crash's).
    static const bool verbose = std::getenv("LFEM_FUZZ_VERBOSE") != nullptr;
    for (int calls = 0; calls < 64 && !in.empty(); ++calls) {
        const lfem_world_stats before = stats_of(s.world);
        const char* name = "";
        const lfem_status st = one_call(s, in, name);
        check(st, name);
        if (verbose)
            std::fprintf(stderr, "%-32s %-22s %s\n", name, lfem_status_string(st),
                         st == LFEM_OK ? "" : lfem_last_error());
        if (st != LFEM_OK) {
            const lfem_world_stats after = stats_of(s.world);
            if (std::memcmp(&before, &after, sizeof before) != 0)
                broken("a failed call changed the world's statistics:", name);
        }
    }
    lfem_world_destroy(s.world);
    return 0;
}
