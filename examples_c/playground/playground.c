/* playground: an interactive lfem scene in a window (SDL2 + OpenGL). Soft jelly bodies, a
 * rigid crate with a soft tail held to it by springs, and static shapes in a room; grab a soft
 * body or the crate with the mouse and throw it.
 *
 *   playground [--threads N]                    play (see the HUD for the controls)
 *   playground --headless N out.png [--blank]   N frames offscreen (under xvfb-run), a
 *                                                scripted grab and throw, a reset, the crate
 *                                                lifted with its tail, the last frame
 *                                                written as out.png, the HUD's figures printed
 *
 * The physics runs as a game's does: lfem_world_step(world, 1/60) once per 60 Hz tick of a
 * fixed-step accumulator (at most 4 ticks a drawn frame). Headless, each frame is one tick. */
#include <SDL.h>
#include <SDL_opengl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "draw.h"
#include "grab.h"
#include "hud.h"
#include "render_png.h"
#include "room.h"

static const double kTick = 1.0 / 60.0;
static const double kMaxMove = 0.25; /* m a tick the hand may move (15 m/s): a flick of the
                                        mouse across the window is not a teleport */

typedef struct app {
    pg_room room;
    pg_camera camera;
    pg_grab grab;
    pg_stats stats;
    uint32_t threads;
    int paused;
    double mouse[2];  /* where the cursor is, pixels */
    double released_velocity[3];
    int grabs, throws;
} app;

