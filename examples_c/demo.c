/* lfem demo: a soft hammer held at the end of its handle falls sideways and swings under
 * gravity, bending as it goes. Writes a ParaView time series (open the .pvd) and prints a
 * progress line per frame.
 *
 *   demo [output.pvd] [seconds]      default: lfem_demo/demo.pvd, 1.5 s */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "lfem.h"

#define CHECK(call)                                                              \
    do {                                                                         \
        lfem_status s_ = (call);                                                 \
        if (s_ != LFEM_OK) {                                                     \
            fprintf(stderr, "%s failed: %s\n", #call, lfem_last_error());        \
            return 1;                                                            \
        }                                                                        \
    } while (0)

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char** argv) {
    const char* pvd = argc > 1 ? argv[1] : "lfem_demo/demo.pvd";
    const double duration = argc > 2 ? atof(argv[2]) : 1.5;
    if (argc <= 1 && mkdir("lfem_demo", 0755) != 0 && errno != EEXIST) {
        perror("mkdir lfem_demo");
        return 1;
    }

    lfem_world_def world_def = lfem_world_def_default();
    lfem_world* world = NULL;
    CHECK(lfem_world_create(&world_def, &world));

    /* Handle 0.3 m along +z, head 0.12 m across; tipped 60 degrees about y so it swings. */
    lfem_mesh* mesh = NULL;
    CHECK(lfem_mesh_create_hammer(0.3, 0.03, 0.12, 0.045, 0.01, &mesh));
    const double axis[3] = {0, 1, 0};
    CHECK(lfem_mesh_rotate(mesh, axis, 1.0472));

    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_COROTATIONAL;
    def.young_modulus = 5e5; /* soft rubber, so the bending shows */
    def.poisson_ratio = 0.35;
    def.density = 1200;
    def.damping = 0.5;
    lfem_body hammer;
    CHECK(lfem_body_create(world, &def, &hammer));
    CHECK(lfem_body_add_mesh(world, hammer, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                             lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh)));
    lfem_mesh_destroy(mesh);

    /* Hold the end of the handle: the nodes within 1 cm of the origin. */
    const double lo[3] = {-0.02, -0.02, -0.01}, hi[3] = {0.02, 0.02, 0.01};
    uint32_t held[256], count = 0;
    CHECK(lfem_body_find_nodes_in_box(world, hammer, lo, hi, held, 256, &count));
    CHECK(lfem_body_fix_nodes(world, hammer, held, count));

    uint32_t nodes = 0, tets = 0;
    CHECK(lfem_body_get_node_count(world, hammer, &nodes));
    CHECK(lfem_body_get_tet_count(world, hammer, &tets));
    double stable = 0;
    CHECK(lfem_world_get_stable_step(world, &stable));
    printf("lfem %s demo: hammer of %u nodes, %u tets, %u held; stable step %.3g s\n",
           lfem_version_string(), nodes, tets, count, stable);

    lfem_vtk_series* series = NULL;
    CHECK(lfem_vtk_series_create(pvd, &series));
    CHECK(lfem_vtk_series_write_frame(series, world));
    const int frames = (int)(duration / 0.02 + 0.5);
    const double start = now();
    for (int frame = 1; frame <= frames; ++frame) {
        CHECK(lfem_world_step(world, 0.02));
        CHECK(lfem_vtk_series_write_frame(series, world));
        lfem_world_stats s;
        CHECK(lfem_world_get_stats(world, &s));
        printf("\rframe %3d/%d  t = %.2f s  steps %llu  kinetic %.4f J  strain %.4f J  energy error %+.1e J  %.1f s wall",
               frame, frames, s.time, (unsigned long long)s.steps, s.kinetic_energy, s.strain_energy,
               s.energy_error, now() - start);
        fflush(stdout);
    }
    printf("\nParaView series written: %s (%d frames)\n", pvd, frames + 1);
    lfem_vtk_series_destroy(series);
    lfem_world_destroy(world);
    return 0;
}
