/* draw: see draw.h. */
#include "draw.h"

#include <SDL_opengl.h>
#include <string.h>

#include "render_png.h"

const float pg_clear_colour[3] = {0.60f, 0.68f, 0.78f};

void pg_draw_init(void) {
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE); /* skins and shapes are closed and counter-clockwise outside */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glShadeModel(GL_SMOOTH);
    const GLfloat ambient[4] = {0.32f, 0.32f, 0.34f, 1}, diffuse[4] = {0.80f, 0.78f, 0.74f, 1};
    const GLfloat specular[4] = {0.35f, 0.35f, 0.35f, 1};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, specular);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.004f);
}

/* gluPerspective and gluLookAt written out, from the camera's frame (no GLU needed). */
static void load_camera(const pg_camera* c) {
    const double near_z = 0.05, far_z = 60, t = tan(0.5 * c->fov_y) * near_z;
    const double aspect = (double)c->width / c->height;
    glViewport(0, 0, c->width, c->height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-t * aspect, t * aspect, -t, t, near_z, far_z);
    double eye[3], f[3], r[3], u[3];
    camera_frame(c, eye, f, r, u);
    const GLdouble view[16] = {r[0], u[0], -f[0], 0, r[1], u[1], -f[1], 0, r[2], u[2], -f[2], 0,
                               -v3_dot(r, eye), -v3_dot(u, eye), v3_dot(f, eye), 1};
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(view);
    const GLfloat light[4] = {1.5f, -2.0f, 4.5f, 1}; /* a lamp above the camera's left */
    glLightfv(GL_LIGHT0, GL_POSITION, light);
}

static void draw_mesh(const pg_mesh* mesh) {
    glInterleavedArrays(GL_N3F_V3F, 0, mesh->vertices);
    glDrawElements(GL_TRIANGLES, (GLsizei)(3 * mesh->triangle_count), GL_UNSIGNED_INT, mesh->triangles);
}

static void draw_marker(const double p[3]) {
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glPointSize(9);
    glColor3f(1.0f, 0.95f, 0.2f);
    glBegin(GL_POINTS);
    glVertex3dv(p);
    glEnd();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
}

void pg_draw_scene(const pg_room* room, const pg_camera* camera, const pg_grab* grab) {
    glClearColor(pg_clear_colour[0], pg_clear_colour[1], pg_clear_colour[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    load_camera(camera);
    const GLfloat no_shine[4] = {0, 0, 0, 1}, shine[4] = {0.6f, 0.6f, 0.6f, 1};
    glMaterialfv(GL_FRONT, GL_SPECULAR, no_shine);
    for (int i = 0; i < room->shape_count; ++i) {
        glColor3fv(room->shapes[i].colour);
        draw_mesh(&room->shapes[i].mesh);
    }
    /* Jelly is glossy; an impact flashes the body towards white for a third of a second. */
    glMaterialfv(GL_FRONT, GL_SPECULAR, shine);
    glMaterialf(GL_FRONT, GL_SHININESS, 40);
    for (int i = 0; i < room->body_count; ++i) {
        const pg_body* b = &room->bodies[i];
        float c[3];
        for (int k = 0; k < 3; ++k) c[k] = b->colour[k] + 0.6f * b->flash * (1 - b->colour[k]);
        glColor3fv(c);
        draw_mesh(&b->skin);
    }
    if (grab && grab->active) draw_marker(grab->point);
}

static void draw_text(int x, int y, int scale, const char* text) {
    glBegin(GL_QUADS);
    for (; *text; ++text, x += 6 * scale) {
        const unsigned char* glyph = rp_glyph(*text);
        if (!glyph) continue;
        for (int row = 0; row < 7; ++row)
            for (int col = 0; col < 5; ++col) {
                if (!(glyph[row] & (0x10 >> col))) continue;
                const int px = x + col * scale, py = y + row * scale;
                glVertex2i(px, py), glVertex2i(px + scale, py);
                glVertex2i(px + scale, py + scale), glVertex2i(px, py + scale);
            }
    }
    glEnd();
}

void pg_draw_hud(char lines[PG_HUD_LINES][PG_HUD_CHARS], int width, int height) {
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, width, height, 0, -1, 1); /* pixels, y down */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    enum { kScale = 2, kLine = 18 };
    int longest = 0;
    for (int i = 0; i + 1 < PG_HUD_LINES; ++i) {
        const int w = rp_text_width(kScale, lines[i]);
        if (w > longest) longest = w;
    }
    glColor4f(0.05f, 0.07f, 0.10f, 0.6f);
    glRecti(6, 6, 18 + longest, 14 + kLine * (PG_HUD_LINES - 1));
    glRecti(6, height - 30, 18 + rp_text_width(kScale, lines[PG_HUD_LINES - 1]), height - 6);
    glDisable(GL_BLEND);
    glColor3f(1.0f, 1.0f, 0.92f);
    for (int i = 0; i + 1 < PG_HUD_LINES; ++i) draw_text(12, 12 + kLine * i, kScale, lines[i]);
    draw_text(12, height - 24, kScale, lines[PG_HUD_LINES - 1]);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
}
