/*
 * opx-bench-call-overhead: the time of one tiny collision query called
 * from C, the reference python_overhead.py sets the bindings' time against.
 *
 * The scene of the C and Python tests: one occupied 25 cm cell [0, 0.25]^3
 * and one link holding a 10 cm sphere that touches the cell's face x = 0.25;
 * every call is opx_query_collide with a default request (stop at the
 * first contact) and a fresh result, as a caller writes it.  Times are
 * CPU time of the calling thread, so other programs' load on the machine
 * counts only through the caches.  Prints the median of the rounds in
 * nanoseconds per call:
 *     ns_per_call 563.2
 *   opx-bench-call-overhead [--calls N] [--rounds R]
 */
#include <octoprox/octoprox.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define CELL 0.25
#define CENTRE 0.125

typedef struct scene {
    opx_octree *map;
    opx_linkset *links;
    opx_query *query;
} scene;

static double now_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int failed(const char *what) {
    fprintf(stderr, "opx-bench-call-overhead: %s: %s\n", what, opx_last_error());
    return 1;
}

/* One cell hit by one endpoint; a sphere of radius 0.1 at x = 0.35. */
static int make_scene(scene *s) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = CELL;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_ENDPOINTS;
    const double point[3] = {CENTRE, CENTRE, CENTRE};
    opx_shape ball = OPX_SHAPE_INIT;
    ball.kind = OPX_SHAPE_SPHERE;
    ball.radius = 0.1;
    const opx_pose pose = {{0.35, CENTRE, CENTRE}, {0.0, 0.0, 0.0, 1.0}};
    uint32_t link = 0;
    if (opx_octree_create(&options, &s->map) != OPX_OK) return failed("map");
    if (opx_octree_insert_points(s->map, point, 1, 0, OPX_SCALAR_FLOAT64, &insert, NULL) != OPX_OK)
        return failed("insert");
    if (opx_linkset_create(&s->links) != OPX_OK || opx_linkset_add_link(s->links, "ball", &link) != OPX_OK ||
        opx_linkset_add_shape(s->links, link, &ball, NULL) != OPX_OK ||
        opx_linkset_set_poses(s->links, &pose, 1, 0) != OPX_OK)
        return failed("link set");
    if (opx_query_create(NULL, &s->query) != OPX_OK) return failed("query");
    return 0;
}

/* ns per call over `calls` calls; -1 when a call fails or misses the cell. */
static double time_round(const scene *s, long calls) {
    long collided = 0;
    const double start = now_seconds();
    for (long i = 0; i < calls; ++i) {
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        if (opx_query_collide(s->query, s->map, s->links, &request, &result) != OPX_OK) return -1.0;
        collided += result.collided;
    }
    const double seconds = now_seconds() - start;
    return collided == calls ? 1e9 * seconds / (double)calls : -1.0;
}

static int compare_doubles(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int parse(int argc, char **argv, long *calls, long *rounds) {
    for (int i = 1; i + 1 < argc; i += 2) {
        long *target = strcmp(argv[i], "--calls") == 0 ? calls : strcmp(argv[i], "--rounds") == 0 ? rounds : NULL;
        if (target == NULL) return 0;
        *target = strtol(argv[i + 1], NULL, 10);
    }
    return argc % 2 == 1 && *calls >= 1 && *calls <= 100000000 && *rounds >= 1 && *rounds <= 101;
}

int main(int argc, char **argv) {
    long calls = 200000, rounds = 5;
    if (!parse(argc, argv, &calls, &rounds)) {
        fprintf(stderr, "usage: opx-bench-call-overhead [--calls N (1..1e8)] [--rounds R (1..101)]\n");
        return 2;
    }
    scene s = {NULL, NULL, NULL};
    if (make_scene(&s) != 0) return 1;
    double times[101];
    int status = time_round(&s, calls / 10 + 1) < 0.0;  /* warm-up */
    for (long r = 0; r < rounds && status == 0; ++r) {
        times[r] = time_round(&s, calls);
        status = times[r] < 0.0;
    }
    if (status == 0) {
        qsort(times, (size_t)rounds, sizeof times[0], compare_doubles);
        printf("ns_per_call %.1f\n", times[rounds / 2]);
    } else {
        fprintf(stderr, "opx-bench-call-overhead: a call failed or missed the cell: %s\n", opx_last_error());
    }
    opx_query_destroy(s.query);
    opx_linkset_destroy(s.links);
    opx_octree_destroy(s.map);
    return status;
}
