/* octoprox ingest INPUT... -o MAP: build or update a map from point clouds
 * and depth images. */
#include "cli.h"
#include "cloud_file.h"
#include "commands.h"
#include "ingest_cloud.h"
#include "ingest_robot.h"

#include <string.h>
#include <unistd.h>

static const char kHelp[] =
    "usage: octoprox ingest INPUT... -o MAP.bt|MAP.ot|MAP.opx\n"
    "                       [--sensor-pose x,y,z[,qx,qy,qz,qw]] [--optical-frame]\n"
    "                       [--res 0.05] [--endpoints] [--max-range M] [--json]\n"
    "                       [--intrinsics fx,fy,cx,cy --depth-scale S]\n"
    "                       [--urdf ROBOT.urdf [robot options] [--robot-padding M]\n"
    "                        [--clear-robot-volume]]\n"
    "\n"
    "Inserts each input as one sensor frame (OctoMap semantics: ray-cast, the\n"
    "cells along each ray become more free, the endpoint cells more occupied)\n"
    "and saves the map.  When MAP exists it is loaded and updated; otherwise a\n"
    "new map is made.  Inputs:\n"
    "  CLOUD.pcd, CLOUD.ply  PCD v0.7 (ascii, binary, binary_compressed) and\n"
    "                      PLY (ascii, binary_little_endian), x y z as float\n"
    "                      or double, in the SENSOR frame;\n"
    "  DEPTH.png, DEPTH.tif  16-bit one-channel depth images (PNG, TIFF), seen\n"
    "                      by a pinhole camera whose optical frame (z forward,\n"
    "                      x right, y down) is the SENSOR frame; 0 is no return.\n"
    "\n"
    "options:\n"
    "  -o, --output MAP    the map to write (.bt: occupancy only, .ot: log-odds,\n"
    "                      .opx: log-odds and the occupied cells' point extents,\n"
    "                      for check --obstacles point-extents)\n"
    "  --sensor-pose POSE  the sensor frame in the map frame, for every input\n"
    "                      (metres; quaternion x,y,z,w); default: a PCD's\n"
    "                      VIEWPOINT (tx ty tz qw qx qy qz), else identity\n"
    "  --optical-frame     the inputs are in a camera's optical frame (z\n"
    "                      forward, x right, y down), as camera clouds and\n"
    "                      depth images are; the sensor pose is then that of\n"
    "                      the camera's z-up body frame (x forward, y left,\n"
    "                      z up), so --sensor-pose 0,0,1.2 is a camera 1.2 m\n"
    "                      up looking along the map's x axis\n"
    "  --res R             resolution of a new map in metres (default 0.05); an\n"
    "                      existing map keeps its own and R must match it\n"
    "  --endpoints         insert endpoints only (no ray-casting, no free space)\n"
    "  --max-range M       skip points farther than M metres from the sensor\n"
    "  --intrinsics fx,fy,cx,cy  the depth camera: focal lengths and principal\n"
    "                      point (column, row) in pixels; needed by depth images\n"
    "  --depth-scale S     depth units per metre of the depth images (1000 for\n"
    "                      millimetres, 5000 for TUM RGB-D PNGs); needed by them\n"
    "  --json              one JSON object: output, updated, resolution, clouds\n"
    "                      [{file, format, points (pixels of an image),\n"
    "                      points_used, points_nonfinite, points_out_of_range,\n"
    "                      points_outside_map, points_on_robot,\n"
    "                      points_shadowed, pixels_no_return, cells_hit,\n"
    "                      cells_missed, cells_cleared, insert_ms, sensor_pose\n"
    "                      [x, y, z, qx, qy, qz, qw], sensor_pose_from}],\n"
    "                      leaves {occupied, uncertain, free}\n"
    "  -h, --help          this help\n"
    "\n";

static const char kExitCodes[] =
    "\n"
    "exit codes: 0 ok, 2 usage error, 3 an input or the map cannot be read or\n"
    "written, 4 internal error\n";

