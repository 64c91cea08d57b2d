/* The demo's picture: see demo_picture.h. */
#include "demo_picture.h"

#include "canvas.h"
#include "picture_frame.h"
#include "png_writer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MARGIN_LEFT 56
#define MARGIN_TOP 44
#define MARGIN_RIGHT 80
#define LEGEND_HEIGHT 164 /* 188 with known objects: one more line */
#define LEGEND_WIDTH 1000 /* its longest line, the last, is 960 pixels */
#define PANEL_BOTTOM 36   /* a panel without legend: room for the axis labels */
#define PAIR_TITLE 36     /* the pair's title band */
#define PAIR_LEGEND 64    /* the pair's legend: two lines */

const colour kOccupied = {40, 40, 48}, kFree = {255, 255, 255}, kUnknown = {176, 180, 192};
const colour kUncertain = {225, 205, 120}, kCollision = {220, 20, 30}, kCost = {255, 140, 0};
const colour kText = {20, 20, 20}, kSensor = {0, 120, 200};
/* The still body in brown, apart from the greys and the arms' colours. */
const colour kBody = {165, 110, 55}, kBodyEdge = {105, 65, 25};
/* Known objects in a teal of their own, hatched. */
const colour kKnown = {0, 125, 110};
const colour kArmColours[PICTURE_MAX_ARMS] = {{20, 150, 60}, {0, 150, 175}, {40, 80, 225}, {130, 50, 200},
                                              {205, 40, 160}, {110, 110, 40}, {60, 60, 60}, {0, 0, 0}};

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void picture_to_pixel(const picture_frame *f, const double p[3], double out[2]) {
    const double d[3] = {p[0] - f->view->origin[0], p[1] - f->view->origin[1], p[2] - f->view->origin[2]};
    out[0] = MARGIN_LEFT + (dot(d, f->view->u) - f->view->u_min) * f->view->pixels_per_metre;
    out[1] = MARGIN_TOP + (f->view->v_max - dot(d, f->view->v)) * f->view->pixels_per_metre;
}

static colour class_colour(int32_t cell_class) {
    switch (cell_class) {
    case OPX_CELL_OCCUPIED: return kOccupied;
    case OPX_CELL_FREE: return kFree;
    case OPX_CELL_UNCERTAIN: return kUncertain;
    default: return kUnknown;
    }
}

static void draw_slice(picture_frame *f, const opx_octree *map) {
    const picture_view *v = f->view;
    int x, y, axis;
    for (y = 0; y < f->plot_h; ++y)
        for (x = 0; x < f->plot_w; ++x) {
            const double a = v->u_min + (x + 0.5) / v->pixels_per_metre, b = v->v_max - (y + 0.5) / v->pixels_per_metre;
            double p[3];
            opx_cell_info cell = OPX_CELL_INFO_INIT;
            for (axis = 0; axis < 3; ++axis) p[axis] = v->origin[axis] + a * v->u[axis] + b * v->v[axis];
            if (opx_octree_classify(map, p, &cell) != OPX_OK) cell.cell_class = OPX_CELL_UNKNOWN;
            canvas_pixel(&f->c, MARGIN_LEFT + x, MARGIN_TOP + y, class_colour(cell.cell_class), 1.0);
        }
}

/* The pixel rectangle of an axis-aligned map box, projected. */
static void box_rect(const picture_frame *f, const double lo[3], const double hi[3], int r[4]) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    int i;
    for (i = 0; i < 8; ++i) {
        const double corner[3] = {i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]};
        double px[2];
        picture_to_pixel(f, corner, px);
        x0 = fmin(x0, px[0]);
        x1 = fmax(x1, px[0]);
        y0 = fmin(y0, px[1]);
        y1 = fmax(y1, px[1]);
    }
    r[0] = (int)floor(x0 + 0.5);
    r[1] = (int)floor(y0 + 0.5);
    r[2] = (int)floor(x1 - 0.5);
    r[3] = (int)floor(y1 - 0.5);
}

