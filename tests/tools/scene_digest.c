/* scene_digest: runs a fixed set of scenes through the public API and prints, per scene, a
 * 64-bit digest (FNV-1a) of everything a caller can read back: positions, velocities, von
 * Mises stresses, the statistics and the contact list, bit for bit. A change meant to leave the
 * physics alone (a restructuring, a faster loop) must leave every line unchanged: run it before
 * and after and compare (`diff`). The scenes cover every body type and material model, the
 * rigid shapes, fixed and prescribed nodes, node forces, a triangle-mesh floor, the
 * side-by-side and on-pool loops on 1 to 3 threads, the retry of a call whose body stiffened,
 * initial overlaps, a checkpoint round trip, bodies of 10-node tets and a pile whose contact
 * group is split for the threads.
 *
 *   scene_digest [scene-name]      (all scenes when no name is given)
 * Each line: the physics digest, the profile's counts, and the events of every call.
 *   scene_digest --queries [name]  the same, casting rays and overlapping boxes after every
 *                                  call, with a digest of their answers: the physics and
 *                                  profile digests must not change
 *   scene_digest --check-queries   runs each scene with and without the queries and fails when
 *                                  a digest differs, or the answers differ between thread counts
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "lfem.h"

/* Two digests: of the physics (everything but the profile) and of the profile's counts, which
 * a change of how the work is done (fewer shape queries, say) may alter while the physics
 * stays bitwise the same. */
static uint64_t g_hash, g_profile_hash;
/* The events of every call (lfem_world_get_events), digested apart so that the physics digests
 * stay comparable with runs from before events were digested. */
static uint64_t g_event_hash;

static void hash_into(uint64_t* h, const void* p, size_t n) {
    const unsigned char* c = (const unsigned char*)p;
    for (size_t i = 0; i < n; ++i) {
        *h ^= c[i];
        *h *= 1099511628211ull;
    }
}

static void hash_bytes(const void* p, size_t n) { hash_into(&g_hash, p, n); }

/* With --queries: after every call, rays and boxes through the scene, their answers digested
 * apart (a query is a read: the other digests must stay as they are without it). */
static int g_queries;
static uint64_t g_query_hash;

static void check(lfem_status s, const char* what) {
    if (s != LFEM_OK) {
        fprintf(stderr, "scene_digest: %s: %s (%s)\n", what, lfem_status_string(s), lfem_last_error());
        exit(1);
    }
}

static lfem_world* make_world(uint32_t threads) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    lfem_world* w = NULL;
    check(lfem_world_create(&wd, &w), "world");
    return w;
}

static lfem_body add_box(lfem_world* w, const lfem_body_def* def, double sx, double sy, double sz,
                         uint32_t nx, uint32_t ny, uint32_t nz, double ox, double oy, double oz) {
    const double size[3] = {sx, sy, sz};
    const uint32_t cells[3] = {nx, ny, nz};
    const double offset[3] = {ox, oy, oz};
    lfem_mesh* m = NULL;
    check(lfem_mesh_create_box(size, cells, &m), "box mesh");
    check(lfem_mesh_translate(m, offset), "translate");
    lfem_body b;
    check(lfem_body_create(w, def, &b), "body");
    check(lfem_body_add_mesh(w, b, lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                             lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)),
          "add mesh");
    lfem_mesh_destroy(m);
    return b;
}

static lfem_body static_floor(lfem_world* w) {
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    return add_box(w, &f, 0.8, 0.8, 0.1, 4, 4, 1, -0.4, -0.4, -0.1);
}

