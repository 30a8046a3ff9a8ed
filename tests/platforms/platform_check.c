/* platform_check: lfem as a game uses it, on every target. Plain C99 with nothing but lfem.h
 * and the library (no test framework); tests/platforms.sh builds it for x86-64 Linux,
 * Windows x64 (run under Wine) and ARM64 Linux (run under qemu-aarch64) and compares what the
 * three print. It creates worlds, adds meshes and shapes, steps, queries contacts, checks that
 * bad input is refused and leaves the world as it was, and makes a checkpoint round trip.
 * Every physical result is checked here against a closed form or a conservation law.
 *
 *   platform_check hulls|no-hulls    whether this build has convex hulls (libccd)
 *
 * Output lines: "figure NAME = numbers" (the targets must agree to 1e-12 relative), "bits NAME
 * = digest" (a digest of the raw bits of a scene's state: equal digests mean bitwise equal
 * results), "check WHAT: ok" and "build WHAT = ..." (what this build contains). A failed
 * check prints "FAILED: ..." on stderr and ends the program with status 1. Writes
 * platform_check.lfem (a checkpoint) in the current folder. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lfem.h"

static const double g = 9.81; /* m/s^2, the default gravity's magnitude */

static void fail(const char* what) {
    fprintf(stderr, "FAILED: %s (last error: %s)\n", what, lfem_last_error());
    exit(1);
}

static void ok(lfem_status s, const char* what) {
    if (s != LFEM_OK) {
        fprintf(stderr, "FAILED: %s: %s (%s)\n", what, lfem_status_string(s), lfem_last_error());
        exit(1);
    }
}

static void check(int condition, const char* what) {
    if (!condition) fail(what);
    printf("check %s: ok\n", what);
}

static void figure(const char* name, int n, const double* v) {
    printf("figure %s =", name);
    for (int i = 0; i < n; ++i) printf(" %.17g", v[i]);
    printf("\n");
}

/* FNV-1a over raw bytes: the digest of a state, bit for bit. */
static uint64_t digest_bytes(uint64_t h, const void* p, size_t n) {
    const unsigned char* c = (const unsigned char*)p;
    for (size_t i = 0; i < n; ++i) {
        h ^= c[i];
        h *= 1099511628211ull;
    }
    return h;
}

#define MAX_NODES 512
static double xs[3 * MAX_NODES], vs[3 * MAX_NODES];

static uint32_t node_count(const lfem_world* w, lfem_body b) {
    uint32_t n = 0;
    ok(lfem_body_get_node_count(w, b, &n), "node count");
    if (n > MAX_NODES) fail("a body has more nodes than this program's buffers");
    return n;
}

/* Positions and velocities of the bodies and the active contacts' forces. */
static uint64_t digest_world(const lfem_world* w, const lfem_body* bodies, int count) {
    uint64_t h = 14695981039346656037ull;
    for (int i = 0; i < count; ++i) {
        const uint32_t n = node_count(w, bodies[i]);
        ok(lfem_body_get_positions(w, bodies[i], xs, n), "positions");
        ok(lfem_body_get_velocities(w, bodies[i], vs, n), "velocities");
        h = digest_bytes(h, xs, sizeof(double) * 3 * n);
        h = digest_bytes(h, vs, sizeof(double) * 3 * n);
    }
    static lfem_contact contacts[2048];
    uint32_t nc = 0;
    ok(lfem_world_query_contacts(w, contacts, 2048, &nc), "contacts");
    for (uint32_t i = 0; i < nc; ++i) {
        h = digest_bytes(h, &contacts[i].node, sizeof contacts[i].node);
        h = digest_bytes(h, contacts[i].force, sizeof contacts[i].force);
    }
    return h;
}

static void bits(const char* name, uint64_t h) {
    printf("bits %s = %08lx%08lx\n", name, (unsigned long)(h >> 32), (unsigned long)(h & 0xffffffffu));
}