static void draw_cost_boxes(picture_frame *f, const picture_input *in) {
    size_t i;
    for (i = 0; i < in->cost_box_count; ++i) {
        int r[4];
        box_rect(f, in->cost_boxes[i].min, in->cost_boxes[i].max, r);
        canvas_fill_rect(&f->c, r[0], r[1], r[2], r[3], kCost, 0.35);
        canvas_rect_outline(&f->c, r[0], r[1], r[2], r[3], kCost, 2);
    }
}

static void draw_collisions(picture_frame *f, const picture_input *in) {
    size_t i;
    for (i = 0; i < in->colliding_count; ++i) {
        const double *c = &in->colliding_centers[3 * i], h = 0.5 * in->colliding_sizes[i];
        const double lo[3] = {c[0] - h, c[1] - h, c[2] - h}, hi[3] = {c[0] + h, c[1] + h, c[2] + h};
        int r[4];
        box_rect(f, lo, hi, r);
        canvas_fill_rect(&f->c, r[0], r[1], r[2], r[3], kCollision, 1.0);
    }
}

static void draw_sensor(picture_frame *f, const picture_input *in) {
    double s[2];
    int i;
    picture_to_pixel(f, in->sensor, s);
    for (i = 0; i < in->fov_edge_count; ++i) {
        const double *d = in->fov_edges[i];
        const double far[3] = {in->sensor[0] + 30 * d[0], in->sensor[1] + 30 * d[1], in->sensor[2] + 30 * d[2]};
        double e[2], t;
        picture_to_pixel(f, far, e);
        /* Clip the ray to the plot so it does not run over the margins. */
        for (t = 0.0; t <= 1.0; t += 0.0005) {
            const double x = s[0] + t * (e[0] - s[0]), y = s[1] + t * (e[1] - s[1]);
            if (x < MARGIN_LEFT || y < MARGIN_TOP || x >= MARGIN_LEFT + f->plot_w || y >= MARGIN_TOP + f->plot_h) break;
            if (fmod(t * 3000.0, 20.0) < 12.0) canvas_fill_rect(&f->c, (int)x, (int)y, (int)x + 1, (int)y + 1, kSensor, 1.0);
        }
    }
    canvas_fill_rect(&f->c, (int)s[0] - 7, (int)s[1] - 5, (int)s[0] + 7, (int)s[1] + 5, kSensor, 1.0);
    canvas_text(&f->c, (int)s[0] - 20, (int)s[1] - 22, "CAMERA", kSensor, 2);
}

static void draw_axes(picture_frame *f) {
    const picture_view *v = f->view;
    const int x0 = MARGIN_LEFT, y0 = MARGIN_TOP, x1 = MARGIN_LEFT + f->plot_w, y1 = MARGIN_TOP + f->plot_h;
    double m;
    char label[32];
    canvas_rect_outline(&f->c, x0 - 1, y0 - 1, x1, y1, kText, 1);
    for (m = ceil(v->u_min); m <= v->u_max; m += 1.0) {
        const int x = x0 + (int)floor((m - v->u_min) * v->pixels_per_metre + 0.5);
        canvas_fill_rect(&f->c, x, y1, x, y1 + 5, kText, 1.0);
        snprintf(label, sizeof label, "%g", m + 0.0); /* + 0.0: no "-0" */
        canvas_text(&f->c, x - canvas_text_width(label, 2) / 2, y1 + 8, label, kText, 2);
    }
    for (m = ceil(v->v_min); m <= v->v_max; m += 1.0) {
        const int y = y0 + (int)floor((v->v_max - m) * v->pixels_per_metre + 0.5);
        canvas_fill_rect(&f->c, x0 - 6, y, x0 - 1, y, kText, 1.0);
        snprintf(label, sizeof label, "%g", m + 0.0);
        canvas_text(&f->c, x0 - 10 - canvas_text_width(label, 2), y - 7, label, kText, 2);
    }
    snprintf(label, sizeof label, "%s (M)", v->u_name);
    canvas_text(&f->c, x1 + 10, y1 - 7, label, kText, 2);
    snprintf(label, sizeof label, "%s (M)", v->v_name);
    canvas_text(&f->c, 4, y0 - 18, label, kText, 2);
}

