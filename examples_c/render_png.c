/* render_png: see render_png.h. */
#include "render_png.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ======================================================================================== */
/* Image and 2-D drawing                                                                     */
/* ======================================================================================== */

int rp_image_create(rp_image* image, int width, int height, const unsigned char background[3]) {
    image->width = width;
    image->height = height;
    image->rgb = (unsigned char*)malloc((size_t)width * (size_t)height * 3);
    if (!image->rgb) {
        fprintf(stderr, "render_png: out of memory for a %dx%d image\n", width, height);
        return -1;
    }
    for (size_t i = 0; i < (size_t)width * (size_t)height; ++i) memcpy(image->rgb + 3 * i, background, 3);
    return 0;
}

void rp_image_destroy(rp_image* image) {
    free(image->rgb);
    image->rgb = NULL;
}

/* Mix colour into the pixel with weight alpha in [0, 1]. */
static void blend(rp_image* image, int x, int y, const unsigned char rgb[3], double alpha) {
    if (x < 0 || y < 0 || x >= image->width || y >= image->height || alpha <= 0) return;
    if (alpha > 1) alpha = 1;
    unsigned char* p = image->rgb + 3 * ((size_t)y * (size_t)image->width + (size_t)x);
    for (int c = 0; c < 3; ++c) p[c] = (unsigned char)(p[c] + alpha * (rgb[c] - p[c]) + 0.5);
}

void rp_fill_rect(rp_image* image, int x0, int y0, int x1, int y1, const unsigned char rgb[3]) {
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) blend(image, x, y, rgb, 1.0);
}

/* Antialiased by coverage: each pixel near the segment is blended by how far its centre lies
 * inside the band of the given width around it. */
void rp_draw_line(rp_image* image, double x0, double y0, double x1, double y1, double width,
                  const unsigned char rgb[3]) {
    const double r = 0.5 * width;
    const int xa = (int)floor(fmin(x0, x1) - r - 1), xb = (int)ceil(fmax(x0, x1) + r + 1);
    const int ya = (int)floor(fmin(y0, y1) - r - 1), yb = (int)ceil(fmax(y0, y1) + r + 1);
    const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    for (int y = ya; y <= yb; ++y)
        for (int x = xa; x <= xb; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            double t = len2 > 0 ? ((px - x0) * dx + (py - y0) * dy) / len2 : 0;
            t = t < 0 ? 0 : (t > 1 ? 1 : t);
            const double ex = px - (x0 + t * dx), ey = py - (y0 + t * dy);
            blend(image, x, y, rgb, r + 0.5 - sqrt(ex * ex + ey * ey));
        }
}

/* 5x7 glyphs, one byte a row (top first), bit 4 = leftmost column. */
static const char kGlyphChars[] = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ.-+()/:=,%";
static const unsigned char kGlyphs[][7] = {
    {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}, {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E},
    {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}, {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E},
    {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}, {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E},
    {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}, {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08},
    {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}, {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C},
    {0x0E, 0x11, 0x11, 0x11, 0x1F, 0x11, 0x11}, {0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E},
    {0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E}, {0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C},
    {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F}, {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10},
    {0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F}, {0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11},
    {0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}, {0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C},
    {0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11}, {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F},
    {0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11}, {0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11},
    {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}, {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10},
    {0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D}, {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11},
    {0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E}, {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04},
    {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}, {0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04},
    {0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A}, {0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11},
    {0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04}, {0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F},
    {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}, {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00},
    {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}, {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02},
    {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}, {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00},
    {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}, {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00},
    {0x00, 0x00, 0x00, 0x00, 0x0C, 0x04, 0x08}, {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03},
};

int rp_text_width(int scale, const char* text) {
    const int n = (int)strlen(text);
    return n > 0 ? scale * (6 * n - 1) : 0;
}

const unsigned char* rp_glyph(char c) {
    if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
    const char* found = c ? strchr(kGlyphChars, c) : NULL;
    return found ? kGlyphs[found - kGlyphChars] : NULL;
}

