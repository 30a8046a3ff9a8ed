/* The smallest complete lfem program: a rubber beam clamped at one end swings down under
 * gravity; every 0.05 s it prints the position of the middle of the free end. */
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
    lfem_world_def world_def = lfem_world_def_default(); /* gravity -9.81 m/s^2 along z */
    lfem_world* world = NULL;
    CHECK(lfem_world_create(&world_def, &world));

    /* A 1 m x 0.1 m x 0.1 m beam of stiff rubber, 20 x 2 x 2 cells of 6 tets. */
    const double size[3] = {1.0, 0.1, 0.1};
    const uint32_t cells[3] = {20, 2, 2};
    lfem_mesh* mesh = NULL;
    CHECK(lfem_mesh_create_box(size, cells, &mesh));

    lfem_body_def body_def = lfem_body_def_default();
    body_def.model = LFEM_MODEL_COROTATIONAL; /* large bending rotations */
    body_def.young_modulus = 5e7;             /* Pa: a stiff rubber */
    body_def.density = 1100;                  /* kg/m^3 */
    body_def.damping = 2.0;                   /* 1/s */
    lfem_body beam;
    CHECK(lfem_body_create(world, &body_def, &beam));
    CHECK(lfem_body_add_mesh(world, beam, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                             lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh)));
    lfem_mesh_destroy(mesh);

    /* Clamp the nodes of the x = 0 face. */
    const double lo[3] = {-1e-6, -1, -1}, hi[3] = {1e-6, 1, 1};
    uint32_t clamped[64], count = 0;
    CHECK(lfem_body_find_nodes_in_box(world, beam, lo, hi, clamped, 64, &count));
    CHECK(lfem_body_fix_nodes(world, beam, clamped, count));

    /* The node at the middle of the free end (x = 1, y = z = 0.05). */
    const double tip_lo[3] = {1 - 1e-6, 0.05 - 1e-6, 0.05 - 1e-6};
    const double tip_hi[3] = {1 + 1e-6, 0.05 + 1e-6, 0.05 + 1e-6};
    uint32_t tip = 0, found = 0;
    CHECK(lfem_body_find_nodes_in_box(world, beam, tip_lo, tip_hi, &tip, 1, &found));

    static double x[3 * 1000];
    for (int frame = 1; frame <= 20; ++frame) {
        CHECK(lfem_world_step(world, 0.05)); /* sub-steps chosen automatically */
        CHECK(lfem_body_get_positions(world, beam, x, 1000));
        printf("t = %.2f s  tip = (%+.4f, %+.4f, %+.4f) m\n", 0.05 * frame, x[3 * tip],
               x[3 * tip + 1], x[3 * tip + 2]);
    }
    lfem_world_destroy(world);
    return 0;
}
