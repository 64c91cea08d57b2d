/* The synthetic room frame: see room_frame.h. */
#include "room_frame.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FX 525.0
#define FY 525.0
#define CX 319.5
#define CY 239.5
#define PITCH_DOWN_DEG 10.0
#define NOISE_SIGMA 0.002

typedef struct box3 {
    double lo[3], hi[3];
} box3;

/* The room's inside, and the solid furniture in it (map frame). */
static const box3 kRoom = {{-1.0, -2.5, 0.0}, {5.0, 2.5, 2.8}};
static const box3 kSolids[] = {
    {{1.20, -0.60, 0.70}, {2.20, 0.60, 0.73}}, /* table top */
    {{1.22, -0.58, 0.00}, {1.27, -0.53, 0.70}}, /* table legs */
    {{1.22, 0.53, 0.00}, {1.27, 0.58, 0.70}},
    {{2.13, -0.58, 0.00}, {2.18, -0.53, 0.70}},
    {{2.13, 0.53, 0.00}, {2.18, 0.58, 0.70}},
    {{3.20, 1.20, 0.00}, {3.70, 1.70, 0.50}},   /* box on the left */
    {{2.60, -2.00, 0.00}, {3.20, -1.40, 0.35}}, /* box on the right */
};
static const double kCylinderCenter[2] = {1.6, 1.5};
static const double kCylinderRadius = 0.2, kCylinderHeight = 0.9;
/* The window in the far wall x = 5: glass returns nothing. */
static const double kWindowY[2] = {-1.0, 0.8}, kWindowZ[2] = {0.9, 2.0};
static const double kCameraPosition[3] = {-0.9, 0.0, 1.4};

typedef struct ray {
    double origin[3], dir[3];
} ray;

/* Distance along the ray where it leaves the room box from inside. */
static double exit_room(const ray *r, int *exit_axis) {
    double best = INFINITY;
    int axis;
    for (axis = 0; axis < 3; ++axis) {
        double t;
        if (r->dir[axis] == 0.0) continue;
        t = ((r->dir[axis] > 0 ? kRoom.hi[axis] : kRoom.lo[axis]) - r->origin[axis]) / r->dir[axis];
        if (t < best) {
            best = t;
            *exit_axis = axis;
        }
    }
    return best;
}

/* Slab test: distance where the ray enters a solid box, or INFINITY. */
static double enter_box(const ray *r, const box3 *b) {
    double t_in = 0.0, t_out = INFINITY;
    int axis;
    for (axis = 0; axis < 3; ++axis) {
        if (r->dir[axis] == 0.0) {
            if (r->origin[axis] < b->lo[axis] || r->origin[axis] > b->hi[axis]) return INFINITY;
            continue;
        }
        {
            double t0 = (b->lo[axis] - r->origin[axis]) / r->dir[axis];
            double t1 = (b->hi[axis] - r->origin[axis]) / r->dir[axis];
            if (t0 > t1) { double s = t0; t0 = t1; t1 = s; }
            if (t0 > t_in) t_in = t0;
            if (t1 < t_out) t_out = t1;
        }
    }
    return t_in <= t_out && t_in > 0.0 ? t_in : INFINITY;
}

/* The upright cylinder: its side, then its top disc. */
static double enter_cylinder(const ray *r) {
    const double ox = r->origin[0] - kCylinderCenter[0], oy = r->origin[1] - kCylinderCenter[1];
    const double a = r->dir[0] * r->dir[0] + r->dir[1] * r->dir[1];
    const double b = 2.0 * (ox * r->dir[0] + oy * r->dir[1]);
    const double c = ox * ox + oy * oy - kCylinderRadius * kCylinderRadius;
    const double disc = b * b - 4.0 * a * c;
    double best = INFINITY;
    if (a > 0.0 && disc >= 0.0) {
        const double t = (-b - sqrt(disc)) / (2.0 * a);
        const double z = r->origin[2] + t * r->dir[2];
        if (t > 0.0 && z >= 0.0 && z <= kCylinderHeight) best = t;
    }
    if (r->dir[2] < 0.0) {
        const double t = (kCylinderHeight - r->origin[2]) / r->dir[2];
        const double x = ox + t * r->dir[0], y = oy + t * r->dir[1];
        if (t > 0.0 && t < best && x * x + y * y <= kCylinderRadius * kCylinderRadius) best = t;
    }
    return best;
}

static int through_window(const ray *r, double t, int exit_axis) {
    const double y = r->origin[1] + t * r->dir[1], z = r->origin[2] + t * r->dir[2];
    return exit_axis == 0 && r->dir[0] > 0 && y > kWindowY[0] && y < kWindowY[1] &&
           z > kWindowZ[0] && z < kWindowZ[1];
}

/* Distance along the ray to the first surface; INFINITY for no return. */
static double cast(const ray *r) {
    int exit_axis = 0;
    const double t_wall = exit_room(r, &exit_axis);
    double t = enter_cylinder(r);
    size_t i;
    for (i = 0; i < sizeof kSolids / sizeof kSolids[0]; ++i) {
        const double t_box = enter_box(r, &kSolids[i]);
        if (t_box < t) t = t_box;
    }
    if (t < t_wall) return t;
    /* The window only matters when no furniture stands in front of it. */
    return through_window(r, t_wall, exit_axis) ? INFINITY : t_wall;
}