void rp_draw_text(rp_image* image, int x, int y, int scale, const char* text,
                  const unsigned char rgb[3]) {
    for (; *text; ++text, x += 6 * scale) {
        const unsigned char* glyph = rp_glyph(*text);
        if (!glyph) continue;
        for (int row = 0; row < 7; ++row)
            for (int col = 0; col < 5; ++col)
                if (glyph[row] & (0x10 >> col))
                    rp_fill_rect(image, x + col * scale, y + row * scale, x + col * scale + scale - 1,
                                 y + row * scale + scale - 1, rgb);
    }
}

/* ======================================================================================== */
/* PNG: zlib stream of one fixed-Huffman deflate block                                       */
/* ======================================================================================== */

typedef struct byte_buffer {
    unsigned char* data;
    size_t size, capacity;
    int failed;
    unsigned bits;  /* pending bits, LSB first (deflate's bit order) */
    int bit_count;
} byte_buffer;

static void put_byte(byte_buffer* b, unsigned char v) {
    if (b->size == b->capacity) {
        const size_t capacity = b->capacity ? 2 * b->capacity : 65536;
        unsigned char* grown = (unsigned char*)realloc(b->data, capacity);
        if (!grown) {
            b->failed = 1;
            return;
        }
        b->data = grown;
        b->capacity = capacity;
    }
    b->data[b->size++] = v;
}

static void put_bits(byte_buffer* b, unsigned value, int count) {
    b->bits |= value << b->bit_count;
    b->bit_count += count;
    while (b->bit_count >= 8) {
        put_byte(b, (unsigned char)(b->bits & 0xFF));
        b->bits >>= 8;
        b->bit_count -= 8;
    }
}

/* Huffman codes are sent most significant bit first, i.e. reversed in deflate's LSB order. */
static void put_code(byte_buffer* b, unsigned code, int length) {
    unsigned reversed = 0;
    for (int i = 0; i < length; ++i) reversed |= ((code >> i) & 1u) << (length - 1 - i);
    put_bits(b, reversed, length);
}

/* The fixed literal/length code of RFC 1951, section 3.2.6. */
static void put_symbol(byte_buffer* b, unsigned symbol) {
    if (symbol < 144) put_code(b, 0x30 + symbol, 8);
    else if (symbol < 256) put_code(b, 0x190 + (symbol - 144), 9);
    else if (symbol < 280) put_code(b, symbol - 256, 7);
    else put_code(b, 0xC0 + (symbol - 280), 8);
}

static const unsigned short kLengthBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,
                                               15, 17, 19, 23, 27, 31, 35, 43, 51,  59,
                                               67, 83, 99, 115, 131, 163, 195, 227, 258};
static const unsigned char kLengthExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                               2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const unsigned short kDistBase[30] = {1,    2,    3,    4,    5,    7,     9,     13,
                                             17,   25,   33,   49,   65,   97,    129,   193,
                                             257,  385,  513,  769,  1025, 1537,  2049,  3073,
                                             4097, 6145, 8193, 12289, 16385, 24577};
static const unsigned char kDistExtra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                             6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

static void put_match(byte_buffer* b, unsigned length, unsigned distance) {
    int i = 28;
    while (kLengthBase[i] > length) --i;
    put_symbol(b, 257 + (unsigned)i);
    put_bits(b, length - kLengthBase[i], kLengthExtra[i]);
    int d = 29;
    while (kDistBase[d] > distance) --d;
    put_code(b, (unsigned)d, 5);
    put_bits(b, distance - kDistBase[d], kDistExtra[d]);
}

enum { kWindow = 32768, kHashSize = 1 << 15, kMaxChain = 48, kMaxMatch = 258 };

static unsigned hash3(const unsigned char* p) {
    return ((unsigned)p[0] * 506832829u ^ (unsigned)p[1] * 2654435761u ^ (unsigned)p[2] * 40503u) >>
           17 & (kHashSize - 1);
}

/* zlib stream (RFC 1950) of data: greedy LZ77 over hash chains, one fixed-Huffman block. The
 * flat colours of rendered pictures are long repeats, which this alone compresses well. */