static lfem_world* make_world(uint32_t threads, double gravity_z) {
    lfem_world_def wd = lfem_world_def_default();
    wd.thread_count = threads;
    wd.gravity[2] = gravity_z;
    lfem_world* w = NULL;
    ok(lfem_world_create(&wd, &w), "world create");
    return w;
}

/* A box body of size s, cells c, its lowest corner at o. */
static lfem_body add_box(lfem_world* w, const lfem_body_def* def, const double s[3],
                         const uint32_t c[3], const double o[3]) {
    lfem_mesh* m = NULL;
    ok(lfem_mesh_create_box(s, c, &m), "box mesh");
    ok(lfem_mesh_translate(m, o), "translate");
    lfem_body b;
    ok(lfem_body_create(w, def, &b), "body create");
    ok(lfem_body_add_mesh(w, b, lfem_mesh_get_positions(m), lfem_mesh_get_node_count(m),
                          lfem_mesh_get_tets(m), lfem_mesh_get_tet_count(m)),
       "add mesh");
    lfem_mesh_destroy(m);
    return b;
}

static const double cube[3] = {0.1, 0.1, 0.1};  /* m */
static const uint32_t cells[3] = {3, 3, 3};

/* 1. Free fall of a corotational cube: uniform gravity strains nothing, so every node follows
 *    z0 - g t^2 / 2. Central differences integrate a constant acceleration exactly; what is
 *    left is rounding, about 1e-16 m per sub-step over fewer than 100 sub-steps, hence 1e-12 m. */
static void free_fall(void) {
    lfem_world* w = make_world(1, -g);
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_COROTATIONAL;
    const double o[3] = {0.0, 0.0, 1.0};
    lfem_body b = add_box(w, &d, cube, cells, o);
    const uint32_t n = node_count(w, b);
    double z0[MAX_NODES];
    ok(lfem_body_get_positions(w, b, xs, n), "positions");
    for (uint32_t i = 0; i < n; ++i) z0[i] = xs[3 * i + 2];
    for (int call = 0; call < 10; ++call) ok(lfem_world_step(w, 0.01), "step");
    lfem_world_stats st;
    ok(lfem_world_get_stats(w, &st), "stats");
    ok(lfem_body_get_positions(w, b, xs, n), "positions");
    double worst = 0.0, mass, p[3];
    for (uint32_t i = 0; i < n; ++i)
        worst = fmax(worst, fabs(xs[3 * i + 2] - (z0[i] - 0.5 * g * st.time * st.time)));
    ok(lfem_body_get_mass(w, b, &mass), "mass");
    ok(lfem_body_get_momentum(w, b, p, NULL), "momentum");
    const double out[4] = {st.time, (double)st.steps, xs[2], p[2] / mass};
    figure("free_fall time_steps_z0_vz", 4, out);
    check(worst < 1e-12, "free fall: every node at z0 - g t^2/2 within 1e-12 m");
    /* The synchronized velocity -g t: exact up to rounding of m v summed over the nodes. */
    check(fabs(p[2] / mass + g * st.time) < 1e-12, "free fall: velocity -g t within 1e-12 m/s");
    lfem_world_destroy(w);
}

/* 2. Two soft cubes resting on a floor, one on a static tet-mesh box (node against triangle),
 *    one on a plane shape, with damping: each floor carries the cube's weight. Run on 1 and on
 *    3 threads: the two runs must agree bit for bit. Returns the digest. */