/* Everything readable about the world and its bodies goes into the digest. */
static void digest_world(lfem_world* w, const lfem_body* bodies, int count) {
    lfem_world_stats st;
    check(lfem_world_get_stats(w, &st), "stats");
    /* Fields added to the stats later (mass scaling's added mass) enter only when they are not
     * zero, so that digests stay comparable across the change that added them. */
    hash_bytes(&st, offsetof(lfem_world_stats, added_mass));
    if (st.added_mass != 0.0) hash_bytes(&st.added_mass, sizeof st.added_mass);
    if (getenv("SCENE_DIGEST_VERBOSE"))
        fprintf(stderr, "  t %.4f s, %llu sub-steps (%u last call), %u contacts, penetration %.3g m, energy error %.3g J\n",
                st.time, (unsigned long long)st.steps, st.substeps_last_call, st.contact_count,
                st.max_penetration, st.energy_error);
    for (int i = 0; i < count; ++i) {
        uint32_t n = 0, t = 0;
        check(lfem_body_get_node_count(w, bodies[i], &n), "node count");
        check(lfem_body_get_tet_count(w, bodies[i], &t), "tet count");
        double* x = malloc(sizeof(double) * 3 * (n + 1));
        double* v = malloc(sizeof(double) * 3 * (n + 1));
        double* vm = malloc(sizeof(double) * (t + 1));
        check(lfem_body_get_positions(w, bodies[i], x, n), "positions");
        check(lfem_body_get_velocities(w, bodies[i], v, n), "velocities");
        hash_bytes(x, sizeof(double) * 3 * n);
        hash_bytes(v, sizeof(double) * 3 * n);
        if (t) {
            check(lfem_body_get_von_mises_stress(w, bodies[i], vm, t), "stress");
            hash_bytes(vm, sizeof(double) * t);
        }
        double R[9], P[3], L[3];
        check(lfem_body_get_rotation(w, bodies[i], R), "rotation");
        check(lfem_body_get_momentum(w, bodies[i], P, L), "momentum");
        hash_bytes(R, sizeof R);
        hash_bytes(P, sizeof P);
        hash_bytes(L, sizeof L);
        free(x);
        free(v);
        free(vm);
    }
    uint32_t nc = 0;
    (void)lfem_world_query_contacts(w, NULL, 0, &nc); /* the count, whatever the status */
    lfem_contact* c = malloc(sizeof(lfem_contact) * (nc + 1));
    check(lfem_world_query_contacts(w, c, nc, &nc), "contacts");
    for (uint32_t i = 0; i < nc; ++i) c[i].body_a.generation = c[i].body_b.generation = 0;
    hash_bytes(c, sizeof(lfem_contact) * nc);
    free(c);
    lfem_profile p;
    check(lfem_world_get_profile(w, &p), "profile");
    const uint64_t calls[] = {p.substeps, p.internal_forces.calls, p.predictor.calls,
                              p.kinematic_motion.calls, p.broad_phase.calls, p.narrow_phase.calls,
                              p.shape_queries.calls, p.shape_tests, p.ccd_queries,
                              p.normal_solve.calls, p.friction.calls, p.global_rotation.calls,
                              p.commit.calls};
    hash_into(&g_profile_hash, calls, sizeof calls);
}

/* Rays from a ring 3 m around the scenes towards points near the origin, rays straight down
 * on a grid, boxes about the origin; every body's skins read. Handles' generations are left
 * out of the digest (they come from a process-wide counter). */
static void ask_queries(lfem_world* w) {
    const lfem_query_filter f = lfem_query_filter_default();
    lfem_ray_hit hits[256];
    for (int i = 0; i < 24; ++i) {
        const double a = 0.2618 * i, o[3] = {3.0 * cos(a), 3.0 * sin(a), 0.05 * (i % 5)};
        const double down[3] = {-0.4 + 0.1 * (i % 9), -0.3 + 0.1 * (i / 9), 2.0};
        const double d[3] = {0.1 * (i % 3) - o[0], 0.07 * (i % 4) - o[1], -0.02 * i - o[2]};
        const double dz[3] = {0.001 * i, 0.0, -1.0};
        uint32_t n = 0;
        check(lfem_world_cast_ray_all(w, o, d, HUGE_VAL, f, hits, 256, &n), "cast_ray_all");
        for (uint32_t k = 0; k < n; ++k) hits[k].body.generation = 0;
        hash_into(&g_query_hash, hits, sizeof(lfem_ray_hit) * n);
        int hit = 0;
        lfem_ray_hit one;
        memset(&one, 0, sizeof one);
        check(lfem_world_cast_ray(w, down, dz, 5.0, f, &one, &hit), "cast_ray");
        one.body.generation = 0;
        hash_into(&g_query_hash, &hit, sizeof hit);
        hash_into(&g_query_hash, &one, sizeof one);
    }
    for (int i = 0; i < 6; ++i) {
        const double r = 0.02 + 0.1 * i, lo[3] = {-r, -r, -0.3 * r}, hi[3] = {r, 0.5 * r, r};
        lfem_body found[64];
        uint32_t n = 0;
        check(lfem_world_overlap_box(w, lo, hi, f, found, 64, &n), "overlap_box");
        for (uint32_t k = 0; k < n; ++k) hash_into(&g_query_hash, &found[k].index, sizeof found[k].index);
    }
}