static int zlib_compress(const unsigned char* data, size_t n, byte_buffer* out) {
    int* head = (int*)malloc(sizeof(int) * kHashSize);
    int* prev = (int*)malloc(sizeof(int) * kWindow);
    if (!head || !prev) {
        free(head);
        free(prev);
        return -1;
    }
    for (int i = 0; i < kHashSize; ++i) head[i] = -1;
    put_byte(out, 0x78); /* deflate, 32 KB window */
    put_byte(out, 0x01); /* no dictionary, check bits: 0x7801 % 31 == 0 */
    put_bits(out, 1, 1); /* final block */
    put_bits(out, 1, 2); /* fixed Huffman codes */
    size_t i = 0;
    while (i < n) {
        unsigned best_length = 0, best_distance = 0;
        if (i + 3 <= n) {
            int candidate = head[hash3(data + i)];
            const size_t limit = n - i < kMaxMatch ? n - i : kMaxMatch;
            for (int chain = 0; candidate >= 0 && chain < kMaxChain; ++chain) {
                const size_t distance = i - (size_t)candidate;
                if (distance > kWindow) break;
                size_t length = 0;
                while (length < limit && data[candidate + length] == data[i + length]) ++length;
                if (length > best_length) {
                    best_length = (unsigned)length;
                    best_distance = (unsigned)distance;
                    if (length == limit) break;
                }
                candidate = prev[candidate & (kWindow - 1)];
            }
        }
        const size_t advance = best_length >= 3 ? best_length : 1;
        if (best_length >= 3) put_match(out, best_length, best_distance);
        else put_symbol(out, data[i]);
        for (size_t k = 0; k < advance; ++k, ++i) {
            if (i + 3 > n) continue;
            const unsigned h = hash3(data + i);
            prev[i & (kWindow - 1)] = head[h];
            head[h] = (int)i;
        }
    }
    put_symbol(out, 256);               /* end of block */
    if (out->bit_count > 0) put_bits(out, 0, 8 - out->bit_count); /* flush to a byte */
    unsigned a = 1, b = 0;              /* Adler-32 of the uncompressed data */
    for (size_t k = 0; k < n; ++k) {
        a = (a + data[k]) % 65521u;
        b = (b + a) % 65521u;
    }
    const unsigned adler = (b << 16) | a;
    for (int s = 24; s >= 0; s -= 8) put_byte(out, (unsigned char)(adler >> s));
    free(head);
    free(prev);
    return out->failed ? -1 : 0;
}

static unsigned long crc32_update(unsigned long crc, const unsigned char* p, size_t n) {
    static unsigned long table[256];
    static int ready = 0;
    if (!ready) {
        for (unsigned long k = 0; k < 256; ++k) {
            unsigned long c = k;
            for (int j = 0; j < 8; ++j) c = c & 1 ? 0xEDB88320UL ^ (c >> 1) : c >> 1;
            table[k] = c;
        }
        ready = 1;
    }
    for (size_t k = 0; k < n; ++k) crc = table[(crc ^ p[k]) & 0xFF] ^ (crc >> 8);
    return crc;
}

static int write_chunk(FILE* f, const char type[4], const unsigned char* data, size_t n) {
    unsigned char be[4] = {(unsigned char)(n >> 24), (unsigned char)(n >> 16),
                           (unsigned char)(n >> 8), (unsigned char)n};
    unsigned long crc = crc32_update(0xFFFFFFFFUL, (const unsigned char*)type, 4);
    crc = crc32_update(crc, data, n) ^ 0xFFFFFFFFUL;
    const unsigned char crc_be[4] = {(unsigned char)(crc >> 24), (unsigned char)(crc >> 16),
                                     (unsigned char)(crc >> 8), (unsigned char)crc};
    return fwrite(be, 1, 4, f) == 4 && fwrite(type, 1, 4, f) == 4 &&
                   (n == 0 || fwrite(data, 1, n, f) == n) && fwrite(crc_be, 1, 4, f) == 4
               ? 0
               : -1;
}

static int paeth(int a, int b, int c) {
    const int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
}