static double now_seconds(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void default_camera(pg_camera* c, int width, int height) {
    v3_set(c->target, 0, 0.5, 0.45);
    c->distance = 5.2;
    c->yaw = 0;
    c->pitch = 0.36;
    c->fov_y = 50 * PG_PI / 180;
    c->width = width;
    c->height = height;
}

/* Everything back where it was built, by teleports: the world and its handles stay. */
static int reset(app* a) {
    double ignored[3];
    if (a->grab.active && pg_grab_release(&a->grab, &a->room, ignored) != 0) return -1;
    memset(&a->grab, 0, sizeof a->grab);
    const double fps = a->stats.fps;
    memset(&a->stats, 0, sizeof a->stats); /* the HUD's figures start again */
    a->stats.fps = fps;
    return pg_room_reset(&a->room);
}

/* The mouse, or the headless script through the same calls. */
static int press(app* a, double x, double y) {
    double origin[3], direction[3], eye[3], forward[3], right[3], up[3];
    camera_ray(&a->camera, x, y, origin, direction);
    camera_frame(&a->camera, eye, forward, right, up);
    const int grabbed = pg_grab_begin(&a->grab, &a->room, origin, direction, forward);
    a->grabs += grabbed == 1;
    return grabbed < 0 ? -1 : 0;
}

static int release(app* a) {
    if (!a->grab.active) return 0;
    a->throws++;
    return pg_grab_release(&a->grab, &a->room, a->released_velocity);
}

/* One 60 Hz tick: the hand follows the cursor, the world steps, the HUD's figures are kept. */
static int tick(app* a) {
    if (a->grab.active) {
        double origin[3], direction[3];
        camera_ray(&a->camera, a->mouse[0], a->mouse[1], origin, direction);
        if (pg_grab_drag(&a->grab, &a->room, origin, direction, kMaxMove, kTick) != 0) return -1;
    }
    lfem_world_stats ws;
    const double t0 = now_seconds();
    const lfem_status s = pg_room_step(&a->room, kTick);
    const double ms = 1e3 * (now_seconds() - t0);
    if (s != LFEM_OK || lfem_world_get_stats(a->room.world, &ws) != LFEM_OK) {
        fprintf(stderr, "playground: the step failed (%s): %s\n", lfem_status_string(s), lfem_last_error());
        return -1;
    }
    pg_stats_add(&a->stats, ms, ws.substeps_last_call);
    return 0;
}

static int draw_frame(app* a, int hud) {
    if (pg_room_read_skins(&a->room) != 0) return -1;
    pg_draw_scene(&a->room, &a->camera, &a->grab);
    if (hud) {
        char lines[PG_HUD_LINES][PG_HUD_CHARS];
        pg_hud_lines(&a->stats, &a->room, a->paused, lines);
        pg_draw_hud(lines, a->camera.width, a->camera.height);
    }
    return 0;
}

/* ---------------------------------------------------------------------------------------- */
/* Headless: a scripted hand, the last frame as a PNG                                         */
/* ---------------------------------------------------------------------------------------- */

/* The script: at kPressFrame the cursor presses where the first jelly cube's centre is seen,
 * lifts it for kLiftFrames ticks, swings it right for kSwingFrames and lets go; at kResetFrame
 * the room is reset (teleports), and every body must then be where it was built, at rest. */
enum { kPressFrame = 40, kLiftFrames = 30, kSwingFrames = 20, kResetFrame = 105 };
/* Then the crate is grabbed (made kinematic) and lifted for kCrateLift ticks and let go: the soft
 * tail held to it by springs must come along. */
enum { kCratePress = 107, kCrateLift = 8 };

static int check_reset(app* a, int frame) {
    if (reset(a) != 0) return -1;
    int back = 0;
    for (int i = 0; i < a->room.body_count; ++i) {
        const pg_body* b = &a->room.bodies[i];
        double* x = (double*)malloc(sizeof(double) * 6 * b->node_count);
        int same = x && lfem_body_get_positions(a->room.world, b->body, x, b->node_count) == LFEM_OK &&
                   lfem_body_get_velocities(a->room.world, b->body, x + 3 * b->node_count, b->node_count) == LFEM_OK;
        /* Soft bodies: their nodes exactly; the crate: placed by its pose, to round-off. */
        for (uint32_t k = 0; same && k < 3 * b->node_count; ++k)
            same = fabs(x[k] - b->start[k]) <= (b->deformable ? 0.0 : 1e-12) && x[3 * b->node_count + k] == 0.0;
        free(x);
        back += same;
    }
    printf("reset: frame %d, %d of %d bodies back where they were built, at rest\n", frame, back, a->room.body_count);
    return back == a->room.body_count ? 0 : -1;
}

static int body_centre(const pg_room* room, lfem_body body, double centre[3]) {
    uint32_t n = 0;
    if (lfem_body_get_node_count(room->world, body, &n) != LFEM_OK || n == 0) return -1;
    double* x = (double*)malloc(sizeof(double) * 3 * n);
    const int ok = x && lfem_body_get_positions(room->world, body, x, n) == LFEM_OK;
    v3_set(centre, 0, 0, 0);
    for (uint32_t i = 0; ok && i < n; ++i) v3_add_scaled(centre, 1.0 / n, x + 3 * i, centre);
    free(x);
    return ok ? 0 : -1;
}

/* 0 to 1 with zero speed at both ends, as a hand moves. */
static double ease(double u) { return u * u * (3 - 2 * u); }

/* The crate's part of the script. */
static int crate_script(app* a, int frame) {
    static double start_y, crate0[3], tail0[3];
    const lfem_body crate = a->room.bodies[4].body, tail = a->room.bodies[5].body;
    if (frame == kCratePress) {
        if (body_centre(&a->room, crate, crate0) != 0 || body_centre(&a->room, tail, tail0) != 0 ||
            !camera_project(&a->camera, crate0, &a->mouse[0], &a->mouse[1]))
            return -1;
        start_y = a->mouse[1];
        if (press(a, a->mouse[0], a->mouse[1]) != 0) return -1;
        printf("grab: frame %d: %s\n", frame, a->grab.active && a->grab.rigid ? "the crate, made kinematic" : "not the crate");
        return a->grab.active && a->grab.rigid ? 0 : -1;
    }
    const int k = frame - kCratePress;
    if (k > 0 && k <= kCrateLift) a->mouse[1] = start_y - 0.2 * a->camera.height * ease((double)k / kCrateLift);
    if (k != kCrateLift + 1) return 0;
    if (release(a) != 0) return -1;
    lfem_body_type type = LFEM_BODY_KINEMATIC;
    double crate1[3], tail1[3];
    if (lfem_body_get_type(a->room.world, crate, &type) != LFEM_OK || body_centre(&a->room, crate, crate1) != 0 ||
        body_centre(&a->room, tail, tail1) != 0)
        return -1;
    const double rose = crate1[2] - crate0[2], tail_rose = tail1[2] - tail0[2];
    printf("crate: frame %d, lifted %.3f m and let go (%s again); the tail held to it rose %.3f m\n", frame, rose,
           type == LFEM_BODY_RIGID ? "rigid" : "not rigid", tail_rose);
    /* The hand lifts it by tens of centimetres in 8 ticks; a tail the springs did not carry
     * would lie on the floor (0 m): a tenth of the crate's rise tells the two apart. */
    return rose > 0.02 && tail_rose > 0.1 * rose && type == LFEM_BODY_RIGID ? 0 : -1;
}

static int script(app* a, int frame) {
    static double start[2];
    if (frame == kResetFrame) return check_reset(a, frame);
    if (frame >= kCratePress) return crate_script(a, frame);
    const double lift = 0.30 * a->camera.height, swing = 0.22 * a->camera.width;
    if (frame == kPressFrame) {
        double centre[3];
        if (body_centre(&a->room, a->room.bodies[0].body, centre) != 0 ||
            !camera_project(&a->camera, centre, &a->mouse[0], &a->mouse[1]))
            return -1;
        start[0] = a->mouse[0], start[1] = a->mouse[1];
        if (press(a, a->mouse[0], a->mouse[1]) != 0) return -1;
        printf("grab: frame %d, cursor at (%.0f, %.0f): %s, %u nodes held\n", frame, a->mouse[0],
               a->mouse[1], a->grab.active ? "a jelly cube" : "nothing grabbable", a->grab.node_count);
        return a->grab.active ? 0 : -1;
    }
    const int k = frame - kPressFrame;
    if (k > 0 && k <= kLiftFrames) {
        a->mouse[1] = start[1] - lift * ease((double)k / kLiftFrames);
    } else if (k > kLiftFrames && k <= kLiftFrames + kSwingFrames) {
        /* speeding up all the way: the throw leaves at the swing's fastest */
        const double u = (double)(k - kLiftFrames) / kSwingFrames;
        a->mouse[0] = start[0] + swing * u * u;
    } else if (k == kLiftFrames + kSwingFrames + 1) {
        const double hand = v3_length(a->grab.last_move) / kTick;
        if (release(a) != 0) return -1;
        const double* v = a->released_velocity;
        printf("throw: frame %d, the hand at %.2f m/s, the cube released at %.2f m/s (%.2f, %.2f, %.2f)\n",
               frame, hand, v3_length(v), v[0], v[1], v[2]);
        /* The held patch moves with the hand, and after 20 ticks of swinging the soft cube
         * moves with its grip up to its own wobble; a cube the attachment did not carry would
         * lie where it was, at rest. Half the hand's speed tells the two apart. */
        if (!(v3_length(v) >= 0.5 * hand)) {
            fprintf(stderr, "playground: the throw did not carry the cube (%.2f m/s for a hand at %.2f)\n",
                    v3_length(v), hand);
            return -1;
        }
    }
    return 0;
}

static int write_screenshot(int width, int height, const char* path) {
    unsigned char* rows = (unsigned char*)malloc((size_t)width * height * 3);
    rp_image image = {0, 0, NULL};
    const unsigned char black[3] = {0, 0, 0};
    if (!rows || rp_image_create(&image, width, height, black) != 0) {
        free(rows);
        return -1;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows);
    for (int y = 0; y < height; ++y) /* OpenGL's rows run bottom to top, PNG's top to bottom */
        memcpy(image.rgb + (size_t)y * width * 3, rows + (size_t)(height - 1 - y) * width * 3, (size_t)width * 3);
    const int result = rp_image_write_png(&image, path);
    rp_image_destroy(&image);
    free(rows);
    return result;
}

static void print_summary(const app* a, int frames) {
    double mean = 0, worst = 0, substeps = 0;
    pg_stats_recent(&a->stats, &mean, &worst, &substeps);
    lfem_world_stats ws;
    lfem_world_get_stats(a->room.world, &ws);
    const pg_stats* s = &a->stats;
    printf("frames: %d at 60 Hz (%.3f s simulated), %d bodies, %u thread(s)\n", frames, ws.time,
           a->room.body_count, a->threads);
    printf("physics ms per frame: mean %.3f, worst %.3f (last %d frames: mean %.3f, worst %.3f)\n",
           s->frames ? s->total_ms / (double)s->frames : 0.0, s->worst_ms, s->count, mean, worst);
    printf("sub-steps per frame: mean %.2f, max %u\n", s->frames ? (double)s->total_substeps / (double)s->frames : 0.0,
           s->max_substeps);
    printf("contacts now: %u, impacts: %llu, asleep: %d of %d\n", ws.contact_count,
           (unsigned long long)a->room.impacts, pg_room_sleeping(&a->room), a->room.body_count);
}

static int run_headless(app* a, SDL_Window* window, int frames, const char* png, int blank) {
    const double start = now_seconds();
    for (int frame = 0; frame < frames; ++frame) {
        if (frame > 0) a->stats.fps = frame / (now_seconds() - start); /* offscreen frames drawn */
        if (script(a, frame) != 0) {
            fprintf(stderr, "playground: the scripted grab and throw failed at frame %d\n", frame);
            return 1;
        }
        if (tick(a) != 0) return 1;
        if (blank) {
            glClearColor(pg_clear_colour[0], pg_clear_colour[1], pg_clear_colour[2], 1);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        } else if (draw_frame(a, 1) != 0) {
            return 1;
        }
        if (frame + 1 == frames && write_screenshot(a->camera.width, a->camera.height, png) != 0) return 1;
        SDL_GL_SwapWindow(window);
    }
    print_summary(a, frames);
    printf("wrote %s (%dx%d)%s\n", png, a->camera.width, a->camera.height, blank ? ", blank on purpose" : "");
    return 0;
}

/* ---------------------------------------------------------------------------------------- */
/* Interactive                                                                                */
/* ---------------------------------------------------------------------------------------- */

/* Handles one SDL event; returns 0 to go on, 1 to quit, -1 on failure. */
static int handle_event(app* a, const SDL_Event* e, int* turning) {
    switch (e->type) {
    case SDL_QUIT: return 1;
    case SDL_KEYDOWN:
        if (e->key.keysym.sym == SDLK_ESCAPE) return 1;
        if (e->key.keysym.sym == SDLK_r) return reset(a) == 0 ? 0 : -1;
        if (e->key.keysym.sym == SDLK_SPACE) a->paused = !a->paused;
        return 0;
    case SDL_MOUSEBUTTONDOWN:
        a->mouse[0] = e->button.x, a->mouse[1] = e->button.y;
        if (e->button.button == SDL_BUTTON_LEFT) return press(a, e->button.x, e->button.y);
        if (e->button.button == SDL_BUTTON_RIGHT) *turning = 1;
        return 0;
    case SDL_MOUSEBUTTONUP:
        if (e->button.button == SDL_BUTTON_LEFT) return release(a);
        if (e->button.button == SDL_BUTTON_RIGHT) *turning = 0;
        return 0;
    case SDL_MOUSEMOTION:
        a->mouse[0] = e->motion.x, a->mouse[1] = e->motion.y;
        if (*turning) {
            a->camera.yaw += 0.006 * e->motion.xrel;
            a->camera.pitch = fmin(1.45, fmax(0.02, a->camera.pitch + 0.006 * e->motion.yrel));
        }
        return 0;
    case SDL_MOUSEWHEEL:
        a->camera.distance = fmin(12, fmax(1.5, a->camera.distance * pow(0.9, e->wheel.y)));
        return 0;
    default: return 0;
    }
}

static int run_interactive(app* a, SDL_Window* window) {
    double last = now_seconds(), behind = 0, fps_since = last;
    int turning = 0, drawn = 0;
    for (;;) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            const int r = handle_event(a, &e, &turning);
            if (r != 0) return r < 0;
        }
        int w = 0, h = 0;
        SDL_GL_GetDrawableSize(window, &w, &h);
        if (w > 0 && h > 0) a->camera.width = w, a->camera.height = h;
        /* The fixed-step accumulator of a game loop: wall time owed to the simulation is paid
         * in 60 Hz ticks; at most 4 a frame, the rest dropped (a slow frame slows the world
         * down rather than piling up steps). */
        const double t = now_seconds();
        behind += fmin(t - last, 0.25);
        last = t;
        int ticks = 0;
        while (behind >= kTick && ticks < 4) {
            if (!a->paused && tick(a) != 0) return 1;
            behind -= kTick;
            ticks++;
        }
        if (ticks == 4 || a->paused) behind = 0;
        if (draw_frame(a, 1) != 0) return 1;
        SDL_GL_SwapWindow(window);
        drawn++;
        if (t - fps_since >= 0.5) a->stats.fps = drawn / (t - fps_since), drawn = 0, fps_since = t;
    }
}

