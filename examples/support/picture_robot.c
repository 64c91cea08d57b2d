/* The robot on the demo picture: see picture_frame.h. */
#include "picture_frame.h"

#include <stdio.h>
#include <stdlib.h>

colour picture_outline_colour(colour edge, int collides, int x, int y) {
    return collides && (x + y) / 6 % 2 == 0 ? kCollision : edge;
}

/* The pixels a mesh covers, projected: 1 each in mask (width * height
 * bytes).  0, or -1 when out of memory. */
static int silhouette_mask(const picture_frame *f, const mesh_out *mesh, unsigned char *mask) {
    const size_t n = (size_t)f->c.width * f->c.height;
    canvas m;
    size_t t, i;
    if (canvas_create(&m, f->c.width, f->c.height) != 0) return -1;
    for (t = 0; t < mesh->face_count; ++t) {
        const uint32_t *face = &mesh->faces[4 * t];
        double p[3][2];
        int k;
        for (k = 0; k < 3; ++k) {
            const float *v = &mesh->vertices[3 * face[k]];
            const double q[3] = {v[0], v[1], v[2]};
            picture_to_pixel(f, q, p[k]);
        }
        canvas_fill_triangle(&m, p[0], p[1], p[2], kText, 1.0);
    }
    for (i = 0; i < n; ++i) mask[i] = m.rgb[3 * i] < 128;
    canvas_free(&m);
    return 0;
}

static int is_edge(const picture_frame *f, const unsigned char *mask, size_t i) {
    const int x = (int)(i % f->c.width), y = (int)(i / f->c.width);
    return x == 0 || y == 0 || x + 1 == (int)f->c.width || y + 1 == (int)f->c.height || !mask[i - 1] ||
           !mask[i + 1] || !mask[i - f->c.width] || !mask[i + f->c.width];
}

/* A 2-pixel outline around a mask. */
static void draw_outline(picture_frame *f, const unsigned char *mask, colour edge, int collides) {
    const size_t n = (size_t)f->c.width * f->c.height;
    size_t i;
    for (i = 0; i < n; ++i) {
        const int x = (int)(i % f->c.width), y = (int)(i / f->c.width);
        if (mask[i] && is_edge(f, mask, i))
            canvas_fill_rect(&f->c, x, y, x + 1, y + 1, picture_outline_colour(edge, collides, x, y), 1.0);
    }
}

static void draw_body(picture_frame *f, const mesh_out *body) {
    const size_t n = (size_t)f->c.width * f->c.height;
    unsigned char *mask = malloc(n);
    size_t i;
    if (mask == NULL || silhouette_mask(f, body, mask) != 0) {
        free(mask);
        return;
    }
    for (i = 0; i < n; ++i)
        if (mask[i]) canvas_pixel(&f->c, (int)(i % f->c.width), (int)(i / f->c.width), kBody, BODY_ALPHA);
    draw_outline(f, mask, kBodyEdge, 0);
    free(mask);
}

/* Where poses overlap (a shoulder that hardly moves), one tint, not a
 * stack of them: the latest waypoint's colour, under every outline. */
static void draw_arms(picture_frame *f, const picture_input *in) {
    const size_t n = (size_t)f->c.width * f->c.height;
    unsigned char *masks = malloc(n * (size_t)(in->arm_count > 0 ? in->arm_count : 1));
    size_t i;
    int a;
    if (masks == NULL) return;
    for (a = 0; a < in->arm_count; ++a)
        if (silhouette_mask(f, in->arms[a], masks + (size_t)a * n) != 0) {
            free(masks);
            return;
        }
    for (i = 0; i < n && !in->arms_outline_only; ++i)
        for (a = in->arm_count - 1; a >= 0; --a)
            if (masks[(size_t)a * n + i]) {
                canvas_pixel(&f->c, (int)(i % f->c.width), (int)(i / f->c.width), kArmColours[a], ARM_ALPHA);
                break;
            }
    for (a = 0; a < in->arm_count; ++a) draw_outline(f, masks + (size_t)a * n, kArmColours[a], in->arm_collides[a]);
    free(masks);
}