/* Orientation of the optical frame: looking along map +x, pitched down. */
static void camera_orientation(double q[4]) {
    /* Optical (z forward, x right, y down) to a level camera looking along
     * +x: the usual ROS quaternion (-0.5, 0.5, -0.5, 0.5). */
    static const double level[4] = {-0.5, 0.5, -0.5, 0.5};
    /* Pitch down = rotation about map +y by a positive angle. */
    const double half = 0.5 * PITCH_DOWN_DEG * 3.14159265358979323846 / 180.0;
    const double p[4] = {0.0, sin(half), 0.0, cos(half)};
    /* q = p * level (Hamilton product, x y z w). */
    q[0] = p[3] * level[0] + p[0] * level[3] + p[1] * level[2] - p[2] * level[1];
    q[1] = p[3] * level[1] - p[0] * level[2] + p[1] * level[3] + p[2] * level[0];
    q[2] = p[3] * level[2] + p[0] * level[1] - p[1] * level[0] + p[2] * level[3];
    q[3] = p[3] * level[3] - p[0] * level[0] - p[1] * level[1] - p[2] * level[2];
}

static void rotate(const double q[4], const double v[3], double out[3]) {
    /* v' = v + 2w (u x v) + 2 u x (u x v), u = (x, y, z). */
    const double ux = q[0], uy = q[1], uz = q[2], w = q[3];
    const double cx = uy * v[2] - uz * v[1], cy = uz * v[0] - ux * v[2], cz = ux * v[1] - uy * v[0];
    out[0] = v[0] + 2.0 * (w * cx + uy * cz - uz * cy);
    out[1] = v[1] + 2.0 * (w * cy + uz * cx - ux * cz);
    out[2] = v[2] + 2.0 * (w * cz + ux * cy - uy * cx);
}

/* splitmix64: small, fast, and the same on every platform. */
static uint64_t next_random(uint64_t *state) {
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Irwin-Hall: the sum of four uniforms, scaled to unit variance. */
static double gaussian_ish(uint64_t *state) {
    double sum = 0.0;
    int i;
    for (i = 0; i < 4; ++i) sum += (double)(next_random(state) >> 11) * (1.0 / 9007199254740992.0);
    return (sum - 2.0) * sqrt(3.0);
}

static void render_pixel(const room_frame *f, uint32_t u, uint32_t v, uint64_t *rng, float *out) {
    const double d_optical[3] = {(u - CX) / FX, (v - CY) / FY, 1.0};
    ray r;
    double t;
    memcpy(r.origin, f->sensor_position, sizeof r.origin);
    rotate(f->sensor_orientation, d_optical, r.dir);
    /* d_optical has z = 1, so the ray parameter is the pixel's depth. */
    t = cast(&r);
    if (!(t <= ROOM_FRAME_MAX_DEPTH)) {
        out[0] = out[1] = out[2] = NAN;
        return;
    }
    t += NOISE_SIGMA * gaussian_ish(rng);
    out[0] = (float)(t * d_optical[0]);
    out[1] = (float)(t * d_optical[1]);
    out[2] = (float)t;
}

int room_frame_generate(uint32_t seed, room_frame *out) {
    uint64_t rng = 0x6F7078ull ^ ((uint64_t)seed << 32);
    uint32_t u, v;
    memset(out, 0, sizeof *out);
    out->width = ROOM_FRAME_WIDTH;
    out->height = ROOM_FRAME_HEIGHT;
    out->count = (size_t)out->width * out->height;
    memcpy(out->sensor_position, kCameraPosition, sizeof kCameraPosition);
    camera_orientation(out->sensor_orientation);
    out->xyz = malloc(out->count * 3 * sizeof(float));
    if (out->xyz == NULL) {
        memset(out, 0, sizeof *out);
        return -1;
    }
    for (v = 0; v < out->height; ++v) {
        for (u = 0; u < out->width; ++u) {
            float *p = &out->xyz[3 * ((size_t)v * out->width + u)];
            render_pixel(out, u, v, &rng, p);
            if (!isnan(p[2])) ++out->finite_count;
        }
    }
    return 0;
}

void room_frame_free(room_frame *frame) {
    if (frame == NULL) return;
    free(frame->xyz);
    memset(frame, 0, sizeof *frame);
}

void room_frame_landmarks(room_landmarks *out) {
    static const double forward[3] = {0.0, 0.0, 1.0};
    double q[4], axis[3];
    int i;
    camera_orientation(q);
    rotate(q, forward, axis);
    /* The table's middle, a hair under its top (inside the top's cells). */
    out->table_top[0] = 1.7;
    out->table_top[1] = 0.0;
    out->table_top[2] = 0.725;
    for (i = 0; i < 3; ++i) out->free_air[i] = kCameraPosition[i] + axis[i];
    out->behind_wall[0] = kRoom.hi[0] + 1.0;
    out->behind_wall[1] = 0.0;
    out->behind_wall[2] = 1.0;
    /* In the box's shadow: every ray towards it ends on the box. */
    out->behind_box[0] = 3.92;
    out->behind_box[1] = 1.50;
    out->behind_box[2] = 0.15;
}
