/*
 * A small RGB raster for the demo's picture: rectangles, lines, filled
 * triangles with alpha, and text in a built-in 5x7 bitmap font (upper
 * case, digits, a little punctuation; lower case prints as upper case).
 */
#ifndef OPX_EXAMPLES_CANVAS_H
#define OPX_EXAMPLES_CANVAS_H

#include <stdint.h>

typedef struct canvas {
    uint32_t width, height;
    uint8_t *rgb; /* width * height * 3 */
} canvas;

typedef struct colour {
    uint8_t r, g, b;
} colour;

/* 0, or -1 when out of memory.  The canvas starts white. */
int canvas_create(canvas *c, uint32_t width, uint32_t height);
void canvas_free(canvas *c);

/* alpha in [0, 1]: 1 paints over, 0.3 tints. */
void canvas_pixel(canvas *c, int x, int y, colour col, double alpha);
void canvas_fill_rect(canvas *c, int x0, int y0, int x1, int y1, colour col, double alpha);
void canvas_rect_outline(canvas *c, int x0, int y0, int x1, int y1, colour col, int thickness);
/* A line of the given thickness (pixels), in float pixel coordinates. */
void canvas_line(canvas *c, double x0, double y0, double x1, double y1, colour col, double thickness);
/* A filled disc of radius r pixels centred at (cx, cy). */
void canvas_fill_disc(canvas *c, double cx, double cy, double r, colour col, double alpha);
void canvas_fill_triangle(canvas *c, const double a[2], const double b[2], const double d[2], colour col, double alpha);
/* Text with its top-left corner at (x, y); scale 1 = 5x7 pixels a glyph.
 * Returns the width drawn in pixels. */
int canvas_text(canvas *c, int x, int y, const char *text, colour col, int scale);
int canvas_text_width(const char *text, int scale);

#endif /* OPX_EXAMPLES_CANVAS_H */
