/* The playground's world: a room (a floor and walls, static plane shapes), a few static rigid
 * shapes (a box, a sphere, a capsule, a ramp), a rigid crate, and soft bodies (jelly cubes and
 * a soft bar) each drawn through a skin: a rounded, finer render mesh bound to its tets. */
#ifndef LFEM_PLAYGROUND_ROOM_H
#define LFEM_PLAYGROUND_ROOM_H

#include <stdio.h>

#include "lfem.h"
#include "meshes.h"

/* Every lfem call of the playground is checked: on failure, say which call and why, and
 * return -1 from the calling function. */
#define PG_TRY(call)                                                                 \
    do {                                                                             \
        lfem_status s_ = (call);                                                     \
        if (s_ != LFEM_OK) {                                                         \
            fprintf(stderr, "playground: %s failed: %s\n", #call, lfem_last_error()); \
            return -1;                                                               \
        }                                                                            \
    } while (0)

enum { PG_MAX_BODIES = 8, PG_MAX_SHAPES = 16 };

/* Collision categories: the room's floor and walls are PG_ROOM_CATEGORY, everything else the
 * bodies' default 1 (PG_PICKABLE), and every mask is all bits, so all of it collides; the
 * hand's ray sees only PG_PICKABLE. */
enum { PG_PICKABLE = 1, PG_ROOM_CATEGORY = 2 };

typedef struct pg_body {
    lfem_body body;
    int deformable;      /* 1: the mouse may grab it (attachments hold deformable bodies) */
    float colour[3];
    pg_mesh skin;        /* the skin's triangles, and its vertices as read after each frame */
    float flash;         /* up to 1 right after an impact (by its speed), fading to 0 */
    double* start;       /* its nodes as built (3 per node): a reset teleports it back */
    uint32_t node_count;
} pg_body;

/* A static shape as drawn: its surface in world coordinates. */
typedef struct pg_shape {
    pg_mesh mesh;
    float colour[3];
} pg_shape;

typedef struct pg_room {
    lfem_world* world;
    pg_body bodies[PG_MAX_BODIES];
    int body_count;
    pg_shape shapes[PG_MAX_SHAPES];
    int shape_count;
    lfem_event* events;  /* the last step's events (grown as needed) */
    uint32_t event_capacity, event_count;
    uint64_t impacts;    /* contacts begun fast enough for a flash, since the start */
} pg_room;

/* Builds the room on a world of thread_count threads. Returns 0, or -1 after printing why. */
int pg_room_create(pg_room* room, uint32_t thread_count);
void pg_room_destroy(pg_room* room);

/* Puts every body back where it was built, at rest, by teleports (lfem_body_set_positions for
 * a soft body, its shape as built; lfem_body_set_transform for the crate; then zero velocities):
 * the world, its handles and skins stay. Returns 0, or -1 after printing why. */
int pg_room_reset(pg_room* room);

/* One frame of the game loop's physics: lfem_world_step(dt), then the events (impacts counted,
 * the bodies hit flashed). Returns lfem_world_step's status (the world is rolled back on
 * failure), or LFEM_OUT_OF_MEMORY when the events' buffer cannot grow. */
lfem_status pg_room_step(pg_room* room, double dt);

/* Reads every skin's deformed vertices and normals into its vertex buffer (before drawing).
 * Returns 0, or -1 after printing why. */
int pg_room_read_skins(pg_room* room);

/* The room's record of body, or NULL when it is not one of the room's. */
pg_body* pg_room_find(pg_room* room, lfem_body body);

/* The number of bodies asleep (the HUD shows it). */
int pg_room_sleeping(const pg_room* room);

#endif