/* The call's events, handles' generations left out (a process-wide counter). */
static void digest_events(lfem_world* w) {
    uint32_t n = 0;
    (void)lfem_world_get_events(w, NULL, 0, &n); /* the count, whatever the status */
    lfem_event* e = malloc(sizeof(lfem_event) * (n + 1));
    check(lfem_world_get_events(w, e, n, &n), "events");
    for (uint32_t i = 0; i < n; ++i)
        e[i].body_a.generation = e[i].body_b.generation = e[i].attachment.generation = 0;
    hash_into(&g_event_hash, e, sizeof(lfem_event) * n);
    if (getenv("SCENE_DIGEST_VERBOSE"))
        for (uint32_t i = 0; i < n; ++i)
            fprintf(stderr, "  event %d: bodies %u, %u, impulse %.6g N s, force %.6g N\n", (int)e[i].type,
                    e[i].body_a.index, e[i].body_b.index, e[i].normal_impulse, e[i].max_force);
    free(e);
}

static void step(lfem_world* w, int calls, double dt) {
    for (int i = 0; i < calls; ++i) {
        check(lfem_world_step(w, dt), "step");
        digest_events(w);
        if (g_queries) ask_queries(w);
    }
}

/* A spinning soft cube of each model dropped on a static box-mesh floor, with friction and
 * damping. */
static void scene_models(uint32_t threads, lfem_model model) {
    lfem_world* w = make_world(threads);
    lfem_body b[2];
    b[0] = static_floor(w);
    lfem_body_def d = lfem_body_def_default();
    d.model = model;
    d.young_modulus = 2e5;
    d.damping = 2.0;
    d.angular_velocity[2] = 3.0;
    d.linear_velocity[0] = 0.3;
    b[1] = add_box(w, &d, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.01);
    step(w, 40, 1.0 / 120.0);
    digest_world(w, b, 2);
    lfem_world_destroy(w);
}

/* Five comparable bodies side by side (the side-by-side loop on several threads), a stack. */
static void scene_many(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[6];
    b[0] = static_floor(w);
    for (int i = 0; i < 5; ++i) {
        lfem_body_def d = lfem_body_def_default();
        d.model = (lfem_model)(i % 4);
        d.young_modulus = 1e5 * (1 + i);
        d.friction = 0.3 + 0.1 * i;
        b[i + 1] = add_box(w, &d, 0.08, 0.08, 0.08, 2 + i % 2, 2, 2, -0.3 + 0.15 * i, -0.04,
                           0.005 + 0.09 * (i % 2));
    }
    step(w, 30, 1.0 / 100.0);
    digest_world(w, b, 6);
    lfem_world_destroy(w);
}

/* A body of over 32768 tets (its own loops on the pool) and a small one on it. */
static void scene_big(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[3];
    b[0] = static_floor(w);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    d.young_modulus = 5e5;
    b[1] = add_box(w, &d, 0.6, 0.6, 0.1, 24, 24, 10, -0.3, -0.3, 0.0);
    d.model = LFEM_MODEL_COROTATIONAL;
    b[2] = add_box(w, &d, 0.1, 0.1, 0.1, 3, 3, 3, -0.05, -0.05, 0.1005);
    step(w, 6, 1.0 / 200.0);
    digest_world(w, b, 3);
    lfem_world_destroy(w);
}

