/* The paper's two-bar impact (Fig. 3 and 4): two steel bars fly at each other at 5.1359 m/s
 * each, touch after closing a 0.254 mm gap, and part again once the compression waves have run
 * to their far ends and back. One-dimensional wave theory gives the contact force in closed
 * form (a plateau of constant force); with Poisson's ratio 0 the 3-D model converges to it.
 *
 *   bar_impact [output.pvd] [nu] [cells]
 *     output.pvd  the ParaView series, default lfem_bar_impact/bar_impact.pvd; the other files
 *                 go beside it: bar_impact.csv (the force-time curve beside the analytic one),
 *                 bar_impact.png (a plot of both) and bar_impact_keyframe.png (the bars during
 *                 contact, coloured by x velocity)
 *     nu          Poisson's ratio, default 0 (the 1-D limit; 0.3 shows lateral inertia)
 *     cells       cells along each bar, default 40 (cells across: cells / 10, at least 1)
 *
 * Prints the impulse, plateau force, contact duration and final velocities beside the
 * analytic ones. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "render_png.h"
#include "scene_common.h"

/* The paper's Fig. 3. */
static const double kLength = 0.254;                /* m, both bars */
static const double kWidth = 0.0254;                /* m, b1 = b2 (along y) */
static const double kHeight1 = 0.0254, kHeight2 = 0.0224; /* m, along z */
static const double kGap = 2.54e-4;                 /* m */
static const double kSpeed = 5.1359;                /* m/s, each bar towards the other */
static const double kDensity = 7844.0;              /* kg/m^3 */
static const double kYoung = 206.82e9;              /* Pa */
static const double kEndTime = 200e-6;              /* s: contact is over by ~124 us */

/* The 1-D solution. Both bars carry waves at c = sqrt(E/rho); contact begins when the gap has
 * closed and lasts until the compression waves return from the (equally long) bars' far ends;
 * the force is the one that brings the two faces to a common velocity. */
typedef struct analytic {
    double wave_speed, start, duration, force, impulse, v1, v2;
} analytic;

static analytic analytic_solution(void) {
    analytic a;
    const double area1 = kWidth * kHeight1, area2 = kWidth * kHeight2;
    a.wave_speed = sqrt(kYoung / kDensity);
    const double z1 = kDensity * a.wave_speed * area1, z2 = kDensity * a.wave_speed * area2;
    a.start = kGap / (2 * kSpeed);
    a.duration = 2 * kLength / a.wave_speed;
    a.force = z1 * z2 / (z1 + z2) * 2 * kSpeed;
    a.impulse = a.force * a.duration;
    a.v1 = kSpeed - a.impulse / (kDensity * area1 * kLength);
    a.v2 = -kSpeed + a.impulse / (kDensity * area2 * kLength);
    return a;
}

static double analytic_force(const analytic* a, double t) {
    return t >= a->start && t < a->start + a->duration ? a->force : 0.0;
}

/* ---- the force-time plot ----------------------------------------------------------------- */

typedef struct plot_frame {
    int left, top, right, bottom; /* pixels of the axes box */
    double t_max, f_max;          /* us, kN at the box's right and top */
} plot_frame;

static double plot_x(const plot_frame* p, double t_us) {
    return p->left + (p->right - p->left) * t_us / p->t_max;
}
static double plot_y(const plot_frame* p, double f_kn) {
    return p->bottom - (p->bottom - p->top) * f_kn / p->f_max;
}