#define MAX_INPUTS 256

typedef struct ingest_args {
    const char *inputs[MAX_INPUTS]; /* clouds and depth images */
    int input_count;
    const char *output;
    opx_insert_options insert;
    ingest_frame frame;
    ingest_camera camera;
    ingest_robot robot; /* self-filtering */
    double resolution; /* 0: not given */
    int json;
} ingest_args;

static int ends_with(const char *text, const char *suffix) {
    const size_t n = strlen(text), m = strlen(suffix);
    return n >= m && strcmp(text + n - m, suffix) == 0;
}

/* Returns -1 to go on, else an exit code. */
static int parse_option(cli_args *args, ingest_args *out) {
    int got, code;
    if (ingest_robot_option(args, &out->robot, &code)) return code;
    if (cli_flag(args, "--json")) out->json = 1;
    else if (cli_flag(args, "--endpoints")) out->insert.mode = OPX_INSERT_ENDPOINTS;
    else if (cli_flag(args, "--optical-frame")) out->frame.optical_frame = 1;
    else if ((got = cli_value(args, "-o")) != 0 || (got = cli_value(args, "--output")) != 0) {
        if (got < 0) return cli_usage("ingest", "-o needs a file name");
        out->output = args->value;
    } else if ((got = cli_value(args, "--sensor-pose")) != 0) {
        if (got < 0 || cli_parse_pose(args->value, &out->frame.sensor_pose) != 0)
            return cli_usage("ingest", "--sensor-pose needs x,y,z or x,y,z,qx,qy,qz,qw (finite decimal numbers)");
        out->frame.has_sensor_pose = 1;
    } else if ((got = cli_value(args, "--res")) != 0) {
        if (got < 0 || cli_parse_double(args->value, &out->resolution) != 0 || !(out->resolution > 0.0))
            return cli_usage("ingest", "--res needs a positive resolution in metres");
    } else if ((got = cli_value(args, "--max-range")) != 0) {
        if (got < 0 || cli_parse_double(args->value, &out->insert.max_range) != 0 || !(out->insert.max_range > 0.0))
            return cli_usage("ingest", "--max-range needs a positive distance in metres");
    } else if ((got = ingest_camera_option(args, &out->camera)) != 0) {
        if (got != 1) return got;
    } else {
        return cli_usage("ingest", "unknown option '%s'", args->argv[args->index]);
    }
    return -1;
}

/* Returns -1 to go on, else an exit code (0 after --help). */
static int parse_arguments(int argc, char **argv, ingest_args *out) {
    cli_args args = {argc, argv, 1, NULL};
    const opx_insert_options defaults = OPX_INSERT_OPTIONS_INIT;
    int code;
    memset(out, 0, sizeof *out);
    out->insert = defaults;
    ingest_robot_init(&out->robot);
    for (; args.index < argc; ++args.index) {
        const char *arg = argv[args.index];
        if (cli_is_help(arg)) {
            printf("%s%s%s%s", kHelp, kRobotOptionsHelp, kIngestRobotHelp, kExitCodes);
            return CLI_EXIT_OK;
        }
        if (arg[0] != '-') {
            if (!cloud_file_supported(arg) && !ingest_is_depth_image(arg))
                return cli_usage("ingest", "'%s' is not a .pcd or .ply cloud, nor a .png, .tif or .tiff depth image",
                                 arg);
            if (out->input_count == MAX_INPUTS) return cli_usage("ingest", "more than %d inputs", MAX_INPUTS);
            out->inputs[out->input_count++] = arg;
        } else if ((code = parse_option(&args, out)) >= 0) {
            return code;
        }
    }
    if (out->input_count == 0) return cli_usage("ingest", "no cloud given (nor a depth image)");
    if ((code = ingest_check_camera(&out->camera, out->inputs, out->input_count)) >= 0) return code;
    if ((code = ingest_robot_check(&out->robot)) >= 0) return code;
    if (out->output == NULL) return cli_usage("ingest", "no output map given (-o MAP.bt)");
    if (!ends_with(out->output, ".bt") && !ends_with(out->output, ".ot") && !ends_with(out->output, ".opx"))
        return cli_usage("ingest", "the output map '%s' must end in .bt, .ot or .opx", out->output);
    return -1;
}