int rp_image_write_png(const rp_image* image, const char* path) {
    const size_t stride = 3 * (size_t)image->width, rows = (size_t)image->height;
    unsigned char* filtered = (unsigned char*)malloc((stride + 1) * rows);
    unsigned char* trial = (unsigned char*)malloc(stride);
    byte_buffer z = {NULL, 0, 0, 0, 0, 0};
    int result = -1;
    if (!filtered || !trial) goto done;
    /* Each row gets the filter (none, sub, up, average, Paeth) whose output has the smallest
     * sum of absolute values: the usual heuristic, which turns smooth shading into zeros. */
    for (size_t y = 0; y < rows; ++y) {
        const unsigned char* row = image->rgb + y * stride;
        const unsigned char* up = y > 0 ? row - stride : NULL;
        unsigned char* dst = filtered + y * (stride + 1);
        long best_cost = -1;
        for (int type = 0; type < 5; ++type) {
            long cost = 0;
            for (size_t x = 0; x < stride; ++x) {
                const int a = x >= 3 ? row[x - 3] : 0, b = up ? up[x] : 0,
                          c = x >= 3 && up ? up[x - 3] : 0;
                const int predictor = type == 0 ? 0 : type == 1 ? a : type == 2 ? b
                                    : type == 3 ? (a + b) / 2 : paeth(a, b, c);
                trial[x] = (unsigned char)(row[x] - predictor);
                cost += trial[x] < 128 ? trial[x] : 256 - trial[x];
            }
            if (best_cost < 0 || cost < best_cost) {
                best_cost = cost;
                dst[0] = (unsigned char)type;
                memcpy(dst + 1, trial, stride);
            }
        }
    }
    if (zlib_compress(filtered, (stride + 1) * rows, &z) != 0) goto done;
    FILE* f = fopen(path, "wb");
    if (!f) goto done;
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    const unsigned w = (unsigned)image->width, h = (unsigned)image->height;
    const unsigned char ihdr[13] = {(unsigned char)(w >> 24), (unsigned char)(w >> 16),
                                    (unsigned char)(w >> 8),  (unsigned char)w,
                                    (unsigned char)(h >> 24), (unsigned char)(h >> 16),
                                    (unsigned char)(h >> 8),  (unsigned char)h,
                                    8, 2, 0, 0, 0}; /* 8-bit RGB, no interlace */
    const int ok = fwrite(signature, 1, 8, f) == 8 && write_chunk(f, "IHDR", ihdr, 13) == 0 &&
                   write_chunk(f, "IDAT", z.data, z.size) == 0 &&
                   write_chunk(f, "IEND", NULL, 0) == 0;
    result = fclose(f) == 0 && ok ? 0 : -1;
done:
    if (result != 0) fprintf(stderr, "render_png: could not write %s\n", path);
    free(filtered);
    free(trial);
    free(z.data);
    return result;
}

/* ======================================================================================== */
/* 3-D rendering of the bodies                                                              */
/* ======================================================================================== */

void rp_colour_map(double t, unsigned char out[3]) {
    /* Blue (59, 76, 192) through light grey (221, 221, 221) to red (180, 4, 38): diverging,
     * so the sign of a signed quantity (a velocity component) reads at a glance. */
    static const double lo[3] = {59, 76, 192}, mid[3] = {221, 221, 221}, hi[3] = {180, 4, 38};
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    for (int c = 0; c < 3; ++c) {
        const double v = t < 0.5 ? lo[c] + 2 * t * (mid[c] - lo[c])
                                 : mid[c] + (2 * t - 1) * (hi[c] - mid[c]);
        out[c] = (unsigned char)(v + 0.5);
    }
}

static void sub3(const double a[3], const double b[3], double out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = a[i] - b[i];
}
static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void cross3(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}
static void normalize3(double v[3]) {
    const double n = sqrt(dot3(v, v));
    if (n > 0) v[0] /= n, v[1] /= n, v[2] /= n;
}

typedef struct frame_buffer {
    int width, height;   /* supersampled size */
    float* depth;
    float* colour;       /* 3 a sample */
    unsigned char* edge; /* 1 where a visible mesh edge passes */
} frame_buffer;

