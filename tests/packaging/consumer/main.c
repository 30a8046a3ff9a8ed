/* A user's program against the installed lfem (built by tests/packaging/check_install.sh,
 * once through find_package and once through pkg-config): a box falls under gravity for one
 * step. Exit status 0 on success. */
#include <lfem.h>

#include <stdio.h>
#include <stdlib.h>

static int ok(lfem_status status, const char* what) {
    if (status == LFEM_OK) return 1;
    fprintf(stderr, "consumer: %s failed: %s (%s)\n", what, lfem_status_string(status),
            lfem_last_error());
    return 0;
}

int main(void) {
    const double size[3] = {0.1, 0.1, 0.1};
    const uint32_t cells[3] = {2, 2, 2};
    lfem_world_def world_def = lfem_world_def_default();
    lfem_body_def body_def = lfem_body_def_default();
    lfem_world* world = NULL;
    lfem_mesh* mesh = NULL;
    lfem_body body = {0, 0};
    uint32_t node_count = 0;
    double* positions = NULL;
    double z0 = 0.0;
    int success = 0;

    if (ok(lfem_world_create(&world_def, &world), "lfem_world_create") &&
        ok(lfem_body_create(world, &body_def, &body), "lfem_body_create") &&
        ok(lfem_mesh_create_box(size, cells, &mesh), "lfem_mesh_create_box") &&
        ok(lfem_body_add_mesh(world, body, lfem_mesh_get_positions(mesh),
                              lfem_mesh_get_node_count(mesh), lfem_mesh_get_tets(mesh),
                              lfem_mesh_get_tet_count(mesh)),
           "lfem_body_add_mesh") &&
        ok(lfem_body_get_node_count(world, body, &node_count), "lfem_body_get_node_count")) {
        positions = (double*)malloc(3 * (size_t)node_count * sizeof(double));
        if (node_count == 0 || positions == NULL) {
            fprintf(stderr, "consumer: no nodes (%u) or out of memory\n", (unsigned)node_count);
        } else if (ok(lfem_body_get_positions(world, body, positions, node_count),
                      "lfem_body_get_positions")) {
            z0 = positions[2];
            if (ok(lfem_world_step(world, 1e-3), "lfem_world_step") &&
                ok(lfem_body_get_positions(world, body, positions, node_count),
                   "lfem_body_get_positions")) {
                printf("lfem %s: node 0 of %u at (%g, %g, %g) m after 1 ms (z was %g)\n",
                       lfem_version_string(), (unsigned)node_count, positions[0],
                       positions[1], positions[2], z0);
                /* Falling under gravity: z went down (and is a number). */
                if (positions[2] < z0) {
                    success = 1;
                } else {
                    fprintf(stderr, "consumer: node 0 did not fall (z %g -> %g)\n", z0,
                            positions[2]);
                }
            }
        }
    }
    free(positions);
    lfem_mesh_destroy(mesh);
    lfem_world_destroy(world);
    return success ? EXIT_SUCCESS : EXIT_FAILURE;
}
