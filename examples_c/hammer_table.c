/* hammer_table: the paper's Fig. 1. A flexible hammer, head first and tilted, drops onto a
 * flexible table top resting on four rigid legs; both deform freely where they meet.
 *
 *   hammer_table [output.pvd] [seconds]      default: lfem_hammer_table/hammer_table.pvd, 0.3 s
 *
 * Writes a ParaView series (open the .pvd, colour by von_mises) and
 * hammer_table_keyframe.png (the frame of the largest contact force), and prints one progress
 * line per frame. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "lfem.h"
#include "render_png.h"
#include "scene_common.h"

/* A box mesh of size (sx, sy, sz) whose lowest corner is at (x, y, z). */
static lfem_status box_body(lfem_world* world, const lfem_body_def* def, const double size[3],
                            const uint32_t cells[3], const double corner[3], lfem_body* out) {
    lfem_mesh* mesh = NULL;
    lfem_status s = lfem_mesh_create_box(size, cells, &mesh);
    if (s == LFEM_OK) s = lfem_mesh_translate(mesh, corner);
    if (s == LFEM_OK) s = lfem_body_create(world, def, out);
    if (s == LFEM_OK)
        s = lfem_body_add_mesh(world, *out, lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                               lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh));
    lfem_mesh_destroy(mesh);
    return s;
}

static int write_keyframe(const char* path, const lfem_world* world, const lfem_body* bodies,
                          int count, double time) {
    static const unsigned char background[3] = {250, 250, 250}, black[3] = {0, 0, 0};
    static const unsigned char colours[6][3] = {{214, 150, 90}, {120, 120, 130}, {120, 120, 130},
                                                {120, 120, 130}, {120, 120, 130}, {70, 110, 190}};
    rp_body_style styles[6];
    for (int b = 0; b < count; ++b) {
        styles[b].body = bodies[b];
        for (int k = 0; k < 3; ++k) styles[b].colour[k] = colours[b][k];
        styles[b].node_scalar = NULL;
        styles[b].scalar_min = styles[b].scalar_max = 0;
        styles[b].draw_edges = 1;
    }
    rp_image img;
    if (rp_image_create(&img, 640, 440, background) != 0) return -1;
    const rp_camera camera = {{0.55, -0.95, 0.85}, {0.0, 0.0, 0.38}, {0, 0, 1}, 32};
    int status = rp_render_bodies(&img, world, styles, count, &camera, background);
    if (status == 0) {
        char label[96];
        snprintf(label, sizeof label, "T = %.3f S: HAMMER MEETS TABLE", time);
        rp_draw_text(&img, 12, 12, 2, label, black);
        status = rp_image_write_png(&img, path);
    }
    rp_image_destroy(&img);
    return status;
}