/* Loads the existing output map, or makes a new one. */
static int open_map(const ingest_args *a, opx_octree **map, int *updated) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_status status;
    *updated = access(a->output, F_OK) == 0;
    if (!*updated) {
        if (a->resolution > 0.0) options.resolution = a->resolution;
        status = opx_octree_create(&options, map);
        /* --res is the only option given to a new map: the library's range
         * check is the command line's. */
        if (status == OPX_ERROR_INVALID_ARGUMENT) return cli_usage("ingest", "--res: %s", opx_last_error());
        return status == OPX_OK ? -1 : cli_library_fail("ingest", status, "creating the map");
    }
    status = opx_octree_load_file(a->output, NULL, map);
    if (status != OPX_OK) return cli_library_fail("ingest", status, "loading the map %s to update", a->output);
    opx_octree_get_options(*map, &options);
    if (a->resolution > 0.0 && a->resolution != options.resolution)
        return cli_usage("ingest", "%s has resolution %g m, not --res %g", a->output, options.resolution,
                         a->resolution);
    return -1;
}

static void print_input_json(const char *path, const ingest_result *r, int last) {
    const opx_insert_report *p = &r->report;
    int i;
    fputs("    {\"file\": ", stdout);
    json_string(stdout, path);
    fputs(", \"format\": ", stdout);
    json_string(stdout, r->format);
    printf(", \"points\": %zu, \"points_used\": %llu, \"points_nonfinite\": %llu, \"points_out_of_range\": %llu, "
           "\"points_outside_map\": %llu, \"points_on_robot\": %llu, \"points_shadowed\": %llu, "
           "\"pixels_no_return\": %llu, \"cells_hit\": %llu, \"cells_missed\": %llu, \"cells_cleared\": %llu, "
           "\"insert_ms\": %.3f",
           r->points, (unsigned long long)p->points_used, (unsigned long long)p->points_nonfinite,
           (unsigned long long)p->points_out_of_range, (unsigned long long)p->points_outside_map,
           (unsigned long long)p->points_on_robot, (unsigned long long)p->points_shadowed,
           (unsigned long long)p->pixels_no_return, (unsigned long long)p->cells_hit,
           (unsigned long long)p->cells_missed, (unsigned long long)p->cells_cleared, r->insert_ms);
    fputs(", \"sensor_pose\": [", stdout);
    for (i = 0; i < 7; ++i) {
        json_number(stdout, i < 3 ? r->sensor_pose.position[i] : r->sensor_pose.orientation[i - 3]);
        fputs(i < 6 ? ", " : "]", stdout);
    }
    fputs(", \"sensor_pose_from\": ", stdout);
    json_string(stdout, r->pose_source);
    printf("}%s\n", last ? "" : ",");
}

static void print_viewpoint_pose(const opx_pose *p) {
    printf("  sensor pose from the file's VIEWPOINT: %g,%g,%g,%g,%g,%g,%g (x,y,z,qx,qy,qz,qw)\n", p->position[0],
           p->position[1], p->position[2], p->orientation[0], p->orientation[1], p->orientation[2], p->orientation[3]);
}

/* One line per input; with a robot, what the filter took out. */
static void print_input_text(const ingest_args *a, const char *path, const ingest_result *r) {
    const opx_insert_report *p = &r->report;
    printf("%s (%s): %zu %s, %llu used, %llu skipped", path, r->format, r->points,
           ingest_is_depth_image(path) ? "pixels" : "points", (unsigned long long)p->points_used,
           (unsigned long long)(p->points_nonfinite + p->points_out_of_range + p->points_outside_map +
                                p->pixels_no_return));
    if (a->robot.links != NULL)
        printf(", %llu on the robot, %llu shadowed", (unsigned long long)p->points_on_robot,
               (unsigned long long)p->points_shadowed);
    printf("; %llu cells hit, %llu missed", (unsigned long long)p->cells_hit, (unsigned long long)p->cells_missed);
    if (a->robot.links != NULL) printf(", %llu cleared", (unsigned long long)p->cells_cleared);
    printf("; %.1f ms\n", r->insert_ms);
    if (strcmp(r->pose_source, "VIEWPOINT") == 0) print_viewpoint_pose(&r->sensor_pose);
}