static uint64_t resting(uint32_t threads, int print) {
    lfem_world* w = make_world(threads, -g);
    lfem_body bodies[3];
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    const double slab[3] = {0.3, 0.3, 0.05}, slab_at[3] = {-0.15, -0.15, -0.05};
    const uint32_t slab_cells[3] = {3, 3, 1};
    bodies[0] = add_box(w, &f, slab, slab_cells, slab_at);
    lfem_shape_def plane = lfem_shape_def_default();  /* z = 0, facing +z */
    plane.center[0] = 1.0;
    lfem_body ground;
    uint32_t shape_index;
    ok(lfem_body_create(w, &f, &ground), "ground body");
    ok(lfem_body_add_shape(w, ground, &plane, &shape_index), "plane shape");
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    d.young_modulus = 2e5;
    d.damping = 20.0;
    const double on_slab[3] = {-0.05, -0.05, 0.002}, on_plane[3] = {0.95, -0.05, 0.002};
    bodies[1] = add_box(w, &d, cube, cells, on_slab);
    bodies[2] = add_box(w, &d, cube, cells, on_plane);
    for (int call = 0; call < 60; ++call) ok(lfem_world_step(w, 1.0 / 60.0), "step");

    /* The contacts: a buffer of one is too small and says how many there are. */
    static lfem_contact contacts[1024];
    uint32_t count = 0;
    const lfem_status small = lfem_world_query_contacts(w, contacts, 1, &count);
    if (print)
        check(small == LFEM_BUFFER_TOO_SMALL && count > 1, "query contacts: too small a buffer is refused with the count");
    ok(lfem_world_query_contacts(w, contacts, 1024, &count), "query contacts");
    /* The force on a pair's node, its opposite on the triangle's (or shape's) side. */
    double load[2] = {0.0, 0.0}, mass[2];
    for (uint32_t i = 0; i < count; ++i)
        for (int k = 0; k < 2; ++k) {
            if (contacts[i].body_a.index == bodies[1 + k].index) load[k] += contacts[i].force[2];
            if (contacts[i].body_b.index == bodies[1 + k].index) load[k] -= contacts[i].force[2];
        }
    ok(lfem_body_get_mass(w, bodies[1], &mass[0]), "mass");
    ok(lfem_body_get_mass(w, bodies[2], &mass[1]), "mass");
    if (print) {
        lfem_world_stats st;
        ok(lfem_world_get_stats(w, &st), "stats");
        const double out[5] = {(double)count, load[0], load[1], st.kinetic_energy, st.strain_energy};
        figure("resting contacts_load_slab_load_plane_kinetic_strain", 5, out);
        /* After 1 s the bounce of the 2 mm drop has rung down by exp(-alpha t / 2) = exp(-10)
         * = 5e-5: what is left of it moves the load by well under 0.1 % of the weight. */
        check(fabs(load[0] / (mass[0] * g) - 1.0) < 1e-3, "resting: the slab carries the weight within 0.1 %");
        check(fabs(load[1] / (mass[1] * g) - 1.0) < 1e-3, "resting: the plane carries the weight within 0.1 %");
    }
    const uint64_t h = digest_world(w, bodies, 3);
    lfem_world_destroy(w);
    return h;
}

/* 3. A cube flying at 2 m/s into a cube at rest, no gravity: the contact forces are equal and
 *    opposite, so the total momentum stays m v (to rounding: 1e-12 of it); the impact can only
 *    lose energy. Halfway, a checkpoint; the run from it must end bitwise where the world
 *    itself ends. Returns the digest at the end. */