/* A kinematic body with every rigid shape, moving and turning, under soft blocks. */
static void scene_shapes(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[7];
    lfem_body_def k = lfem_body_def_default();
    k.type = LFEM_BODY_KINEMATIC;
    k.linear_velocity[0] = 0.05;
    k.angular_velocity[2] = 0.2;
    check(lfem_body_create(w, &k, &b[0]), "kinematic");
    lfem_shape_def s = lfem_shape_def_default();
    s.type = LFEM_SHAPE_PLANE;
    s.center[2] = -0.2;
    check(lfem_body_add_shape(w, b[0], &s, NULL), "plane");
    const double hull[] = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.1, 0.1, 0.08};
    const lfem_shape_type types[4] = {LFEM_SHAPE_BOX, LFEM_SHAPE_SPHERE, LFEM_SHAPE_CAPSULE,
                                      LFEM_SHAPE_CONVEX_HULL};
    for (int i = 0; i < 4; ++i) {
        s = lfem_shape_def_default();
        s.type = types[i];
        s.center[0] = -0.45 + 0.3 * i;
        s.center[2] = -0.1;
        s.half_extents[0] = s.half_extents[1] = s.half_extents[2] = 0.08;
        s.radius = 0.08;
        s.half_length = 0.05;
        s.rotation[0] = cos(0.2);
        s.rotation[1] = sin(0.2);
        s.points = hull;
        s.point_count = 5;
        const lfem_status added = lfem_body_add_shape(w, b[0], &s, NULL);
        /* A build without libccd has no hulls (tests/configs.sh): that cube falls on the plane. */
        if (!(types[i] == LFEM_SHAPE_CONVEX_HULL && added == LFEM_UNSUPPORTED)) check(added, "shape");
        lfem_body_def d = lfem_body_def_default();
        d.model = (lfem_model)i;
        d.young_modulus = 3e5;
        b[i + 1] = add_box(w, &d, 0.06, 0.06, 0.06, 2, 2, 2, s.center[0] - 0.03, -0.03, 0.005);
    }
    lfem_body_def d = lfem_body_def_default();
    b[5] = add_box(w, &d, 0.1, 0.1, 0.05, 2, 2, 1, 0.6, -0.05, -0.19);
    d.type = LFEM_BODY_RIGID;
    d.density = 3000;
    b[6] = add_box(w, &d, 0.05, 0.05, 0.05, 1, 1, 1, 0.62, -0.03, -0.13);
    step(w, 40, 1.0 / 100.0);
    digest_world(w, b, 7);
    lfem_world_destroy(w);
}

/* A rigid box dropped on a free soft slab resting on a static triangle surface; node forces,
 * set velocities. */
static void scene_rigid_terrain(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[3];
    lfem_body_def t = lfem_body_def_default();
    t.type = LFEM_BODY_STATIC;
    check(lfem_body_create(w, &t, &b[0]), "terrain");
    enum { G = 6 };
    double p[3 * (G + 1) * (G + 1)];
    uint32_t tri[6 * G * G];
    for (int j = 0; j <= G; ++j)
        for (int i = 0; i <= G; ++i) {
            double* q = &p[3 * (j * (G + 1) + i)];
            q[0] = -0.5 + i / (double)G, q[1] = -0.5 + j / (double)G;
            q[2] = 0.01 * sin(3.0 * q[0]) * cos(2.0 * q[1]);
        }
    for (int j = 0, k = 0; j < G; ++j)
        for (int i = 0; i < G; ++i) {
            const uint32_t a = j * (G + 1) + i, bb = a + 1, c = a + G + 1, e = c + 1;
            tri[k++] = a, tri[k++] = bb, tri[k++] = e;
            tri[k++] = a, tri[k++] = e, tri[k++] = c;
        }
    check(lfem_body_add_triangle_mesh(w, b[0], p, (G + 1) * (G + 1), tri, 2 * G * G), "triangles");
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    d.young_modulus = 1e5;
    d.damping = 1.0;
    b[1] = add_box(w, &d, 0.3, 0.3, 0.05, 4, 4, 1, -0.15, -0.15, 0.03);
    d.type = LFEM_BODY_RIGID;
    d.density = 3000;
    d.linear_velocity[2] = -1.0;
    d.angular_velocity[1] = 1.0;
    b[2] = add_box(w, &d, 0.06, 0.06, 0.06, 1, 1, 1, -0.03, -0.03, 0.1);
    const uint32_t nodes[2] = {0, 3};
    const double forces[6] = {0, 0, -0.5, 0.2, 0, -0.5};
    check(lfem_body_set_node_forces(w, b[1], nodes, 2, forces), "node forces");
    step(w, 20, 1.0 / 100.0);
    uint32_t n = 0;
    check(lfem_body_get_node_count(w, b[1], &n), "count");
    double* v = malloc(sizeof(double) * 3 * n);
    check(lfem_body_get_velocities(w, b[1], v, n), "velocities");
    for (uint32_t i = 0; i < 3 * n; ++i) v[i] *= 0.5;
    check(lfem_body_set_velocities(w, b[1], v, n), "set velocities");
    free(v);
    step(w, 20, 1.0 / 100.0);
    digest_world(w, b, 3);
    lfem_world_destroy(w);
}