/* One legend entry: a swatch and a label; returns the next x. */
static int legend_entry(picture_frame *f, int x, int y, colour fill, double alpha, colour edge, int collides, const char *label) {
    int px, py;
    canvas_fill_rect(&f->c, x, y, x + 22, y + 14, fill, alpha);
    for (py = y; py <= y + 14; ++py)
        for (px = x; px <= x + 22; ++px)
            if (px < x + 2 || px > x + 20 || py < y + 2 || py > y + 12)
                canvas_pixel(&f->c, px, py, picture_outline_colour(edge, collides, px, py), 1.0);
    return x + 30 + canvas_text(&f->c, x + 30, y, label, kText, 2) + 24;
}

/* The tool path's entry: a line through dots. */
static int legend_path_entry(picture_frame *f, int x, int y, const char *label) {
    canvas_line(&f->c, x, y + 7, x + 22, y + 7, kText, 1.0);
    canvas_fill_disc(&f->c, x + 4.5, y + 7.5, 2.5, kText, 1.0);
    canvas_fill_disc(&f->c, x + 18.5, y + 7.5, 2.5, kCollision, 1.0);
    return x + 30 + canvas_text(&f->c, x + 30, y, label, kText, 2) + 24;
}

static void draw_legend(picture_frame *f, const picture_input *in) {
    int x = MARGIN_LEFT, y = MARGIN_TOP + f->plot_h + 32, i;
    char label[96];
    x = legend_entry(f, x, y, kOccupied, 1.0, kOccupied, 0, "OCCUPIED");
    x = legend_entry(f, x, y, kFree, 1.0, kText, 0, "FREE");
    x = legend_entry(f, x, y, kUnknown, 1.0, kUnknown, 0, "UNKNOWN (NEVER SEEN)");
    legend_entry(f, x, y, kCollision, 1.0, kCollision, 0, "CELLS THE ARM HITS");
    y += 24;
    snprintf(label, sizeof label, "UNKNOWN SPACE THE PATH SWEEPS: COSTLIEST BOXES (TOTAL %.3g M^3)", in->total_cost);
    legend_entry(f, MARGIN_LEFT, y, kCost, 0.35, kCost, 0, label);
    x = MARGIN_LEFT;
    y += 24;
    if (in->body != NULL)
        x = legend_entry(f, x, y, kBody, BODY_ALPHA, kBodyEdge, 0, in->body_label ? in->body_label : "ROBOT BODY (STILL)");
    if (in->tool_path_count > 0) {
        snprintf(label, sizeof label, "%s PATH, A DOT A WAYPOINT (RED: COLLIDES)", in->tool_label ? in->tool_label : "TOOL");
        legend_path_entry(f, x, y, label);
    }
    x = MARGIN_LEFT;
    y += 24;
    if (in->known != NULL) {
        picture_known_swatch(f, x, y);
        x += 30 + canvas_text(&f->c, x + 30, y, in->known_label ? in->known_label : "KNOWN OBJECTS", kText, 2) + 24;
        canvas_fill_disc(&f->c, x + 11, y + 7, 6.0, kCollision, 1.0);
        canvas_fill_disc(&f->c, x + 11, y + 7, 3.5, kFree, 1.0);
        canvas_text(&f->c, x + 30, y, "WHERE THE ARM TOUCHES IT", kText, 2);
        x = MARGIN_LEFT;
        y += 24;
    }
    for (i = 0; i < in->arm_count; ++i)
        x = legend_entry(f, x, y, kArmColours[i], ARM_ALPHA, kArmColours[i], in->arm_collides[i], in->arm_labels[i]);
    y += 24;
    canvas_text(&f->c, MARGIN_LEFT, y, "RED-DASHED OUTLINE: THAT WAYPOINT COLLIDES.  DOTTED BLUE: CAMERA FIELD OF VIEW.",
                kText, 2);
}