static void print_report(const ingest_args *a, const ingest_result *results, int updated,
                         const opx_octree_stats *s) {
    int i;
    if (a->json) {
        fputs("{\n  \"output\": ", stdout);
        json_string(stdout, a->output);
        printf(",\n  \"updated\": %s,\n  \"resolution\": ", updated ? "true" : "false");
        json_number(stdout, s->resolution);
        fputs(",\n  \"clouds\": [\n", stdout);
        for (i = 0; i < a->input_count; ++i) print_input_json(a->inputs[i], &results[i], i + 1 == a->input_count);
        printf("  ],\n  \"leaves\": {\"occupied\": %llu, \"uncertain\": %llu, \"free\": %llu}\n}\n",
               (unsigned long long)s->leaves_occupied, (unsigned long long)s->leaves_uncertain,
               (unsigned long long)s->leaves_free);
        return;
    }
    for (i = 0; i < a->input_count; ++i) print_input_text(a, a->inputs[i], &results[i]);
    printf("%s %s: resolution %g m, leaves occupied %llu, uncertain %llu, free %llu\n",
           updated ? "updated" : "wrote", a->output, s->resolution, (unsigned long long)s->leaves_occupied,
           (unsigned long long)s->leaves_uncertain, (unsigned long long)s->leaves_free);
}

/* A depth image is in its camera's optical frame: placed by --sensor-pose
 * (turned by --optical-frame), without a VIEWPOINT. */
static int ingest_depth(const char *path, const ingest_args *a, opx_octree *map, ingest_result *result) {
    opx_insert_options insert = a->insert;
    result->sensor_pose = ingest_sensor_pose(&a->frame, NULL, &result->pose_source);
    insert.sensor_pose = result->sensor_pose;
    return ingest_depth_file(path, map, &a->camera, &insert, result);
}

static int ingest_all(const ingest_args *a, opx_octree *map, ingest_result *results) {
    cli_progress progress;
    int i, code = -1;
    cli_progress_start(&progress, "ingesting", (size_t)a->input_count);
    for (i = 0; i < a->input_count && code < 0; ++i) {
        const char *path = a->inputs[i];
        code = ingest_is_depth_image(path) ? ingest_depth(path, a, map, &results[i])
                                           : ingest_cloud_file(path, map, &a->frame, &a->insert, &results[i]);
        cli_progress_update(&progress, (size_t)i + 1);
    }
    cli_progress_finish(&progress);
    return code;
}

int cmd_ingest(int argc, char **argv) {
    static ingest_result results[MAX_INPUTS];
    ingest_args a;
    opx_octree *map = NULL;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    opx_status status;
    int updated = 0, code = parse_arguments(argc, argv, &a);
    if (code >= 0) return code;
    code = ingest_robot_load(&a.robot, &a.insert);
    if (code < 0) code = open_map(&a, &map, &updated);
    if (code < 0) code = ingest_all(&a, map, results);
    if (code < 0 && (status = opx_octree_save_file(map, a.output, OPX_FORMAT_AUTO)) != OPX_OK)
        code = cli_library_fail("ingest", status, "saving the map %s", a.output);
    if (code < 0 && (status = opx_octree_get_stats(map, &stats)) != OPX_OK)
        code = cli_library_fail("ingest", status, "reading the map");
    if (code < 0) {
        print_report(&a, results, updated, &stats);
        code = CLI_EXIT_OK;
    }
    opx_octree_destroy(map);
    ingest_robot_free(&a.robot);
    return code;
}