/* A clamped paper-model beam with a prescribed end and node forces, changing gravity and a
 * fixed time step. */
static void scene_supports(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[1];
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 5e6;
    d.angular_velocity[0] = 0.5;
    b[0] = add_box(w, &d, 0.5, 0.05, 0.05, 10, 1, 1, 0, 0, 0);
    const double lo[3] = {-1e-6, -1, -1}, hi[3] = {1e-6, 1, 1};
    uint32_t clamped[16], nc = 0;
    check(lfem_body_find_nodes_in_box(w, b[0], lo, hi, clamped, 16, &nc), "find");
    check(lfem_body_fix_nodes(w, b[0], clamped, nc), "fix");
    const double lo2[3] = {0.5 - 1e-6, -1, -1}, hi2[3] = {0.5 + 1e-6, 1, 1};
    uint32_t tip[16], nt = 0;
    check(lfem_body_find_nodes_in_box(w, b[0], lo2, hi2, tip, 16, &nt), "find tip");
    const double vel[3] = {0, 0, 0.01};
    check(lfem_body_prescribe_node_velocity(w, b[0], tip, 1, vel), "prescribe");
    double f[48];
    for (uint32_t i = 0; i < 3 * nt; ++i) f[i] = (i % 3 == 1) ? 0.3 : 0.0;
    check(lfem_body_set_node_forces(w, b[0], tip + 1, nt - 1, f), "forces");
    step(w, 10, 0.01);
    check(lfem_body_release_nodes(w, b[0], tip, 1), "release");
    const double g[3] = {0.5, 0, -9.81};
    check(lfem_world_set_gravity(w, g), "gravity");
    double limit = 0;
    check(lfem_world_get_stable_step(w, &limit), "stable step");
    check(lfem_world_set_time_step(w, 0.5 * limit), "time step");
    step(w, 5, 0.003);
    digest_world(w, b, 1);
    lfem_world_destroy(w);
}

/* A neo-Hookean cube hit at its wave speed: calls redone with more sub-steps. */
static void scene_crush(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[2];
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    f.friction = 0;
    b[0] = add_box(w, &f, 0.4, 0.4, 0.1, 2, 2, 1, -0.2, -0.2, -0.1);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    d.young_modulus = 1e7;
    d.friction = 0;
    d.linear_velocity[2] = -100.0;
    b[1] = add_box(w, &d, 0.1, 0.1, 0.1, 6, 6, 6, -0.05, -0.05, 0.0005);
    const double g[3] = {0, 0, 0};
    check(lfem_world_set_gravity(w, g), "gravity");
    step(w, 10, 2e-4);
    digest_world(w, b, 2);
    lfem_world_destroy(w);
}

/* The world saved to path and loaded again (the old one destroyed), when the build has file
 * I/O; else the world itself. */
static lfem_world* round_trip(lfem_world* w, const char* name) {
    /* The file's name carries the process id: ctest runs three scene_digest tests side by
     * side in one folder, and with one shared name one run's save replaced the file another
     * was reading ("truncated", "cannot rename"). */
    char path[256];
    snprintf(path, sizeof path, "%s.%ld", name, (long)getpid());
    const lfem_status s = lfem_world_save(w, path);
    if (s == LFEM_UNSUPPORTED) return w;
    check(s, "save");
    lfem_world* loaded = NULL;
    check(lfem_world_load(path, &loaded), "load");
    remove(path);
    lfem_world_destroy(w);
    return loaded;
}

/* Two blocks created 0.3 of a cell into each other, separating; then a checkpoint round trip
 * and more steps from the loaded world. */
