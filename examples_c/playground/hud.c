/* hud: see hud.h. */
#include "hud.h"

#include <stdio.h>

void pg_stats_add(pg_stats* stats, double ms, uint32_t substeps) {
    stats->ms[stats->next] = ms;
    stats->substeps[stats->next] = substeps;
    stats->next = (stats->next + 1) % PG_HISTORY;
    if (stats->count < PG_HISTORY) stats->count++;
    stats->frames++;
    stats->total_ms += ms;
    if (ms > stats->worst_ms) stats->worst_ms = ms;
    stats->total_substeps += substeps;
    if (substeps > stats->max_substeps) stats->max_substeps = substeps;
}

void pg_stats_recent(const pg_stats* stats, double* mean_ms, double* worst_ms, double* mean_substeps) {
    double sum = 0, worst = 0, steps = 0;
    for (int i = 0; i < stats->count; ++i) {
        sum += stats->ms[i];
        steps += stats->substeps[i];
        if (stats->ms[i] > worst) worst = stats->ms[i];
    }
    const int n = stats->count > 0 ? stats->count : 1;
    *mean_ms = sum / n;
    *worst_ms = worst;
    *mean_substeps = steps / n;
}

void pg_hud_lines(const pg_stats* stats, const pg_room* room, int paused,
                  char lines[PG_HUD_LINES][PG_HUD_CHARS]) {
    double mean = 0, worst = 0, substeps = 0;
    pg_stats_recent(stats, &mean, &worst, &substeps);
    lfem_world_stats ws;
    if (lfem_world_get_stats(room->world, &ws) != LFEM_OK) ws.contact_count = 0, ws.time = 0;
    snprintf(lines[0], PG_HUD_CHARS, "PHYSICS %.2f MS/FRAME (WORST %.2f)%s", mean, worst,
             paused ? "  PAUSED" : "");
    snprintf(lines[1], PG_HUD_CHARS, "SUB-STEPS %.1f PER FRAME, 60 FRAMES/S OF SIMULATED TIME", substeps);
    snprintf(lines[2], PG_HUD_CHARS, "T = %.2f S  CONTACTS %u  IMPACTS %llu  ASLEEP %d OF %d", ws.time,
             ws.contact_count, (unsigned long long)room->impacts, pg_room_sleeping(room), room->body_count);
    snprintf(lines[3], PG_HUD_CHARS, "FPS %.0f", stats->fps);
    snprintf(lines[4], PG_HUD_CHARS, "LEFT DRAG: GRAB AND THROW   RIGHT DRAG: TURN   R: RESET   ESC: QUIT");
}