static int write_plot(const char* path, const analytic* a, const double* time_us,
                      const double* force_n, int samples, double nu, int cells) {
    static const unsigned char white[3] = {255, 255, 255}, black[3] = {0, 0, 0},
                               grey[3] = {215, 215, 215}, blue[3] = {31, 119, 180},
                               red[3] = {214, 39, 40};
    rp_image img;
    if (rp_image_create(&img, 640, 400, white) != 0) return -1;
    const plot_frame p = {70, 40, 620, 340, 200.0, 150.0};
    char label[128];

    /* Grid and ticks: every 25 us and 25 kN. */
    for (int t = 0; t <= 200; t += 25) {
        const double x = plot_x(&p, t);
        rp_draw_line(&img, x, p.top, x, p.bottom, 1, grey);
        rp_draw_line(&img, x, p.bottom, x, p.bottom + 6, 1.5, black);
        snprintf(label, sizeof label, "%d", t);
        rp_draw_text(&img, (int)x - rp_text_width(2, label) / 2, p.bottom + 10, 2, label, black);
    }
    for (int f = 0; f <= 150; f += 25) {
        const double y = plot_y(&p, f);
        rp_draw_line(&img, p.left, y, p.right, y, 1, grey);
        rp_draw_line(&img, p.left - 6, y, p.left, y, 1.5, black);
        snprintf(label, sizeof label, "%d", f);
        rp_draw_text(&img, p.left - 10 - rp_text_width(2, label), (int)y - 7, 2, label, black);
    }
    rp_draw_line(&img, p.left, p.top, p.left, p.bottom, 1.5, black);
    rp_draw_line(&img, p.left, p.bottom, p.right, p.bottom, 1.5, black);
    rp_draw_line(&img, p.right, p.top, p.right, p.bottom, 1, black);
    rp_draw_line(&img, p.left, p.top, p.right, p.top, 1, black);
    const char* x_title = "TIME (MICROSECONDS)";
    rp_draw_text(&img, (p.left + p.right - rp_text_width(2, x_title)) / 2, p.bottom + 34, 2, x_title,
                 black);
    rp_draw_text(&img, 8, 12, 2, "FORCE (KN)", black);
    snprintf(label, sizeof label, "NU = %.2g, %dX%dX%d CELLS A BAR", nu, cells,
             cells / 10 > 0 ? cells / 10 : 1, cells / 10 > 0 ? cells / 10 : 1);
    rp_draw_text(&img, p.right - rp_text_width(2, label), 12, 2, label, black);

    /* The analytic step first, lfem over it. */
    const double t0 = a->start * 1e6, t1 = (a->start + a->duration) * 1e6, f = a->force / 1e3;
    const double step[6][2] = {{0, 0}, {t0, 0}, {t0, f}, {t1, f}, {t1, 0}, {p.t_max, 0}};
    for (int k = 0; k + 1 < 6; ++k)
        rp_draw_line(&img, plot_x(&p, step[k][0]), plot_y(&p, step[k][1]), plot_x(&p, step[k + 1][0]),
                     plot_y(&p, step[k + 1][1]), 2.5, red);
    for (int k = 0; k + 1 < samples; ++k)
        rp_draw_line(&img, plot_x(&p, time_us[k]), plot_y(&p, force_n[k] / 1e3),
                     plot_x(&p, time_us[k + 1]), plot_y(&p, force_n[k + 1] / 1e3), 2, blue);

    /* Legend: colour swatches. */
    const int lx = (int)plot_x(&p, 132.0), ly = (int)plot_y(&p, 100.0); /* right of the pulse */
    rp_fill_rect(&img, lx - 10, ly - 8, p.right - 12, ly + 52, white);
    rp_draw_line(&img, lx, ly + 7, lx + 30, ly + 7, 3, blue);
    rp_draw_text(&img, lx + 40, ly, 2, "LFEM", black);
    rp_draw_line(&img, lx, ly + 35, lx + 30, ly + 35, 3, red);
    rp_draw_text(&img, lx + 40, ly + 28, 2, "1-D THEORY", black);

    const int status = rp_image_write_png(&img, path);
    rp_image_destroy(&img);
    return status;
}

/* ---- the key frame: the bars during contact, coloured by x velocity ------------------------- */