static void scene_overlap_checkpoint(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[2];
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    const double g[3] = {0, 0, 0};
    check(lfem_world_set_gravity(w, g), "gravity");
    b[0] = add_box(w, &d, 0.1, 0.1, 0.1, 4, 4, 4, 0, 0, 0);
    d.model = LFEM_MODEL_PAPER;
    b[1] = add_box(w, &d, 0.1, 0.1, 0.1, 4, 4, 4, 0.0925, 0.01, 0.0);
    step(w, 10, 0.002);
    w = round_trip(w, "scene_digest_checkpoint.bin");
    step(w, 10, 0.002);
    digest_world(w, b, 2);
    lfem_world_destroy(w);
}

/* Bodies of 10-node tets (lfem_mesh_make_quadratic): a corotational block on a neo-Hookean one
 * on a static quadratic floor, with friction, damping and a spin; then a checkpoint round trip
 * when the build has file I/O. */
static void scene_quadratic(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[3];
    const double sizes[3][3] = {{0.8, 0.8, 0.1}, {0.12, 0.12, 0.06}, {0.06, 0.06, 0.06}};
    const double offsets[3][3] = {{-0.4, -0.4, -0.1}, {-0.06, -0.06, 0.001}, {-0.03, -0.02, 0.063}};
    const uint32_t cells[3][3] = {{2, 2, 1}, {3, 3, 2}, {2, 2, 2}};
    for (int i = 0; i < 3; ++i) {
        lfem_body_def d = lfem_body_def_default();
        if (i == 0) d.type = LFEM_BODY_STATIC;
        d.model = i == 1 ? LFEM_MODEL_NEO_HOOKEAN : LFEM_MODEL_COROTATIONAL;
        d.young_modulus = 3e5;
        d.damping = 1.0;
        d.angular_velocity[2] = i == 2 ? 4.0 : 0.0;
        lfem_mesh* m = NULL;
        check(lfem_mesh_create_box(sizes[i], cells[i], &m), "box mesh");
        check(lfem_mesh_translate(m, offsets[i]), "translate");
        check(lfem_mesh_make_quadratic(m), "make quadratic");
        check(lfem_body_create(w, &d, &b[i]), "body");
        check(lfem_body_add_quadratic_mesh(w, b[i], lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                                           lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)),
              "add quadratic mesh");
        lfem_mesh_destroy(m);
    }
    step(w, 8, 1.0 / 200.0);
    w = round_trip(w, "scene_digest_quadratic.ckpt");
    step(w, 8, 1.0 / 200.0);
    digest_world(w, b, 3);
    uint32_t faces = 0;
    check(lfem_body_get_boundary_face_count(w, b[1], &faces), "face count");
    uint32_t* face = malloc(sizeof(uint32_t) * 6 * (faces + 1));
    check(lfem_body_get_boundary_faces(w, b[1], face, faces), "faces");
    hash_bytes(face, sizeof(uint32_t) * 6 * faces);
    free(face);
    lfem_world_destroy(w);
}

/* What a game does between frames, with sleeping on: soft cubes dropped on a floor and on each
 * other, one held by its top nodes to a frame the caller moves, one hanging from a rigid box by
 * an attachment that breaks; velocities set and node forces applied between calls, a sleeper
 * woken, a touching body destroyed. The events of every call enter their own digest. */