static void draw_notes(picture_frame *f, const picture_input *in) {
    int i;
    for (i = 0; i < in->note_count; ++i) {
        double p[2];
        const int w = canvas_text_width(in->notes[i], 2);
        int x, y;
        picture_to_pixel(f, in->note_at[i], p);
        x = (int)p[0] - w / 2;
        y = (int)p[1] - 7;
        canvas_fill_rect(&f->c, x - 3, y - 3, x + w + 1, y + 16, kFree, 0.75);
        canvas_text(&f->c, x, y, in->notes[i], kText, 2);
    }
}

static void draw_scale_bar(picture_frame *f) {
    const int len = (int)floor(f->view->pixels_per_metre + 0.5);
    const int x = MARGIN_LEFT + 24, y = MARGIN_TOP + 16;
    canvas_fill_rect(&f->c, x - 8, y - 6, x + len + 8, y + 28, kFree, 0.85);
    canvas_fill_rect(&f->c, x, y, x + len, y + 5, kText, 1.0);
    canvas_fill_rect(&f->c, x, y - 4, x + 1, y + 9, kText, 1.0);
    canvas_fill_rect(&f->c, x + len - 1, y - 4, x + len, y + 9, kText, 1.0);
    canvas_text(&f->c, x + len / 2 - canvas_text_width("1 M", 2) / 2, y + 10, "1 M", kText, 2);
}

/* Wide enough for the plot, the title and (with_legend) the legend. */
static uint32_t picture_width(const picture_input *in, int plot_w, int with_legend) {
    int width = MARGIN_LEFT + plot_w + MARGIN_RIGHT;
    const int title = MARGIN_LEFT + 80 + canvas_text_width(in->view.title, 2) + 16;
    if (width < title) width = title;
    if (with_legend && width < MARGIN_LEFT + LEGEND_WIDTH) width = MARGIN_LEFT + LEGEND_WIDTH;
    return (uint32_t)width;
}

/* One panel on a canvas of its own: the slice and all drawn over it, its
 * title, axes and scale bar, and the legend when with_legend (else room
 * for the axis labels only).  0, or -1 when out of memory. */
static int render_panel(picture_frame *f, const picture_input *in, int with_legend) {
    const int below = with_legend ? LEGEND_HEIGHT + (in->known != NULL ? 24 : 0) : PANEL_BOTTOM;
    f->view = &in->view;
    f->plot_w = (int)ceil((in->view.u_max - in->view.u_min) * in->view.pixels_per_metre);
    f->plot_h = (int)ceil((in->view.v_max - in->view.v_min) * in->view.pixels_per_metre);
    if (canvas_create(&f->c, picture_width(in, f->plot_w, with_legend), (uint32_t)(MARGIN_TOP + f->plot_h + below)) != 0)
        return -1;
    draw_slice(f, in->map);
    draw_cost_boxes(f, in);
    picture_draw_known(f, in);
    picture_draw_robot(f, in);
    draw_collisions(f, in);
    picture_draw_object_contacts(f, in);
    picture_draw_tool_path(f, in);
    draw_sensor(f, in);
    draw_notes(f, in);
    /* Margins are painted last so nothing drawn in map space spills over. */
    canvas_fill_rect(&f->c, 0, 0, (int)f->c.width - 1, MARGIN_TOP - 2, kFree, 1.0);
    canvas_fill_rect(&f->c, 0, MARGIN_TOP + f->plot_h + 1, (int)f->c.width - 1, (int)f->c.height - 1, kFree, 1.0);
    canvas_fill_rect(&f->c, 0, 0, MARGIN_LEFT - 2, (int)f->c.height - 1, kFree, 1.0);
    canvas_fill_rect(&f->c, MARGIN_LEFT + f->plot_w + 1, 0, (int)f->c.width - 1, (int)f->c.height - 1, kFree, 1.0);
    canvas_text(&f->c, MARGIN_LEFT + 80, 12, in->view.title, kText, 2);
    draw_axes(f);
    draw_scale_bar(f);
    if (with_legend) draw_legend(f, in);
    return 0;
}