static int write_keyframe(const char* path, const lfem_world* world, const lfem_body bars[2],
                          double* velocity_x[2], double time_us) {
    static const unsigned char background[3] = {250, 250, 250}, black[3] = {0, 0, 0};
    rp_image img;
    if (rp_image_create(&img, 640, 300, background) != 0) return -1;
    rp_body_style styles[2];
    for (int b = 0; b < 2; ++b) {
        styles[b].body = bars[b];
        styles[b].colour[0] = styles[b].colour[1] = styles[b].colour[2] = 200;
        styles[b].node_scalar = velocity_x[b];
        styles[b].scalar_min = -kSpeed;
        styles[b].scalar_max = kSpeed;
        styles[b].draw_edges = 1;
    }
    const rp_camera camera = {{0.12, -0.52, 0.22}, {0.0, 0.0, -0.01}, {0, 0, 1}, 26};
    int status = rp_render_bodies(&img, world, styles, 2, &camera, background);
    if (status == 0) {
        /* Colour bar of the x velocity. */
        const int x0 = 170, x1 = 470, y0 = 250, y1 = 262;
        for (int x = x0; x <= x1; ++x) {
            unsigned char c[3];
            rp_colour_map((double)(x - x0) / (x1 - x0), c);
            rp_fill_rect(&img, x, y0, x, y1, c);
        }
        char label[96];
        snprintf(label, sizeof label, "%.2f", -kSpeed);
        rp_draw_text(&img, x0 - 8 - rp_text_width(2, label), y0 - 1, 2, label, black);
        snprintf(label, sizeof label, "+%.2f", kSpeed);
        rp_draw_text(&img, x1 + 8, y0 - 1, 2, label, black);
        rp_draw_text(&img, (x0 + x1 - rp_text_width(2, "X VELOCITY (M/S)")) / 2, y1 + 10, 2,
                     "X VELOCITY (M/S)", black);
        snprintf(label, sizeof label, "T = %.1f MICROSECONDS: WAVES RUNNING FROM THE CONTACT",
                 time_us);
        rp_draw_text(&img, 12, 12, 2, label, black);
        status = rp_image_write_png(&img, path);
    }
    rp_image_destroy(&img);
    return status;
}