static void scene_game(uint32_t threads) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.enable_sleep = 1;
    wd.sleep_time = 0.1;
    lfem_world* w = NULL;
    check(lfem_world_create(&wd, &w), "world");
    lfem_body b[7];
    b[0] = static_floor(w);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 2e5;
    d.damping = 10.0;
    d.model = LFEM_MODEL_COROTATIONAL;
    b[1] = add_box(w, &d, 0.08, 0.08, 0.08, 2, 2, 2, -0.3, -0.04, 0.002);
    b[2] = add_box(w, &d, 0.08, 0.08, 0.08, 2, 2, 2, -0.29, -0.03, 0.09);
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    b[3] = add_box(w, &d, 0.08, 0.08, 0.08, 2, 2, 2, 0.0, -0.04, 0.2);
    d.model = LFEM_MODEL_PAPER;
    b[4] = add_box(w, &d, 0.06, 0.06, 0.06, 2, 2, 2, 0.2, -0.03, 0.15);
    lfem_body_def r = lfem_body_def_default();
    r.type = LFEM_BODY_RIGID;
    r.density = 800;
    b[5] = add_box(w, &r, 0.05, 0.05, 0.05, 1, 1, 1, 0.2, -0.025, 0.25);
    d.model = LFEM_MODEL_COROTATIONAL;
    b[6] = add_box(w, &d, 0.05, 0.05, 0.05, 2, 2, 2, 0.3, -0.025, 0.1);
    /* The neo-Hookean cube held by its top nodes to the caller's frame. */
    const double lo[3] = {-1, -1, 0.279}, hi[3] = {1, 1, 1};
    uint32_t top[32], n_top = 0;
    check(lfem_body_find_nodes_in_box(w, b[3], lo, hi, top, 32, &n_top), "top nodes");
    lfem_attachment_def ad = lfem_attachment_def_default();
    ad.body = b[3];
    ad.nodes = top;
    ad.node_count = n_top;
    lfem_attachment held;
    check(lfem_attachment_create(w, &ad, &held), "attach to frame");
    /* The paper cube's top nodes to the rigid box, breaking once it pulls hard. */
    const double lo2[3] = {-1, -1, 0.209};
    check(lfem_body_find_nodes_in_box(w, b[4], lo2, hi, top, 32, &n_top), "top nodes");
    ad = lfem_attachment_def_default();
    ad.body = b[4];
    ad.target = b[5];
    ad.nodes = top;
    ad.node_count = n_top;
    ad.break_force = 2.0;
    lfem_attachment hung;
    check(lfem_attachment_create(w, &ad, &hung), "attach to rigid");
    int woken = 0;
    for (int call = 0; call < 60; ++call) {
        const double frame[7] = {0.001 * call, 0.0, 0.0, cos(0.01 * call), 0.0, 0.0, sin(0.01 * call)};
        check(lfem_attachment_set_frame(w, held, frame), "frame");
        if (call == 10) {
            uint32_t n = 0;
            check(lfem_body_get_node_count(w, b[6], &n), "nodes");
            double* v = malloc(sizeof(double) * 3 * n);
            for (uint32_t i = 0; i < n; ++i) v[3 * i] = -0.5, v[3 * i + 1] = 0.1, v[3 * i + 2] = 0.2;
            check(lfem_body_set_velocities(w, b[6], v, n), "set velocities");
            free(v);
        }
        if (call == 20) {
            const uint32_t nodes[2] = {0, 1};
            const double f[6] = {0.5, 0, 1, 0, 0.5, 1};
            check(lfem_body_set_node_forces(w, b[1], nodes, 2, f), "node forces");
        }
        if (call == 30) check(lfem_body_clear_node_forces(w, b[1]), "clear forces");
        if (call >= 40 && !woken && lfem_body_is_awake(w, b[2]) == 0) {  /* once it has fallen asleep */
            check(lfem_body_wake(w, b[2]), "wake");
            woken = 1;
        }
        if (call == 50) check(lfem_body_destroy(w, b[6]), "destroy");
        step(w, 1, 1.0 / 60.0);
        for (int i = 0; i < 7; ++i) {
            const int awake = lfem_body_is_awake(w, b[i]);
            hash_into(&g_event_hash, &awake, sizeof awake);
        }
        double force[3];
        check(lfem_attachment_get_force(w, held, force), "force");
        hash_bytes(force, sizeof force);
    }
    digest_world(w, b, 6);
    lfem_world_destroy(w);
}

/* A pile: two layers of 4 x 4 soft cubes with friction, one contact group big enough to be
 * split for the threads (src/contact/group_partition.h: its parts' pairs and the pairs between
 * parts in coloured phases), landing and coming to rest. */