typedef struct projected {
    double x, y, depth;
} projected;

static void fill_triangle(frame_buffer* fb, const projected p[3], const double scalar[3],
                          const rp_body_style* style, double light) {
    const int x0 = (int)fmax(0, floor(fmin(p[0].x, fmin(p[1].x, p[2].x))));
    const int x1 = (int)fmin(fb->width - 1, ceil(fmax(p[0].x, fmax(p[1].x, p[2].x))));
    const int y0 = (int)fmax(0, floor(fmin(p[0].y, fmin(p[1].y, p[2].y))));
    const int y1 = (int)fmin(fb->height - 1, ceil(fmax(p[0].y, fmax(p[1].y, p[2].y))));
    const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (fabs(area) < 1e-12) return;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            double w[3];
            for (int k = 0; k < 3; ++k) {
                const projected* a = &p[(k + 1) % 3];
                const projected* b = &p[(k + 2) % 3];
                w[k] = ((b->x - a->x) * (py - a->y) - (px - a->x) * (b->y - a->y)) / area;
            }
            if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
            const double depth = w[0] * p[0].depth + w[1] * p[1].depth + w[2] * p[2].depth;
            const size_t i = (size_t)y * (size_t)fb->width + (size_t)x;
            if (depth >= fb->depth[i]) continue;
            fb->depth[i] = (float)depth;
            unsigned char base[3];
            if (style->node_scalar) {
                const double v = w[0] * scalar[0] + w[1] * scalar[1] + w[2] * scalar[2];
                const double range = style->scalar_max - style->scalar_min;
                rp_colour_map(range > 0 ? (v - style->scalar_min) / range : 0.5, base);
            } else {
                memcpy(base, style->colour, 3);
            }
            for (int c = 0; c < 3; ++c) fb->colour[3 * i + c] = (float)(base[c] * light);
        }
}

/* Marks the samples along a triangle edge that are not hidden behind another surface. */
static void mark_edge(frame_buffer* fb, const projected* a, const projected* b) {
    const double dx = b->x - a->x, dy = b->y - a->y;
    const int steps = (int)ceil(fmax(fabs(dx), fabs(dy))) + 1;
    for (int s = 0; s <= steps; ++s) {
        const double t = (double)s / steps;
        const int x = (int)floor(a->x + t * dx), y = (int)floor(a->y + t * dy);
        if (x < 0 || y < 0 || x >= fb->width || y >= fb->height) continue;
        const double depth = a->depth + t * (b->depth - a->depth);
        const size_t i = (size_t)y * (size_t)fb->width + (size_t)x;
        if (depth <= fb->depth[i] * (1 + 2e-3)) fb->edge[i] = 1;
    }
}

