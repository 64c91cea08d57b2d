/* A small RGB raster: see canvas.h. */
#include "canvas.h"

#include "font5x7.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int canvas_create(canvas *c, uint32_t width, uint32_t height) {
    c->width = width;
    c->height = height;
    c->rgb = malloc((size_t)width * height * 3);
    if (c->rgb == NULL) return -1;
    memset(c->rgb, 255, (size_t)width * height * 3);
    return 0;
}

void canvas_free(canvas *c) {
    free(c->rgb);
    c->rgb = NULL;
}

void canvas_pixel(canvas *c, int x, int y, colour col, double alpha) {
    uint8_t *p;
    if (x < 0 || y < 0 || (uint32_t)x >= c->width || (uint32_t)y >= c->height) return;
    p = c->rgb + ((size_t)y * c->width + (size_t)x) * 3;
    p[0] = (uint8_t)(p[0] + alpha * (col.r - p[0]) + 0.5);
    p[1] = (uint8_t)(p[1] + alpha * (col.g - p[1]) + 0.5);
    p[2] = (uint8_t)(p[2] + alpha * (col.b - p[2]) + 0.5);
}

void canvas_fill_rect(canvas *c, int x0, int y0, int x1, int y1, colour col, double alpha) {
    int x, y;
    if (x0 > x1) { int t = x0; x0 = x1; x1 = t; }
    if (y0 > y1) { int t = y0; y0 = y1; y1 = t; }
    for (y = y0; y <= y1; ++y)
        for (x = x0; x <= x1; ++x) canvas_pixel(c, x, y, col, alpha);
}

void canvas_rect_outline(canvas *c, int x0, int y0, int x1, int y1, colour col, int thickness) {
    int t;
    for (t = 0; t < thickness; ++t) {
        canvas_fill_rect(c, x0 + t, y0 + t, x1 - t, y0 + t, col, 1.0);
        canvas_fill_rect(c, x0 + t, y1 - t, x1 - t, y1 - t, col, 1.0);
        canvas_fill_rect(c, x0 + t, y0 + t, x0 + t, y1 - t, col, 1.0);
        canvas_fill_rect(c, x1 - t, y0 + t, x1 - t, y1 - t, col, 1.0);
    }
}

void canvas_line(canvas *c, double x0, double y0, double x1, double y1, colour col, double thickness) {
    const double dx = x1 - x0, dy = y1 - y0, length = sqrt(dx * dx + dy * dy);
    const int steps = (int)ceil(length * 2.0) + 1;
    const int r = (int)floor(thickness * 0.5);
    int i, ox, oy;
    for (i = 0; i <= steps; ++i) {
        const double t = (double)i / steps;
        const int x = (int)floor(x0 + t * dx + 0.5), y = (int)floor(y0 + t * dy + 0.5);
        for (oy = -r; oy <= r; ++oy)
            for (ox = -r; ox <= r; ++ox) canvas_pixel(c, x + ox, y + oy, col, 1.0);
    }
}

void canvas_fill_disc(canvas *c, double cx, double cy, double r, colour col, double alpha) {
    int x, y;
    for (y = (int)floor(cy - r); y <= (int)ceil(cy + r); ++y)
        for (x = (int)floor(cx - r); x <= (int)ceil(cx + r); ++x) {
            const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
            if (dx * dx + dy * dy <= r * r) canvas_pixel(c, x, y, col, alpha);
        }
}

static double edge(const double a[2], const double b[2], double x, double y) {
    return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
}

void canvas_fill_triangle(canvas *c, const double a[2], const double b[2], const double d[2], colour col, double alpha) {
    const double area = edge(a, b, d[0], d[1]);
    int x0 = (int)floor(fmin(a[0], fmin(b[0], d[0]))), x1 = (int)ceil(fmax(a[0], fmax(b[0], d[0])));
    int y0 = (int)floor(fmin(a[1], fmin(b[1], d[1]))), y1 = (int)ceil(fmax(a[1], fmax(b[1], d[1])));
    int x, y;
    if (area == 0.0) return;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 >= (int)c->width) x1 = (int)c->width - 1;
    if (y1 >= (int)c->height) y1 = (int)c->height - 1;
    for (y = y0; y <= y1; ++y)
        for (x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const double w0 = edge(b, d, px, py), w1 = edge(d, a, px, py), w2 = edge(a, b, px, py);
            if ((area > 0 && w0 >= 0 && w1 >= 0 && w2 >= 0) || (area < 0 && w0 <= 0 && w1 <= 0 && w2 <= 0))
                canvas_pixel(c, x, y, col, alpha);
        }
}

int canvas_text_width(const char *text, int scale) { return (int)strlen(text) * 6 * scale; }

int canvas_text(canvas *c, int x, int y, const char *text, colour col, int scale) {
    int start = x, row, bit;
    for (; *text != '\0'; ++text, x += 6 * scale) {
        const uint8_t *g = font5x7_glyph(*text);
        for (row = 0; row < 7; ++row)
            for (bit = 0; bit < 5; ++bit)
                if (g[row] & (0x10 >> bit))
                    canvas_fill_rect(c, x + bit * scale, y + row * scale, x + bit * scale + scale - 1,
                                     y + row * scale + scale - 1, col, 1.0);
    }
    return x - start;
}