static void scene_pile(uint32_t threads) {
    lfem_world* w = make_world(threads);
    lfem_body b[33];
    b[0] = static_floor(w);
    lfem_body_def d = lfem_body_def_default();
    d.young_modulus = 1e5;
    d.poisson_ratio = 0.45;
    d.density = 1100;
    d.damping = 5.0;
    d.friction = 0.5;
    for (int i = 0; i < 32; ++i) {
        const int layer = i / 16, k = i % 16;
        b[i + 1] = add_box(w, &d, 0.1, 0.1, 0.1, 3, 3, 3, 0.11 * (k % 4) - 0.22 + 0.02 * layer,
                           0.11 * (k / 4) - 0.22 + 0.015 * layer, 0.001 + 0.102 * layer);
    }
    step(w, 24, 1.0 / 60.0);
    digest_world(w, b, 33);
    lfem_world_destroy(w);
}

struct scene {
    const char* name;
    void (*run)(uint32_t);
};

static void models_paper(uint32_t t) { scene_models(t, LFEM_MODEL_PAPER); }
static void models_corotational(uint32_t t) { scene_models(t, LFEM_MODEL_COROTATIONAL); }
static void models_neo_hookean(uint32_t t) { scene_models(t, LFEM_MODEL_NEO_HOOKEAN); }
static void models_linear(uint32_t t) { scene_models(t, LFEM_MODEL_LINEAR); }

static const struct scene scenes[] = {
    {"paper", models_paper},         {"corotational", models_corotational},
    {"neo_hookean", models_neo_hookean}, {"linear", models_linear},
    {"many", scene_many},            {"big", scene_big},
    {"shapes", scene_shapes},        {"rigid_terrain", scene_rigid_terrain},
    {"supports", scene_supports},    {"crush", scene_crush},
    {"overlap_checkpoint", scene_overlap_checkpoint},
    {"quadratic", scene_quadratic},  {"game", scene_game},
    {"pile", scene_pile},
};

/* One run of a scene; the digests in *physics, *profile, *events and *queries. */
static void run_scene(size_t i, uint32_t threads, int queries, uint64_t* physics, uint64_t* profile,
                      uint64_t* events, uint64_t* answers) {
    g_hash = g_profile_hash = g_query_hash = g_event_hash = 1469598103934665603ull;
    g_queries = queries;
    scenes[i].run(threads);
    *physics = g_hash, *profile = g_profile_hash, *events = g_event_hash, *answers = g_query_hash;
}

/* Exits 1 when a scene's digest depends on the thread count (results must not) or, with
 * --check-queries, on whether queries were made; 2 for an unknown scene name. */
int main(int argc, char** argv) {
    int queries = 0, check_queries = 0, arg = 1;
    if (argc > arg && strcmp(argv[arg], "--queries") == 0) queries = 1, ++arg;
    else if (argc > arg && strcmp(argv[arg], "--check-queries") == 0) check_queries = 1, ++arg;
    const char* only = argc > arg ? argv[arg] : NULL;
    int differ = 0, ran = 0;
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; ++i) {
        if (only && strcmp(only, scenes[i].name) != 0) continue;
        uint64_t first = 0, first_profile = 0, first_events = 0, first_answers = 0;
        for (uint32_t threads = 1; threads <= 3; ++threads) {
            uint64_t physics, profile, events, answers;
            run_scene(i, threads, queries || check_queries, &physics, &profile, &events, &answers);
            if (threads == 1) first = physics, first_profile = profile, first_events = events, first_answers = answers;
            int different = physics != first || profile != first_profile || events != first_events ||
                            answers != first_answers;
            const char* why = different ? "  DIFFERS from 1 thread" : "";
            if (check_queries) {  /* and the same run without the queries */
                uint64_t quiet, quiet_profile, quiet_events, none;
                run_scene(i, threads, 0, &quiet, &quiet_profile, &quiet_events, &none);
                if (quiet != physics || quiet_profile != profile || quiet_events != events)
                    different = 1, why = "  CHANGED BY THE QUERIES";
            }
            differ |= different;
            printf("%-20s threads %u  physics %016llx  profile %016llx  events %016llx", scenes[i].name, threads,
                   (unsigned long long)physics, (unsigned long long)profile, (unsigned long long)events);
            if (queries || check_queries) printf("  queries %016llx", (unsigned long long)answers);
            printf("%s\n", why);
            fflush(stdout);
        }
        ++ran;
    }
    if (ran == 0) {
        fprintf(stderr, "scene_digest: no scene named %s\n", only);
        return 2;
    }
    return differ;
}