int rp_render_bodies(rp_image* image, const lfem_world* world, const rp_body_style* styles,
                     int style_count, const rp_camera* camera,
                     const unsigned char background[3]) {
    enum { kSuper = 2 };
    frame_buffer fb;
    fb.width = kSuper * image->width;
    fb.height = kSuper * image->height;
    const size_t samples = (size_t)fb.width * (size_t)fb.height;
    fb.depth = (float*)malloc(sizeof(float) * samples);
    fb.colour = (float*)malloc(sizeof(float) * 3 * samples);
    fb.edge = (unsigned char*)calloc(samples, 1);
    double* positions = NULL;
    uint32_t* triangles = NULL;
    int result = -1;
    if (!fb.depth || !fb.colour || !fb.edge) {
        fprintf(stderr, "render_png: out of memory\n");
        goto done;
    }
    for (size_t i = 0; i < samples; ++i) {
        fb.depth[i] = HUGE_VALF;
        for (int c = 0; c < 3; ++c) fb.colour[3 * i + c] = background[c];
    }

    /* Camera frame: forward f, right r, up u; focal length in samples from the field of view. */
    double f[3], r[3], u[3];
    sub3(camera->target, camera->eye, f);
    normalize3(f);
    cross3(f, camera->up, r);
    normalize3(r);
    cross3(r, f, u);
    const double focal = 0.5 * fb.height / tan(0.5 * camera->fov_y_degrees * 3.14159265358979 / 180);
    /* Light from behind the viewer's left shoulder, a little above. */
    double light_dir[3];
    for (int i = 0; i < 3; ++i) light_dir[i] = -f[i] + 0.6 * u[i] - 0.5 * r[i];
    normalize3(light_dir);

    for (int pass = 0; pass < 2; ++pass) /* pass 0 fills, pass 1 marks visible edges */
        for (int s = 0; s < style_count; ++s) {
            const rp_body_style* style = &styles[s];
            uint32_t nodes = 0, count = 0;
            if (lfem_body_get_node_count(world, style->body, &nodes) != LFEM_OK ||
                lfem_body_get_boundary_triangle_count(world, style->body, &count) != LFEM_OK)
                goto lfem_failed;
            free(positions);
            free(triangles);
            positions = (double*)malloc(sizeof(double) * 3 * (nodes ? nodes : 1));
            triangles = (uint32_t*)malloc(sizeof(uint32_t) * 3 * (count ? count : 1));
            if (!positions || !triangles) {
                fprintf(stderr, "render_png: out of memory\n");
                goto done;
            }
            if (lfem_body_get_positions(world, style->body, positions, nodes) != LFEM_OK ||
                lfem_body_get_boundary_triangles(world, style->body, triangles, count) != LFEM_OK)
                goto lfem_failed;
            for (uint32_t t = 0; t < count; ++t) {
                const double* v[3];
                projected p[3];
                double scalar[3] = {0, 0, 0};
                int behind = 0;
                for (int k = 0; k < 3; ++k) {
                    const uint32_t node = triangles[3 * t + k];
                    v[k] = positions + 3 * node;
                    double d[3];
                    sub3(v[k], camera->eye, d);
                    p[k].depth = dot3(d, f);
                    if (p[k].depth <= 1e-6) behind = 1;
                    p[k].x = 0.5 * fb.width + focal * dot3(d, r) / p[k].depth;
                    p[k].y = 0.5 * fb.height - focal * dot3(d, u) / p[k].depth;
                    if (style->node_scalar) scalar[k] = style->node_scalar[node];
                }
                if (behind) continue;
                double e1[3], e2[3], n[3], to_eye[3];
                sub3(v[1], v[0], e1);
                sub3(v[2], v[0], e2);
                cross3(e1, e2, n);
                normalize3(n);
                sub3(camera->eye, v[0], to_eye);
                if (dot3(n, to_eye) <= 0) continue; /* seen from behind: a hidden face */
                if (pass == 0) {
                    const double light = 0.35 + 0.65 * fmax(0, dot3(n, light_dir));
                    fill_triangle(&fb, p, scalar, style, light);
                } else if (style->draw_edges) {
                    for (int k = 0; k < 3; ++k) mark_edge(&fb, &p[k], &p[(k + 1) % 3]);
                }
            }
        }

    /* Darken edge samples, then average each kSuper x kSuper block into one pixel. */
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) {
            double sum[3] = {0, 0, 0};
            for (int sy = 0; sy < kSuper; ++sy)
                for (int sx = 0; sx < kSuper; ++sx) {
                    const size_t i = (size_t)(kSuper * y + sy) * (size_t)fb.width + (size_t)(kSuper * x + sx);
                    const double shade = fb.edge[i] ? 0.55 : 1.0;
                    for (int c = 0; c < 3; ++c) sum[c] += shade * fb.colour[3 * i + c];
                }
            unsigned char* out = image->rgb + 3 * ((size_t)y * (size_t)image->width + (size_t)x);
            for (int c = 0; c < 3; ++c) {
                const double v = sum[c] / (kSuper * kSuper);
                out[c] = (unsigned char)(v < 0 ? 0 : (v > 255 ? 255 : v + 0.5));
            }
        }
    result = 0;
    goto done;
lfem_failed:
    fprintf(stderr, "render_png: %s\n", lfem_last_error());
done:
    free(fb.depth);
    free(fb.colour);
    free(fb.edge);
    free(positions);
    free(triangles);
    return result;
}