int main(int argc, char** argv) {
    const char* pvd = argc > 1 ? argv[1] : "lfem_bar_impact/bar_impact.pvd";
    const double nu = argc > 2 ? atof(argv[2]) : 0.0;
    const int cells = argc > 3 ? atoi(argv[3]) : 40;
    if (cells < 1 || cells > 1000 || !(nu >= 0 && nu < 0.5)) {
        fprintf(stderr, "usage: bar_impact [output.pvd] [nu in [0, 0.5)] [cells along, 1..1000]\n");
        return 1;
    }
    const uint32_t across = cells / 10 > 0 ? (uint32_t)(cells / 10) : 1u;
    char csv_path[1024], plot_path[1024], key_path[1024];
    if (scene_make_output_folder(pvd) != 0 ||
        scene_sibling_path(pvd, "bar_impact.csv", csv_path, sizeof csv_path) != 0 ||
        scene_sibling_path(pvd, "bar_impact.png", plot_path, sizeof plot_path) != 0 ||
        scene_sibling_path(pvd, "bar_impact_keyframe.png", key_path, sizeof key_path) != 0)
        return 1;
    const analytic exact = analytic_solution();

    lfem_world_def world_def = lfem_world_def_default();
    world_def.gravity[2] = 0.0; /* the bars fly along x; gravity would only tilt them */
    lfem_world* world = NULL;
    CHECK(lfem_world_create(&world_def, &world));

    /* Bar 1 on the left moving +x, bar 2 on the right moving -x, centred on the x axis, the gap
     * split evenly about x = 0. */
    lfem_body_def def = lfem_body_def_default();
    def.model = LFEM_MODEL_PAPER;
    def.young_modulus = kYoung;
    def.poisson_ratio = nu;
    def.density = kDensity;
    def.friction = 0.0; /* the faces meet head on: friction would do nothing but cost work */
    lfem_body bars[2];
    for (int b = 0; b < 2; ++b) {
        const double height = b == 0 ? kHeight1 : kHeight2;
        const double size[3] = {kLength, kWidth, height};
        const uint32_t grid[3] = {(uint32_t)cells, across, across};
        const double offset[3] = {b == 0 ? -kLength - kGap / 2 : kGap / 2, -kWidth / 2, -height / 2};
        lfem_mesh* mesh = NULL;
        CHECK(lfem_mesh_create_box(size, grid, &mesh));
        CHECK(lfem_mesh_translate(mesh, offset));
        def.linear_velocity[0] = b == 0 ? kSpeed : -kSpeed;
        CHECK(lfem_body_create(world, &def, &bars[b]));
        CHECK(lfem_body_add_mesh(world, bars[b], lfem_mesh_get_positions(mesh),
                                 lfem_mesh_get_node_count(mesh), lfem_mesh_get_tets(mesh),
                                 lfem_mesh_get_tet_count(mesh)));
        lfem_mesh_destroy(mesh);
    }
    double mass[2], p0[2][3];
    uint32_t nodes[2];
    for (int b = 0; b < 2; ++b) {
        CHECK(lfem_body_get_mass(world, bars[b], &mass[b]));
        CHECK(lfem_body_get_momentum(world, bars[b], p0[b], NULL));
        CHECK(lfem_body_get_node_count(world, bars[b], &nodes[b]));
    }

    /* A fixed step, 0.9 of the stable limit: each step's contact force is then one sample of
     * the force-time curve, all of equal width. */
    double stable = 0;
    CHECK(lfem_world_get_stable_step(world, &stable));
    const double h = 0.9 * stable;
    const int steps = (int)ceil(kEndTime / h);
    printf("lfem %s two-bar impact: nu = %.2f, %dx%ux%u cells a bar, %u + %u nodes, step %.3g us, "
           "%d steps\n",
           lfem_version_string(), nu, cells, across, across, nodes[0], nodes[1], h * 1e6, steps);

    double* time_us = (double*)malloc(sizeof(double) * (size_t)steps);
    double* force_n = (double*)malloc(sizeof(double) * (size_t)steps);
    double* velocities[2] = {(double*)malloc(sizeof(double) * 3 * nodes[0]),
                             (double*)malloc(sizeof(double) * 3 * nodes[1])};
    double* velocity_x[2] = {(double*)malloc(sizeof(double) * nodes[0]),
                             (double*)malloc(sizeof(double) * nodes[1])};
    uint32_t contact_capacity = 1024;
    lfem_contact* contacts = (lfem_contact*)malloc(sizeof(lfem_contact) * contact_capacity);
    FILE* csv = fopen(csv_path, "w");
    if (!time_us || !force_n || !velocities[0] || !velocities[1] || !velocity_x[0] ||
        !velocity_x[1] || !contacts || !csv) {
        fprintf(stderr, "out of memory, or cannot write %s\n", csv_path);
        return 1;
    }
    /* time_us is the middle of the step's interval: the force of a step is the multiplier of
     * the forward increment, the impulse between t - h and t divided by h. */
    fprintf(csv, "time_us,force_N,analytic_N\n");

    lfem_vtk_series* series = NULL;
    CHECK(lfem_vtk_series_create(pvd, &series));
    CHECK(lfem_vtk_series_write_frame(series, world));
    int frames = 1, keyframe_written = 0;
    /* The key frame: half way through the first wave transit, when the compressed zones
     * (near zero velocity) reach half way along the bars. */
    const double keyframe_time = exact.start + 0.25 * exact.duration;
    double impulse = 0, plateau_sum = 0, plateau_time = 0, first = -1, last = -1,
           max_penetration = 0;
    const double start = scene_now();
    for (int k = 0; k < steps; ++k) {
        CHECK(lfem_world_step(world, h));
        lfem_world_stats s;
        CHECK(lfem_world_get_stats(world, &s));
        if (s.max_penetration > max_penetration) max_penetration = s.max_penetration;
        uint32_t count = 0;
        CHECK(scene_query_contacts(world, &contacts, &contact_capacity, &count));
        /* The force on bar 2 along +x: its nodes' contact forces, and the opposite of the
         * forces on bar 1's nodes (whose reaction lands on bar 2's triangles). */
        double force = 0;
        for (uint32_t c = 0; c < count; ++c)
            force += (contacts[c].body_a.index == bars[1].index ? 1.0 : -1.0) * contacts[c].force[0];
        impulse += force * h;
        if (force > 0) {
            if (first < 0) first = s.time - h;
            last = s.time;
        }
        if (s.time - h >= 40e-6 && s.time <= 110e-6) plateau_sum += force * h, plateau_time += h;
        time_us[k] = (s.time - 0.5 * h) * 1e6;
        force_n[k] = force;
        fprintf(csv, "%.6f,%.3f,%.3f\n", time_us[k], force, analytic_force(&exact, s.time - 0.5 * h));

        if (!keyframe_written && s.time >= keyframe_time) {
            for (int b = 0; b < 2; ++b) {
                CHECK(lfem_body_get_velocities(world, bars[b], velocities[b], nodes[b]));
                for (uint32_t i = 0; i < nodes[b]; ++i) velocity_x[b][i] = velocities[b][3 * i];
            }
            if (write_keyframe(key_path, world, bars, velocity_x, s.time * 1e6) != 0) return 1;
            keyframe_written = 1;
        }
        /* A frame every 5 us (and the last step), with a progress line. */
        if ((int)(s.time / 5e-6) != (int)((s.time - h) / 5e-6) || k + 1 == steps) {
            CHECK(lfem_vtk_series_write_frame(series, world));
            ++frames;
            printf("t = %6.1f us  contacts %4u  force on bar 2 %9.1f N  kinetic %8.3f J  strain "
                   "%8.3f J  max penetration %.1e m  %.2f s wall\n",
                   s.time * 1e6, s.contact_count, force, s.kinetic_energy, s.strain_energy,
                   s.max_penetration, scene_now() - start);
        }
    }
    if (fclose(csv) != 0) {
        fprintf(stderr, "cannot write %s\n", csv_path);
        return 1;
    }
    double p[2][3];
    for (int b = 0; b < 2; ++b) CHECK(lfem_body_get_momentum(world, bars[b], p[b], NULL));
    const double plateau = plateau_time > 0 ? plateau_sum / plateau_time : 0;
    const double duration = first >= 0 ? last - first : 0;
    const double v1 = p[0][0] / mass[0], v2 = p[1][0] / mass[1];
    printf("impulse   %9.4f N s  (1-D %9.4f N s, %+.2f %%); bar 2's momentum change %.4f N s\n",
           impulse, exact.impulse, 100 * (impulse / exact.impulse - 1), p[1][0] - p0[1][0]);
    printf("plateau   %9.2f kN   (1-D %9.2f kN,  %+.2f %%), mean force from 40 to 110 us\n",
           plateau / 1e3, exact.force / 1e3, 100 * (plateau / exact.force - 1));
    printf("duration  %9.2f us   (1-D %9.2f us,  %+.2f %%), from %.2f us (1-D %.2f us)\n",
           duration * 1e6, exact.duration * 1e6, 100 * (duration / exact.duration - 1), first * 1e6,
           exact.start * 1e6);
    printf("velocity  bar 1 %+.4f m/s (1-D %+.4f), bar 2 %+.4f m/s (1-D %+.4f)\n", v1, exact.v1, v2,
           exact.v2);
    printf("max penetration %.2e m; %.2f s wall\n", max_penetration, scene_now() - start);

    if (write_plot(plot_path, &exact, time_us, force_n, steps, nu, cells) != 0) return 1;
    printf("force-time curve: %s (plot %s); key frame: %s; ParaView series: %s (%d frames)\n",
           csv_path, plot_path, key_path, pvd, frames);

    lfem_vtk_series_destroy(series);
    lfem_world_destroy(world);
    free(time_us);
    free(force_n);
    for (int b = 0; b < 2; ++b) free(velocities[b]), free(velocity_x[b]);
    free(contacts);
    return 0;
}