int main(int argc, char** argv) {
    const char* pvd = argc > 1 ? argv[1] : "lfem_hammer_table/hammer_table.pvd";
    const double duration = argc > 2 ? atof(argv[2]) : 0.3;
    char key_path[1100];
    if (scene_make_output_folder(pvd) != 0 ||
        scene_sibling_path(pvd, "hammer_table_keyframe.png", key_path, sizeof key_path) != 0)
        return 1;

    lfem_world_def world_def = lfem_world_def_default(); /* gravity -9.81 m/s^2 along z */
    lfem_world* world = NULL;
    CHECK(lfem_world_create(&world_def, &world));
    lfem_body bodies[6];

    /* The table top: a 0.6 x 0.4 x 0.03 m slab of a soft, fictitious material on four rigid
     * 0.05 m square legs 0.4 m high (static bodies): it sags and rings when struck. */
    lfem_body_def top = lfem_body_def_default();
    top.model = LFEM_MODEL_COROTATIONAL;
    top.young_modulus = 5e6;
    top.poisson_ratio = 0.3;
    top.density = 800;
    top.damping = 2.0;
    top.friction = 0.4;
    const double top_size[3] = {0.6, 0.4, 0.03}, top_corner[3] = {-0.3, -0.2, 0.4};
    const uint32_t top_cells[3] = {24, 16, 2};
    CHECK(box_body(world, &top, top_size, top_cells, top_corner, &bodies[0]));
    lfem_body_def leg = lfem_body_def_default();
    leg.type = LFEM_BODY_STATIC;
    leg.friction = 0.4;
    const double leg_size[3] = {0.05, 0.05, 0.4};
    const uint32_t leg_cells[3] = {1, 1, 4};
    for (int i = 0; i < 4; ++i) {
        const double corner[3] = {i % 2 ? 0.22 : -0.27, i / 2 ? 0.12 : -0.17, 0.0};
        CHECK(box_body(world, &leg, leg_size, leg_cells, corner, &bodies[1 + i]));
    }

    /* The hammer: handle 0.25 m, head 0.12 m; turned head down and tilted 30 degrees, its head
     * 5 cm above the table, thrown down at 2 m/s. Stiffer than the table, but still soft
     * enough to bend. */
    lfem_mesh* mesh = NULL;
    CHECK(lfem_mesh_create_hammer(0.25, 0.025, 0.12, 0.04, 0.0125, &mesh));
    const double axis_y[3] = {0, 1, 0}, axis_x[3] = {1, 0, 0};
    CHECK(lfem_mesh_rotate(mesh, axis_y, 3.14159265358979 - 0.5236)); /* head down, tilted */
    CHECK(lfem_mesh_rotate(mesh, axis_x, 0.3));
    double lowest = 1e9;
    const double* x = lfem_mesh_get_positions(mesh);
    for (uint32_t i = 0; i < lfem_mesh_get_node_count(mesh); ++i)
        if (x[3 * i + 2] < lowest) lowest = x[3 * i + 2];
    const double lift[3] = {0.05, 0.0, 0.43 + 0.05 - lowest};
    CHECK(lfem_mesh_translate(mesh, lift));
    lfem_body_def hammer = lfem_body_def_default();
    hammer.model = LFEM_MODEL_COROTATIONAL;
    hammer.young_modulus = 3e7;
    hammer.poisson_ratio = 0.3;
    hammer.density = 2000;
    hammer.damping = 1.0;
    hammer.friction = 0.4;
    hammer.linear_velocity[2] = -2.0;
    CHECK(lfem_body_create(world, &hammer, &bodies[5]));
    CHECK(lfem_body_add_mesh(world, bodies[5], lfem_mesh_get_positions(mesh), lfem_mesh_get_node_count(mesh),
                             lfem_mesh_get_tets(mesh), lfem_mesh_get_tet_count(mesh)));
    lfem_mesh_destroy(mesh);

    uint32_t tets_top = 0, tets_hammer = 0;
    CHECK(lfem_body_get_tet_count(world, bodies[0], &tets_top));
    CHECK(lfem_body_get_tet_count(world, bodies[5], &tets_hammer));
    double stable = 0;
    CHECK(lfem_world_get_stable_step(world, &stable));
    printf("lfem %s hammer_table: table top %u tets, hammer %u tets; stable step %.3g s\n",
           lfem_version_string(), tets_top, tets_hammer, stable);

    lfem_vtk_series* series = NULL;
    CHECK(lfem_vtk_series_create(pvd, &series));
    CHECK(lfem_vtk_series_write_frame(series, world));
    const double frame = 0.005;
    const int frames = (int)(duration / frame + 0.5);
    lfem_contact* contacts = NULL;
    uint32_t capacity = 0;
    double strongest = 0, max_penetration = 0;
    const double start = scene_now();
    for (int f = 1; f <= frames; ++f) {
        CHECK(lfem_world_step(world, frame));
        CHECK(lfem_vtk_series_write_frame(series, world));
        lfem_world_stats s;
        CHECK(lfem_world_get_stats(world, &s));
        if (s.max_penetration > max_penetration) max_penetration = s.max_penetration;
        /* The hammer's contact force on the table (its nodes' forces and the reactions on its
         * triangles), for choosing the key frame. */
        uint32_t count = 0;
        CHECK(scene_query_contacts(world, &contacts, &capacity, &count));
        double fz = 0;
        for (uint32_t c = 0; c < count; ++c) {
            if (contacts[c].body_a.index == bodies[5].index) fz += contacts[c].force[2];
            if (contacts[c].body_b.index == bodies[5].index) fz -= contacts[c].force[2];
        }
        if (fz > strongest) {
            strongest = fz;
            if (write_keyframe(key_path, world, bodies, 6, s.time) != 0) return 1;
        }
        printf("t = %.3f s  contacts %4u  hammer contact force %8.1f N  kinetic %7.4f J  strain %7.4f J  "
               "max penetration %.1e m  %.1f s wall\n",
               s.time, s.contact_count, fz, s.kinetic_energy, s.strain_energy, s.max_penetration,
               scene_now() - start);
        fflush(stdout);
    }
    printf("largest hammer contact force %.1f N, largest penetration %.1e m, %.1f s wall\n", strongest,
           max_penetration, scene_now() - start);
    printf("ParaView series: %s (%d frames); key frame: %s\n", pvd, frames + 1, key_path);
    free(contacts);
    lfem_vtk_series_destroy(series);
    lfem_world_destroy(world);
    return 0;
}
