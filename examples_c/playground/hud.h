/* What the HUD shows: the physics' wall time per frame (the lfem_world_step calls of a frame)
 * and its sub-steps, over the last second and over the whole run. */
#ifndef LFEM_PLAYGROUND_HUD_H
#define LFEM_PLAYGROUND_HUD_H

#include <stdint.h>

#include "room.h"

enum { PG_HISTORY = 60, PG_HUD_LINES = 5, PG_HUD_CHARS = 96 };

typedef struct pg_stats {
    double ms[PG_HISTORY];        /* physics ms of the last frames (a ring) */
    uint32_t substeps[PG_HISTORY];
    int count, next;
    uint64_t frames;              /* since the start */
    double total_ms, worst_ms;    /* since the start */
    uint64_t total_substeps;
    uint32_t max_substeps;
    double fps;                   /* frames drawn per second of wall time (interactive) */
} pg_stats;

void pg_stats_add(pg_stats* stats, double ms, uint32_t substeps);
/* Mean and worst of the last PG_HISTORY frames. */
void pg_stats_recent(const pg_stats* stats, double* mean_ms, double* worst_ms, double* mean_substeps);

/* The HUD's lines (upper case: the 5x7 font has no lower case). */
void pg_hud_lines(const pg_stats* stats, const pg_room* room, int paused,
                  char lines[PG_HUD_LINES][PG_HUD_CHARS]);

#endif
