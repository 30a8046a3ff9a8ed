/* The scene shared by the C, Rust, C# and Python examples: a soft box (0.3 x 0.2 x 0.1 m,
 * neo-Hookean rubber) dropped from rest with its bottom at z = 2 m, gravity only, stepped
 * 0.5 s in 0.01 s calls. Every 0.1 s it prints the time, the lowest node z, the centre-of-mass
 * velocity along z (linear momentum / mass) and the kinetic energy. The four programs must print
 * exactly the same lines (ctest bindings_examples_agree). */
#include <stdio.h>

#include "lfem.h"

#define CHECK(call)                                                              \
    do {                                                                         \
        lfem_status s_ = (call);                                                 \
        if (s_ != LFEM_OK) {                                                     \
            fprintf(stderr, "%s failed: %s\n", #call, lfem_last_error());        \
            return 1;                                                            \
        }                                                                        \
    } while (0)

int main(void) {
    const double size[3] = {0.3, 0.2, 0.1}; /* m */
    const uint32_t cells[3] = {3, 2, 1};
    const double lift[3] = {0.0, 0.0, 2.0}; /* m */
    const double density = 400.0;           /* kg/m^3 */
    const double mass = density * (size[0] * size[1] * size[2]);

    lfem_world_def world_def = lfem_world_def_default(); /* gravity (0, 0, -9.81) m/s^2 */
    lfem_world* world = NULL;
    CHECK(lfem_world_create(&world_def, &world));

    lfem_mesh* mesh = NULL;
    CHECK(lfem_mesh_create_box(size, cells, &mesh));
    CHECK(lfem_mesh_translate(mesh, lift));

    lfem_body_def body_def = lfem_body_def_default();
    body_def.model = LFEM_MODEL_NEO_HOOKEAN;
    body_def.young_modulus = 2e5; /* Pa: soft rubber */
    body_def.poisson_ratio = 0.3;
    body_def.density = density;
    lfem_body block;
    CHECK(lfem_body_create(world, &body_def, &block));
    CHECK(lfem_body_add_mesh(world, block, lfem_mesh_get_positions(mesh),
                             lfem_mesh_get_node_count(mesh), lfem_mesh_get_tets(mesh),
                             lfem_mesh_get_tet_count(mesh)));
    lfem_mesh_destroy(mesh);

    uint32_t node_count = 0;
    CHECK(lfem_body_get_node_count(world, block, &node_count));
    static double x[3 * 256];
    if (node_count > 256) return 1;

    for (int call = 1; call <= 50; ++call) {
        CHECK(lfem_world_step(world, 0.01));
        if (call % 10 != 0) continue;
        CHECK(lfem_body_get_positions(world, block, x, node_count));
        double lowest = x[2];
        for (uint32_t i = 1; i < node_count; ++i)
            if (x[3 * i + 2] < lowest) lowest = x[3 * i + 2];
        lfem_world_stats stats;
        CHECK(lfem_world_get_stats(world, &stats));
        printf("t = %.6f s  lowest z = %.6f m  com vz = %.6f m/s  kinetic energy = %.6f J\n",
               stats.time, lowest, stats.linear_momentum[2] / mass, stats.kinetic_energy);
    }
    lfem_world_destroy(world);
    return 0;
}
