/* cup_wall: the paper's Fig. 2. An elastic cup, tilted and thrown obliquely, strikes a rigid
 * wall with its rim; the local deformation is unsymmetric: the side that lands first flattens
 * and the rest of the rim keeps its shape.
 *
 *   cup_wall [output.pvd] [seconds]      default: lfem_cup_wall/cup_wall.pvd, 0.06 s
 *
 * Writes a ParaView series, cup_wall_keyframe.png (the frame of the largest contact force,
 * coloured by how far each node is from where a rigid cup would be), and prints one progress
 * line per frame. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lfem.h"
#include "render_png.h"
#include "scene_common.h"

int main(int argc, char** argv) {
    const char* pvd = argc > 1 ? argv[1] : "lfem_cup_wall/cup_wall.pvd";
    const double duration = argc > 2 ? atof(argv[2]) : 0.06;
    char key_path[1100];
    if (scene_make_output_folder(pvd) != 0 ||
        scene_sibling_path(pvd, "cup_wall_keyframe.png", key_path, sizeof key_path) != 0)
        return 1;

    lfem_world_def world_def = lfem_world_def_default();
    lfem_world* world = NULL;
    CHECK(lfem_world_create(&world_def, &world));

    /* The wall: a static box, its face at x = 0.1 m. */
    lfem_mesh* mesh = NULL;
    const double wall_size[3] = {0.05, 0.4, 0.4}, wall_corner[3] = {0.1, -0.2, -0.2};
    const uint32_t wall_cells[3] = {1, 4, 4};
    CHECK(lfem_mesh_create_box(wall_size, wall_cells, &mesh));
    CHECK(lfem_mesh_translate(mesh, wall_corner));
    lfem_body_def wall_def = lfem_body_def_default();
    wall_def.type = LFEM_BODY_STATIC;
    wall_def.friction = 0.3;
    lfem_body wall;
    CHECK(lfem_body_create(world, &wall_def, &wall));
    CHECK(lfem_body_add_mesh(world, wall, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                             lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh)));
    lfem_mesh_destroy(mesh);

    /* The cup: radius 5 cm, 8 cm high, 6 mm wall, 8 mm bottom, centred at the origin with its
     * opening towards the wall, tilted 35 degrees so the rim lands on one side first; thrown
     * at 4 m/s towards the wall and 1 m/s sideways. */
    CHECK(lfem_mesh_create_cup(0.05, 0.08, 0.006, 0.008, 24, 6, &mesh));
    const double centre[3] = {0, 0, -0.04};
    CHECK(lfem_mesh_translate(mesh, centre));
    const double axis_y[3] = {0, 1, 0}, axis_z[3] = {0, 0, 1};
    CHECK(lfem_mesh_rotate(mesh, axis_y, 1.5708 - 0.6109)); /* opening towards +x, tilted */
    CHECK(lfem_mesh_rotate(mesh, axis_z, 0.3));
    const double start[3] = {-0.02, 0.0, 0.0};
    CHECK(lfem_mesh_translate(mesh, start));
    lfem_body_def cup_def = lfem_body_def_default();
    cup_def.model = LFEM_MODEL_COROTATIONAL;
    cup_def.young_modulus = 3e6;
    cup_def.poisson_ratio = 0.4;
    cup_def.density = 1100;
    cup_def.friction = 0.3;
    cup_def.damping = 2.0;
    cup_def.linear_velocity[0] = 4.0;
    cup_def.linear_velocity[1] = 1.0;
    lfem_body cup;
    CHECK(lfem_body_create(world, &cup_def, &cup));
    CHECK(lfem_body_add_mesh(world, cup, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                             lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh)));
    lfem_mesh_destroy(mesh);

    uint32_t nodes = 0, tets = 0;
    CHECK(lfem_body_get_node_count(world, cup, &nodes));
    CHECK(lfem_body_get_tet_count(world, cup, &tets));
    double stable = 0;
    CHECK(lfem_world_get_stable_step(world, &stable));
    printf("lfem %s cup_wall: cup of %u nodes, %u tets; stable step %.3g s\n", lfem_version_string(), nodes,
           tets, stable);

    double* x = (double*)malloc(sizeof(double) * 3 * nodes);
    double* v = (double*)malloc(sizeof(double) * 3 * nodes);
    double* squash = (double*)malloc(sizeof(double) * nodes);
    if (!x || !v || !squash) {
        fprintf(stderr, "out of memory\n");
        return 1;
    }
    lfem_vtk_series* series = NULL;
    CHECK(lfem_vtk_series_create(pvd, &series));
    CHECK(lfem_vtk_series_write_frame(series, world));
    const double frame = 0.002;
    const int frames = (int)(duration / frame + 0.5);
    lfem_contact* contacts = NULL;
    uint32_t capacity = 0;
    double strongest = 0, max_penetration = 0;
    const double t0 = scene_now();
    for (int f = 1; f <= frames; ++f) {
        CHECK(lfem_world_step(world, frame));
        CHECK(lfem_vtk_series_write_frame(series, world));
        lfem_world_stats s;
        CHECK(lfem_world_get_stats(world, &s));
        if (s.max_penetration > max_penetration) max_penetration = s.max_penetration;
        uint32_t count = 0;
        CHECK(scene_query_contacts(world, &contacts, &capacity, &count));
        double force = 0; /* the wall's push on the cup, along -x */
        for (uint32_t c = 0; c < count; ++c) force -= contacts[c].force[0];
        if (force > strongest) {
            /* Key frame: colour each node by its speed relative to the cup's mean velocity,
             * which is zero for a rigid cup: the struck side lights up, the far side not. */
            strongest = force;
            CHECK(lfem_body_get_velocities(world, cup, v, nodes));
            double mean[3] = {0, 0, 0}, top = 0;
            for (uint32_t i = 0; i < nodes; ++i)
                for (int k = 0; k < 3; ++k) mean[k] += v[3 * i + k] / nodes;
            for (uint32_t i = 0; i < nodes; ++i) {
                const double dx = v[3 * i] - mean[0], dy = v[3 * i + 1] - mean[1], dz = v[3 * i + 2] - mean[2];
                squash[i] = sqrt(dx * dx + dy * dy + dz * dz);
                if (squash[i] > top) top = squash[i];
            }
            static const unsigned char background[3] = {250, 250, 250}, black[3] = {0, 0, 0};
            rp_body_style styles[2] = {{wall, {150, 150, 160}, NULL, 0, 0, 1},
                                       {cup, {200, 200, 200}, squash, -top, top, 1}};
            rp_image img;
            if (rp_image_create(&img, 640, 440, background) != 0) return 1;
            const rp_camera camera = {{0.0, -0.32, 0.16}, {0.07, 0.0, 0.0}, {0, 0, 1}, 36};
            if (rp_render_bodies(&img, world, styles, 2, &camera, background) != 0) return 1;
            char label[96];
            snprintf(label, sizeof label, "T = %.3f S: RIM STRIKES THE WALL", s.time);
            rp_draw_text(&img, 12, 12, 2, label, black);
            rp_draw_text(&img, 12, 410, 2, "RED: SPEED RELATIVE TO THE MEAN MOTION OF THE CUP", black);
            if (rp_image_write_png(&img, key_path) != 0) return 1;
            rp_image_destroy(&img);
        }
        printf("t = %.3f s  contacts %4u  wall force %8.2f N  kinetic %.5f J  strain %.5f J  "
               "max penetration %.1e m  %.1f s wall\n",
               s.time, s.contact_count, force, s.kinetic_energy, s.strain_energy, s.max_penetration,
               scene_now() - t0);
        fflush(stdout);
    }
    printf("largest wall force %.2f N, largest penetration %.1e m, %.1f s wall\n", strongest, max_penetration,
           scene_now() - t0);
    printf("ParaView series: %s (%d frames); key frame: %s\n", pvd, frames + 1, key_path);
    free(x);
    free(v);
    free(squash);
    free(contacts);
    lfem_vtk_series_destroy(series);
    lfem_world_destroy(world);
    return 0;
}