static int usage(void) {
    fprintf(stderr, "usage: playground [--threads N] [--headless FRAMES out.png [--blank]]\n");
    return 2;
}

int main(int argc, char** argv) {
    int frames = -1, blank = 0;
    const char* png = NULL;
    app a;
    memset(&a, 0, sizeof a);
    a.threads = 1;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--headless") && i + 2 < argc) {
            frames = atoi(argv[++i]);
            png = argv[++i];
            if (frames < 1) return usage();
        } else if (!strcmp(argv[i], "--threads") && i + 1 < argc) {
            a.threads = (uint32_t)atoi(argv[++i]);
        } else if (!strcmp(argv[i], "--blank")) {
            blank = 1;
        } else {
            return usage();
        }
    }
    const int width = 960, height = 540;
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, "playground: SDL_Init failed: %s\n", SDL_GetError());
        return 1;
    }
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
    SDL_Window* window = SDL_CreateWindow("lfem playground", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                          width, height, SDL_WINDOW_OPENGL | (png ? 0 : SDL_WINDOW_RESIZABLE));
    SDL_GLContext gl = window ? SDL_GL_CreateContext(window) : NULL;
    if (!gl) {
        fprintf(stderr, "playground: no OpenGL window: %s\n", SDL_GetError());
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }
    SDL_GL_SetSwapInterval(png ? 0 : 1);
    printf("OpenGL: %s, %s\n", (const char*)glGetString(GL_RENDERER), (const char*)glGetString(GL_VERSION));
    pg_draw_init();
    default_camera(&a.camera, width, height);
    int result = pg_room_create(&a.room, a.threads) == 0 ? 0 : 1;
    if (result == 0) result = png ? run_headless(&a, window, frames, png, blank) : run_interactive(&a, window);
    pg_room_destroy(&a.room);
    SDL_GL_DeleteContext(gl);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return result;
}
