/* What the mouse points at: the first surface along a ray. */
#ifndef LFEM_PLAYGROUND_PICK_H
#define LFEM_PLAYGROUND_PICK_H

#include "room.h"

typedef struct pg_hit {
    lfem_body body;
    uint32_t triangle;  /* the body's boundary triangle hit (UINT32_MAX: one of its shapes) */
    double point[3];    /* m */
    double distance;    /* m along the unit ray */
} pg_hit;

/* 1 and *hit when the ray (unit direction) meets something, 0 when not, -1 after printing why
 * a call failed. */
int pg_pick(pg_room* room, const double origin[3], const double direction[3], pg_hit* hit);

#endif
