/* Drawing the room with OpenGL 2.1's fixed function (what Mesa's llvmpipe gives under Xvfb):
 * the shapes and the bodies' skins lit by one light with smooth normals, the grab point, and
 * the HUD in the 5x7 font of render_png. */
#ifndef LFEM_PLAYGROUND_DRAW_H
#define LFEM_PLAYGROUND_DRAW_H

#include "grab.h"
#include "hud.h"
#include "pg_math.h"
#include "room.h"

/* The background, also what a frame with nothing drawn shows. */
extern const float pg_clear_colour[3];

void pg_draw_init(void);
/* Clears the frame and draws the room from the camera (grab nullable). */
void pg_draw_scene(const pg_room* room, const pg_camera* camera, const pg_grab* grab);
/* The HUD: lines at the top left, the last one (the controls) at the bottom. */
void pg_draw_hud(char lines[PG_HUD_LINES][PG_HUD_CHARS], int width, int height);

#endif
