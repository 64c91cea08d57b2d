/*
 * opx-demo: builds occupancy maps of a synthetic room frame (no data files
 * needed) at 5 cm and 2 cm, prints what they hold, probes a few points and
 * saves the 5 cm map as an OctoMap .bt file.
 *
 *   opx-demo [--out DIR]     (the .bt file goes to DIR, default ".")
 */
#define _POSIX_C_SOURCE 200809L

#include <octoprox/octoprox.h>

#include "support/room_frame.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define MAP_FILE_NAME "opx-demo-room-5cm.bt"

/* Stops the demo with the library's own explanation of a failure. */
static void check(opx_status status, const char *what) {
    if (status == OPX_OK) return;
    fprintf(stderr, "opx-demo: %s failed: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    exit(EXIT_FAILURE);
}

static double now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

static const char *class_name(int32_t cell_class) {
    switch (cell_class) {
    case OPX_CELL_FREE: return "free";
    case OPX_CELL_UNCERTAIN: return "uncertain";
    case OPX_CELL_OCCUPIED: return "occupied";
    default: return "unknown";
    }
}

static void print_header(const room_frame *frame) {
    const double *p = frame->sensor_position, *q = frame->sensor_orientation;
    printf("OctoProx %s demo: one synthetic %ux%u depth frame of a furnished room\n",
           opx_version(), frame->width, frame->height);
    printf("  sensor pose (map frame)  position (%.2f, %.2f, %.2f) m\n", p[0], p[1], p[2]);
    printf("                           quaternion xyzw (%.4f, %.4f, %.4f, %.4f)\n", q[0], q[1], q[2], q[3]);
    printf("  points                   %zu, %zu with a return\n", frame->count, frame->finite_count);
}

/* Inserts the frame into a new map of the given resolution; times it. */
static opx_octree *build_map(const room_frame *frame, double resolution, opx_insert_report *report,
                             double *insert_ms) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    opx_octree *tree = NULL;
    double start;
    options.resolution = resolution;
    check(opx_octree_create(&options, &tree), "opx_octree_create");
    insert.mode = OPX_INSERT_RAYCAST;
    memcpy(insert.sensor_pose.position, frame->sensor_position, sizeof insert.sensor_pose.position);
    memcpy(insert.sensor_pose.orientation, frame->sensor_orientation, sizeof insert.sensor_pose.orientation);
    start = now_ms();
    check(opx_octree_insert_points(tree, frame->xyz, frame->count, 0, OPX_SCALAR_FLOAT32, &insert, report),
          "opx_octree_insert_points");
    *insert_ms = now_ms() - start;
    return tree;
}

static void print_insert(const opx_insert_report *r, double insert_ms) {
    const unsigned long long skipped = r->points_nonfinite + r->points_out_of_range + r->points_outside_map;
    printf("  insert time              %.1f ms\n", insert_ms);
    printf("  points used              %llu\n", (unsigned long long)r->points_used);
    printf("  points skipped           %llu (no return %llu, beyond max range %llu, outside map %llu)\n",
           skipped, (unsigned long long)r->points_nonfinite, (unsigned long long)r->points_out_of_range,
           (unsigned long long)r->points_outside_map);
    printf("  cells updated            %llu as hit, %llu as miss\n", (unsigned long long)r->cells_hit,
           (unsigned long long)r->cells_missed);
}

static void print_stats(const opx_octree *tree) {
    opx_octree_stats s = OPX_OCTREE_STATS_INIT;
    unsigned long long leaves;
    check(opx_octree_get_stats(tree, &s), "opx_octree_get_stats");
    leaves = s.leaves_occupied + s.leaves_uncertain + s.leaves_free;
    printf("  leaves occupied          %llu\n", (unsigned long long)s.leaves_occupied);
    printf("  leaves uncertain         %llu\n", (unsigned long long)s.leaves_uncertain);
    printf("  leaves free              %llu\n", (unsigned long long)s.leaves_free);
    if (s.has_occupied) {
        printf("  occupied bounds          x %.2f .. %.2f, y %.2f .. %.2f, z %.2f .. %.2f m\n",
               s.occupied_min[0], s.occupied_max[0], s.occupied_min[1], s.occupied_max[1],
               s.occupied_min[2], s.occupied_max[2]);
    }
    printf("  memory                   %llu bytes (%.1f bytes per leaf, %llu inner nodes)\n",
           (unsigned long long)s.memory_bytes, leaves ? (double)s.memory_bytes / (double)leaves : 0.0,
           (unsigned long long)s.inner_nodes);
}

static void probe(const opx_octree *tree, const char *label, const double point[3]) {
    opx_cell_info info = OPX_CELL_INFO_INIT;
    check(opx_octree_classify(tree, point, &info), "opx_octree_classify");
    printf("    %-12s (%5.2f, %5.2f, %5.2f)  %-9s  p = %.3f  cell %g cm, depth %u\n", label, point[0],
           point[1], point[2], class_name(info.cell_class), info.probability, info.size * 100.0, info.depth);
}

static void print_probes(const opx_octree *tree) {
    room_landmarks marks;
    room_frame_landmarks(&marks);
    printf("  probes (map frame, m):\n");
    probe(tree, "table top", marks.table_top);
    probe(tree, "free air", marks.free_air);
    probe(tree, "behind box", marks.behind_box);
    probe(tree, "behind wall", marks.behind_wall);
}

static void save_map(const opx_octree *tree, const char *out_dir) {
    char path[4096];
    int n = snprintf(path, sizeof path, "%s/%s", out_dir, MAP_FILE_NAME);
    if (n < 0 || (size_t)n >= sizeof path) {
        fprintf(stderr, "opx-demo: output directory name too long\n");
        exit(EXIT_FAILURE);
    }
    check(opx_octree_save_file(tree, path, OPX_FORMAT_BT), "opx_octree_save_file");
    printf("  saved                    %s (view it with octovis)\n", path);
}

static const char *parse_out_dir(int argc, char **argv) {
    if (argc == 3 && strcmp(argv[1], "--out") == 0) return argv[2];
    if (argc == 1) return ".";
    fprintf(stderr, "usage: %s [--out DIR]\n", argv[0]);
    exit(EXIT_FAILURE);
}

int main(int argc, char **argv) {
    static const double resolutions[2] = {0.05, 0.02};
    const char *out_dir = parse_out_dir(argc, argv);
    room_frame frame;
    int i;
    if (room_frame_generate(1, &frame) != 0) {
        fprintf(stderr, "opx-demo: out of memory\n");
        return EXIT_FAILURE;
    }
    print_header(&frame);
    for (i = 0; i < 2; ++i) {
        opx_insert_report report = OPX_INSERT_REPORT_INIT;
        double insert_ms = 0.0;
        opx_octree *tree = build_map(&frame, resolutions[i], &report, &insert_ms);
        printf("\n%g cm map, ray-cast insert\n", resolutions[i] * 100.0);
        print_insert(&report, insert_ms);
        print_stats(tree);
        print_probes(tree);
        if (i == 0) save_map(tree, out_dir);
        opx_octree_destroy(tree);
    }
    room_frame_free(&frame);
    return EXIT_SUCCESS;
}