static uint64_t collision(void) {
    lfem_world* w = make_world(2, 0.0);
    lfem_body b[2];
    lfem_body_def d = lfem_body_def_default();
    d.model = LFEM_MODEL_LINEAR;
    d.young_modulus = 1e6;
    const double at_rest[3] = {0.101, 0.0, 0.0}, moving[3] = {0.0, 0.0, 0.0};
    b[0] = add_box(w, &d, cube, cells, at_rest);
    d.model = LFEM_MODEL_NEO_HOOKEAN;
    d.linear_velocity[0] = 2.0;
    b[1] = add_box(w, &d, cube, cells, moving);
    double m, p0[3];
    ok(lfem_body_get_mass(w, b[1], &m), "mass");
    ok(lfem_body_get_momentum(w, b[1], p0, NULL), "momentum");
    lfem_world_stats st;
    ok(lfem_world_get_stats(w, &st), "stats");
    const double e0 = st.kinetic_energy;
    for (int call = 0; call < 10; ++call) ok(lfem_world_step(w, 0.005), "step");
    const char* path = "platform_check.lfem";
    ok(lfem_world_save(w, path), "checkpoint save");
    for (int call = 0; call < 10; ++call) ok(lfem_world_step(w, 0.005), "step");
    const uint64_t end = digest_world(w, b, 2);

    double pa[3], pb[3];
    ok(lfem_body_get_momentum(w, b[0], pa, NULL), "momentum");
    ok(lfem_body_get_momentum(w, b[1], pb, NULL), "momentum");
    ok(lfem_world_get_stats(w, &st), "stats");
    const double out[5] = {pa[0], pb[0], st.kinetic_energy, st.strain_energy, (double)st.steps};
    figure("collision momentum_a_momentum_b_kinetic_strain_steps", 5, out);
    check(pa[0] > 0.5 * p0[0], "collision: the struck cube took over momentum");
    check(fabs(pa[0] + pb[0] - p0[0]) < 1e-12 * p0[0], "collision: momentum kept within 1e-12");
    check(st.kinetic_energy + st.strain_energy <= e0 * (1.0 + 1e-12), "collision: no energy gained");

    /* From the checkpoint: the same end, bit for bit. Saving over the file again replaces it. */
    lfem_world* loaded = NULL;
    ok(lfem_world_load(path, &loaded), "checkpoint load");
    for (int call = 0; call < 10; ++call) ok(lfem_world_step(loaded, 0.005), "step");
    check(digest_world(loaded, b, 2) == end, "checkpoint: continuing from it is bitwise the same");
    ok(lfem_world_save(w, path), "checkpoint save over the old one");
    lfem_world_destroy(loaded);
    loaded = NULL;
    ok(lfem_world_load(path, &loaded), "checkpoint load");
    check(digest_world(loaded, b, 2) == end, "checkpoint: saved over the old file and read back");
    lfem_world_destroy(loaded);
    lfem_world_destroy(w);
    remove(path);
    return end;
}

/* 4. A rigid octahedron (a centre node and one tet per octant: its lumped masses are mirror
 *    symmetric, so its axes are principal axes) spinning about z: no torque, so the rotation
 *    after t is exactly Rz(omega t). Eq. (2) composes the steps' rotations, each from sin and
 *    cos: the one place where the platform's libm enters this program. 1e-12 covers the
 *    rounding of 50 compositions. */
static void spinning(void) {
    lfem_world* w = make_world(1, 0.0);
    lfem_body_def d = lfem_body_def_default();
    d.type = LFEM_BODY_RIGID;
    d.angular_velocity[2] = 3.0;
    const double nodes[21] = {0, 0, 0, 0.2, 0, 0, -0.2, 0, 0, 0, 0.1, 0, 0, -0.1, 0, 0, 0, 0.05, 0, 0, -0.05};
    uint32_t tets[32];
    for (int k = 0; k < 8; ++k) {
        const uint32_t x = 1 + (k & 1), y = 3 + ((k >> 1) & 1), z = 5 + ((k >> 2) & 1);
        const int positive = ((k & 1) + ((k >> 1) & 1) + ((k >> 2) & 1)) % 2 == 0; /* sx sy sz > 0 */
        const uint32_t t[4] = {0, positive ? x : y, positive ? y : x, z};
        memcpy(tets + 4 * k, t, sizeof t);
    }
    lfem_body b;
    ok(lfem_body_create(w, &d, &b), "body create");
    ok(lfem_body_add_mesh(w, b, nodes, 7, tets, 8), "add mesh");
    double L0[3], R[9], L[3];
    ok(lfem_body_get_momentum(w, b, NULL, L0), "momentum");
    for (int call = 0; call < 50; ++call) ok(lfem_world_step(w, 0.01), "step");
    ok(lfem_body_get_rotation(w, b, R), "rotation");
    ok(lfem_body_get_momentum(w, b, NULL, L), "momentum");
    figure("spinning rotation_xx_xy_yx_yy_momentum_z", 5, (const double[]){R[0], R[1], R[3], R[4], L[2]});
    const double a = 3.0 * 0.5;
    check(fabs(R[0] - cos(a)) < 1e-12 && fabs(R[1] + sin(a)) < 1e-12 && fabs(R[3] - sin(a)) < 1e-12 &&
              fabs(R[4] - cos(a)) < 1e-12 && fabs(R[8] - 1.0) < 1e-12,
          "spinning: rotation Rz(omega t) within 1e-12");
    check(L[0] == L0[0] && L[1] == L0[1] && L[2] == L0[2], "spinning: angular momentum kept exactly");
    lfem_world_destroy(w);
}

