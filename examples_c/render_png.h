/* render_png: the pictures of the example scenes, with no dependency beyond lfem and libc.
 *
 * - An RGB image with 2-D drawing (lines, rectangles, a 5x7 bitmap font) for plots.
 * - A PNG writer (zlib stream of fixed-Huffman deflate with a small LZ77 matcher, CRC32,
 *   Adler32): the flat colours of these pictures compress ~20x, so a key frame is tens of KB.
 * - A 3-D renderer of the bodies of an lfem world: their boundary triangles, read through the
 *   public API, flat shaded with a z-buffer from a fixed perspective camera, coloured by body or
 *   by a scalar per node, mesh edges drawn faintly so the deformation shows.
 *
 * Plain C99; functions return 0 on success and -1 on failure (after printing why on stderr). */
#ifndef LFEM_EXAMPLES_RENDER_PNG_H
#define LFEM_EXAMPLES_RENDER_PNG_H

#include "lfem.h"

typedef struct rp_image {
    int width, height;
    unsigned char* rgb; /* 3 bytes a pixel, rows top to bottom */
} rp_image;

int rp_image_create(rp_image* image, int width, int height, const unsigned char background[3]);
void rp_image_destroy(rp_image* image);
int rp_image_write_png(const rp_image* image, const char* path);

/* 2-D drawing in pixel coordinates (x right, y down); everything is clipped to the image. */
void rp_fill_rect(rp_image* image, int x0, int y0, int x1, int y1, const unsigned char rgb[3]);
void rp_draw_line(rp_image* image, double x0, double y0, double x1, double y1, double width,
                  const unsigned char rgb[3]);
/* Text in the 5x7 font, each font pixel scale x scale image pixels; lower case is drawn as
 * upper case, characters without a glyph as blanks. (x, y) is the top left corner. */
void rp_draw_text(rp_image* image, int x, int y, int scale, const char* text,
                  const unsigned char rgb[3]);
int rp_text_width(int scale, const char* text);
/* The 5x7 glyph of c (lower case as upper case): 7 rows, top first, bit 4 the leftmost column;
 * NULL for a character without one (drawn as a blank). For drawing the same font elsewhere
 * (the playground's HUD draws it with OpenGL). */
const unsigned char* rp_glyph(char c);

/* A perspective camera looking from eye at target; up fixes the roll. */
typedef struct rp_camera {
    double eye[3], target[3], up[3];
    double fov_y_degrees;
} rp_camera;

/* How one body is drawn. With node_scalar NULL the body is drawn in colour; otherwise each
 * node's value (node_scalar[i], same order as lfem_body_get_positions) is mapped linearly from
 * [scalar_min, scalar_max] onto a blue-white-red colour map and interpolated across triangles. */
typedef struct rp_body_style {
    lfem_body body;
    unsigned char colour[3];
    const double* node_scalar; /* nullable */
    double scalar_min, scalar_max;
    int draw_edges;            /* 1 = outline the boundary triangles */
} rp_body_style;

/* Render the bodies into image (cleared to background first): boundary triangles lit by a
 * light from the camera's upper left, hidden surfaces removed with a z-buffer, supersampled
 * 2x2 for smooth edges. Returns -1 (message on stderr) when an lfem call fails. */
int rp_render_bodies(rp_image* image, const lfem_world* world, const rp_body_style* styles,
                     int style_count, const rp_camera* camera,
                     const unsigned char background[3]);

/* The blue-white-red colour of t in [0, 1] (clamped), as used for node scalars. */
void rp_colour_map(double t, unsigned char out[3]);

#endif
