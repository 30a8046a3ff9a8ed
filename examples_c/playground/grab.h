/* The mouse's hand: a ray cast picks the soft body under the cursor, an attachment to a frame
 * (lfem_attachment_create with the null target) holds the boundary nodes around the point hit,
 * the frame follows the cursor in the plane through that point facing the camera, and letting
 * go destroys the attachment: the body keeps the velocity it was dragged with (the throw). The
 * rigid crate is held by making it kinematic (lfem_body_set_type) and giving it the velocity
 * that carries the point hit to the cursor each tick; letting go makes it rigid again, at that
 * velocity. */
#ifndef LFEM_PLAYGROUND_GRAB_H
#define LFEM_PLAYGROUND_GRAB_H

#include "room.h"

typedef struct pg_grab {
    int active;
    int rigid;               /* 1: the crate, made kinematic while held */
    lfem_attachment attachment;
    lfem_body body;
    uint32_t node_count;     /* nodes held */
    double point[3];         /* where the frame is (m): the hit point, then the cursor's */
    double plane_normal[3];  /* the camera's forward direction when the body was grabbed */
    double last_move[3];     /* how far the frame was moved for the last tick (m) */
} pg_grab;

/* Casts the ray (unit direction) and grabs the deformable body it hits first, its drag plane
 * facing `forward`. Returns 1 when a body was grabbed, 0 when the ray hits nothing or something
 * that cannot be held (a wall, a shape), -1 after printing why a call failed. */
int pg_grab_begin(pg_grab* grab, pg_room* room, const double origin[3], const double direction[3],
                  const double forward[3]);

/* Moves the frame to where the ray crosses the drag plane, by at most max_move (m) this frame:
 * the next lfem_world_step of dt carries the held nodes there (the crate: at that velocity).
 * 0, or -1 after printing why. */
int pg_grab_drag(pg_grab* grab, pg_room* room, const double origin[3], const double direction[3],
                 double max_move, double dt);

/* Lets go. velocity (nullable) receives the body's velocity at release (momentum / mass, m/s).
 * 0, or -1 after printing why. */
int pg_grab_release(pg_grab* grab, pg_room* room, double velocity[3]);

#endif