/* A disc in its arm's colour at each drawn waypoint, with its number. */
static void draw_waypoint_marks(picture_frame *f, const picture_input *in) {
    char number[24];
    double p[2];
    int i;
    for (i = 0; i < in->arm_count; ++i) {
        if (in->arm_waypoints[i] >= in->tool_path_count) continue;
        picture_to_pixel(f, &in->tool_path[3 * in->arm_waypoints[i]], p);
        canvas_fill_disc(&f->c, p[0], p[1], 7.0, kText, 1.0);
        canvas_fill_disc(&f->c, p[0], p[1], 5.0, kArmColours[i], 1.0);
        snprintf(number, sizeof number, "%zu", in->arm_waypoints[i]);
        canvas_fill_rect(&f->c, (int)p[0] + 8, (int)p[1] - 20, (int)p[0] + 11 + canvas_text_width(number, 2),
                         (int)p[1] - 3, kFree, 0.8);
        canvas_text(&f->c, (int)p[0] + 10, (int)p[1] - 18, number, in->arm_collides[i] ? kCollision : kText, 2);
    }
}

void picture_draw_tool_path(picture_frame *f, const picture_input *in) {
    double p[2], next[2];
    size_t w;
    for (w = 0; w + 1 < in->tool_path_count; ++w) {
        picture_to_pixel(f, &in->tool_path[3 * w], p);
        picture_to_pixel(f, &in->tool_path[3 * (w + 1)], next);
        canvas_line(&f->c, p[0], p[1], next[0], next[1], kText, 1.0);
    }
    for (w = 0; w < in->tool_path_count; ++w) {
        picture_to_pixel(f, &in->tool_path[3 * w], p);
        canvas_fill_disc(&f->c, p[0], p[1], 3.5, kFree, 1.0);
        canvas_fill_disc(&f->c, p[0], p[1], 2.5, in->tool_collides[w] ? kCollision : kText, 1.0);
    }
    draw_waypoint_marks(f, in);
}

void picture_draw_robot(picture_frame *f, const picture_input *in) {
    if (in->body != NULL) draw_body(f, in->body);
    draw_arms(f, in);
}

/* Diagonal stripes, 3 pixels of 8, so the silhouette reads over any cell
 * colour and apart from the arms' flat tints. */
static int is_hatched(int x, int y) { return (x + y) % 8 < 3; }

void picture_draw_known(picture_frame *f, const picture_input *in) {
    const size_t n = (size_t)f->c.width * f->c.height;
    unsigned char *mask;
    size_t i;
    if (in->known == NULL || in->known->face_count == 0) return;
    mask = malloc(n);
    if (mask == NULL || silhouette_mask(f, in->known, mask) != 0) {
        free(mask);
        return;
    }
    for (i = 0; i < n; ++i) {
        const int x = (int)(i % f->c.width), y = (int)(i / f->c.width);
        if (mask[i]) canvas_pixel(&f->c, x, y, kKnown, is_hatched(x, y) ? 0.85 : 0.2);
    }
    draw_outline(f, mask, kKnown, 0);
    free(mask);
}

void picture_draw_object_contacts(picture_frame *f, const picture_input *in) {
    size_t i;
    for (i = 0; i < in->object_contact_count; ++i) {
        double p[2];
        picture_to_pixel(f, &in->object_contacts[3 * i], p);
        canvas_fill_disc(&f->c, p[0], p[1], 6.0, kCollision, 1.0);
        canvas_fill_disc(&f->c, p[0], p[1], 3.5, kFree, 1.0);
    }
}

void picture_known_swatch(picture_frame *f, int x, int y) {
    int px, py;
    for (py = y; py <= y + 14; ++py)
        for (px = x; px <= x + 22; ++px) {
            const int edge = px < x + 2 || px > x + 20 || py < y + 2 || py > y + 12;
            canvas_pixel(&f->c, px, py, kKnown, edge ? 1.0 : is_hatched(px, py) ? 0.85 : 0.2);
        }
}