int demo_picture_write(const picture_input *in, const char *path) {
    picture_frame f;
    int status;
    if (render_panel(&f, in, 1) != 0) return -1;
    status = png_write_rgb(path, f.c.rgb, f.c.width, f.c.height);
    canvas_free(&f.c);
    return status;
}

static void blit(canvas *to, const canvas *from, uint32_t x0, uint32_t y0) {
    uint32_t y;
    for (y = 0; y < from->height && y0 + y < to->height; ++y)
        memcpy(&to->rgb[3 * ((size_t)(y0 + y) * to->width + x0)], &from->rgb[3 * (size_t)y * from->width],
               3 * (size_t)(from->width < to->width - x0 ? from->width : to->width - x0));
}

static const char *const kCellClasses[3] = {"OCCUPIED", "FREE", "UNKNOWN (NEVER SEEN)"};

/* The pair's legend's first line: its entries, each a swatch, a label and
 * a gap (legend_entry), after the left margin. */
static int pair_legend_width(const picture_input *in) {
    int width = MARGIN_LEFT, i;
    for (i = 0; i < 3; ++i) width += 54 + canvas_text_width(kCellClasses[i], 2);
    if (in->arm_count > 0) width += 54 + canvas_text_width(in->arm_labels[0] ? in->arm_labels[0] : "ROBOT", 2);
    return width;
}

/* The pair's legend: the cell classes, the robot, the camera's field. */
static void draw_pair_legend(canvas *c, const picture_input *in, int y) {
    picture_frame f;
    const colour fills[3] = {kOccupied, kFree, kUnknown}, edges[3] = {kOccupied, kText, kUnknown};
    int x = MARGIN_LEFT, i;
    f.c = *c;
    for (i = 0; i < 3; ++i) x = legend_entry(&f, x, y, fills[i], 1.0, edges[i], 0, kCellClasses[i]);
    if (in->arm_count > 0)
        legend_entry(&f, x, y, kArmColours[0], in->arms_outline_only ? 0.0 : ARM_ALPHA, kArmColours[0], 0,
                     in->arm_labels[0] ? in->arm_labels[0] : "ROBOT");
    canvas_text(c, MARGIN_LEFT, y + 24, "DOTTED BLUE: CAMERA FIELD OF VIEW.", kText, 2);
}

/* Both panels, the title and the legend. */
static uint32_t pair_width(const canvas *left, const canvas *right, const char *title, const picture_input *in) {
    uint32_t width = left->width + right->width;
    const uint32_t text = (uint32_t)(MARGIN_LEFT + canvas_text_width(title, 2) + 16);
    const uint32_t legend = (uint32_t)pair_legend_width(in);
    if (width < text) width = text;
    if (width < legend) width = legend;
    return width;
}

int demo_picture_write_pair(const picture_input *left, const picture_input *right, const char *title, const char *path) {
    picture_frame l, r;
    canvas pair;
    int status = -1;
    if (render_panel(&l, left, 0) != 0) return -1;
    if (render_panel(&r, right, 0) != 0) {
        canvas_free(&l.c);
        return -1;
    }
    if (canvas_create(&pair, pair_width(&l.c, &r.c, title, left),
                      PAIR_TITLE + (l.c.height > r.c.height ? l.c.height : r.c.height) + PAIR_LEGEND) == 0) {
        canvas_text(&pair, MARGIN_LEFT, 12, title, kText, 2);
        blit(&pair, &l.c, 0, PAIR_TITLE);
        blit(&pair, &r.c, l.c.width, PAIR_TITLE);
        draw_pair_legend(&pair, left, (int)pair.height - PAIR_LEGEND + 8);
        status = png_write_rgb(path, pair.rgb, pair.width, pair.height);
        canvas_free(&pair);
    }
    canvas_free(&l.c);
    canvas_free(&r.c);
    return status;
}