/* 5. Bad input is refused with a status and a message, and the world stays as it was. */
static void refusals(int with_hulls) {
    lfem_world* w = make_world(1, -g);
    lfem_body_def d = lfem_body_def_default();
    const double o[3] = {0.0, 0.0, 0.0};
    lfem_body b[1];
    b[0] = add_box(w, &d, cube, cells, o);
    ok(lfem_world_step(w, 0.01), "step");
    const uint64_t before = digest_world(w, b, 1);

    const double nodes[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t inverted[4] = {0, 2, 1, 3};  /* negative volume */
    check(lfem_body_add_mesh(w, b[0], nodes, 4, inverted, 1) == LFEM_INVALID_MESH,
          "inverted tet: LFEM_INVALID_MESH");
    double nan_nodes[12];
    memcpy(nan_nodes, nodes, sizeof nodes);
    nan_nodes[4] = nan("");
    const uint32_t tet[4] = {0, 1, 2, 3};
    check(lfem_body_add_mesh(w, b[0], nan_nodes, 4, tet, 1) == LFEM_INVALID_ARGUMENT,
          "NaN position: LFEM_INVALID_ARGUMENT");
    check(lfem_body_get_positions(w, b[0], xs, 1) == LFEM_BUFFER_TOO_SMALL, "positions into a buffer of one node: LFEM_BUFFER_TOO_SMALL");
    check(digest_world(w, b, 1) == before, "the refused calls left the world bitwise as it was");
    lfem_body gone;
    ok(lfem_body_create(w, &d, &gone), "body create");
    ok(lfem_body_destroy(w, gone), "body destroy");
    uint32_t n = 0;
    check(lfem_body_get_node_count(w, gone, &n) == LFEM_INVALID_HANDLE, "stale handle: LFEM_INVALID_HANDLE");

    /* A convex hull on a static body: libccd, where the build has it. */
    lfem_body_def f = lfem_body_def_default();
    f.type = LFEM_BODY_STATIC;
    lfem_body rock;
    ok(lfem_body_create(w, &f, &rock), "body create");
    lfem_shape_def hull = lfem_shape_def_default();
    hull.type = LFEM_SHAPE_CONVEX_HULL;
    hull.points = nodes;
    hull.point_count = 4;
    uint32_t index;
    const lfem_status s = lfem_body_add_shape(w, rock, &hull, &index);
    printf("build convex hulls = %s\n", s == LFEM_OK ? "supported" : lfem_status_string(s));
    check(with_hulls ? s == LFEM_OK : s == LFEM_UNSUPPORTED,
          "convex hull shape: added, or LFEM_UNSUPPORTED in a build without libccd");
    lfem_world_destroy(w);
}

int main(int argc, char** argv) {
    if (argc != 2 || (strcmp(argv[1], "hulls") != 0 && strcmp(argv[1], "no-hulls") != 0)) {
        fprintf(stderr, "usage: platform_check hulls|no-hulls\n");
        return 2;
    }
    printf("lfem %s platform check\n", lfem_version_string());
    check(lfem_version() == ((LFEM_VERSION_MAJOR << 16) | (LFEM_VERSION_MINOR << 8) | LFEM_VERSION_PATCH),
          "the library's version is the header's");
    free_fall();
    const uint64_t one = resting(1, 1), three = resting(3, 0);
    bits("resting", one);
    check(one == three, "resting: 1 and 3 threads give bitwise the same state");
    bits("collision", collision());
    spinning();
    refusals(strcmp(argv[1], "hulls") == 0);
    printf("platform check: all checks passed\n");
    return 0;
}
