#include "check_path.h"

#include "cli.h"
#include "path_csv.h"

#include <math.h>
#include <stdlib.h>

/* The path as rows of every joint (model order): the robot's current
 * positions (its --joints) with the CSV's joints replaced. */
typedef struct path_rows {
    double *values; /* waypoint_count x joint_count */
    size_t joint_count;
} path_rows;

static int fill_rows(const check_context *c, const opx_linkset *links, const path_csv *csv, path_rows *rows) {
    uint32_t count = 0, joint;
    size_t w, j, got = 0;
    opx_linkset_get_joint_count(links, &count);
    rows->joint_count = count;
    rows->values = malloc(csv->waypoint_count * (count ? count : 1) * sizeof(double));
    if (rows->values == NULL) return cli_fail("check", CLI_EXIT_INTERNAL, "out of memory for the path's rows");
    if (count > 0 && opx_linkset_get_joint_positions(links, rows->values, count, &got) != OPX_OK)
        return cli_library_fail("check", OPX_ERROR_INTERNAL, "reading the joint positions");
    for (w = 1; w < csv->waypoint_count; ++w)
        for (j = 0; j < count; ++j) rows->values[w * count + j] = rows->values[j];
    for (j = 0; j < csv->joint_count; ++j) {
        if (opx_linkset_find_joint(links, csv->names[j], &joint) != OPX_OK)
            return cli_fail("check", CLI_EXIT_INPUT, "%s: the waypoints name a joint the robot does not have: %s",
                            c->path_file, opx_last_error());
        for (w = 0; w < csv->waypoint_count; ++w)
            rows->values[w * count + joint] = csv->values[w * csv->joint_count + j];
    }
    return -1;
}

/* opx_query_check_motions checks at most this many steps a motion
 * (include/octoprox/batch.h). */
#define MAX_MOTION_STEPS 1e7

/* A --resolution that cuts some motion into more steps than are checked
 * is a usage error (exit 2), found before any query runs. */
static int check_resolution(const check_context *c, const path_csv *csv, const path_rows *rows) {
    size_t m, j;
    if (c->certified) return -1; /* the resolution does not apply */
    for (m = 0; m + 1 < csv->waypoint_count; ++m) {
        const double *start = rows->values + m * rows->joint_count, *goal = start + rows->joint_count;
        double largest = 0.0;
        for (j = 0; j < rows->joint_count; ++j)
            if (fabs(goal[j] - start[j]) > largest) largest = fabs(goal[j] - start[j]);
        if (largest / c->resolution > MAX_MOTION_STEPS)
            return cli_usage("check", "--resolution %g cuts motion %zu (a joint moves %g) into %.3g steps; at most "
                             "%g steps a motion are checked", c->resolution, m, largest, ceil(largest / c->resolution),
                             MAX_MOTION_STEPS);
    }
    return -1;
}

/* A library failure on the path's values is the file's fault (exit 3). */
static int path_fail(const check_context *c, opx_status status, const char *what) {
    if (status == OPX_ERROR_INVALID_ARGUMENT)
        return cli_fail("check", CLI_EXIT_INPUT, "%s: %s", c->path_file, opx_last_error());
    return cli_library_fail("check", status, "%s", what);
}

static int check_waypoints(const check_context *c, const opx_linkset *links, const path_csv *csv,
                           const path_rows *rows, opx_path_result *result) {
    size_t w;
    opx_status status;
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    uint8_t *collided = malloc(csv->waypoint_count);
    if (collided == NULL) return cli_fail("check", CLI_EXIT_INTERNAL, "out of memory for the path's answers");
    request.unknown_policy = c->unknown_policy;
    request.obstacle_geometry = c->obstacle_geometry;
    request.max_threads = c->threads;
    request.self_collision = c->want_self;
    status = opx_query_check_configurations(c->query, c->map, links, rows->values, csv->waypoint_count,
                                            rows->joint_count, 0, &c->robot->base_pose, 1, 0, &request, collided,
                                            NULL, csv->waypoint_count);
    for (w = 0; status == OPX_OK && w < csv->waypoint_count && result->first_colliding_waypoint < 0; ++w)
        if (collided[w]) result->first_colliding_waypoint = (int64_t)w;
    free(collided);
    if (status != OPX_OK) return path_fail(c, status, "checking the waypoints");
    result->collided = result->first_colliding_waypoint >= 0;
    return -1;
}

static int check_motions(const check_context *c, const opx_linkset *links, const path_csv *csv,
                         const path_rows *rows, check_motions_report *report) {
    const size_t motions = csv->waypoint_count - 1;
    size_t m;
    opx_status status;
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    uint8_t *collided = malloc(motions ? motions : 1);
    double *fractions = malloc((motions ? motions : 1) * sizeof(double));
    report->count = motions;
    if (collided == NULL || fractions == NULL) {
        free(collided), free(fractions);
        return cli_fail("check", CLI_EXIT_INTERNAL, "out of memory for the path's motions");
    }
    request.unknown_policy = c->unknown_policy;
    request.obstacle_geometry = c->obstacle_geometry;
    request.resolution = c->resolution;
    request.max_threads = c->threads;
    request.self_collision = c->want_self;
    request.check = c->certified ? OPX_MOTION_CERTIFIED : OPX_MOTION_SAMPLED;
    status = motions == 0 ? OPX_OK
                          : opx_query_check_motions(c->query, c->map, links, rows->values,
                                                    rows->values + rows->joint_count, motions, rows->joint_count, 0,
                                                    &c->robot->base_pose, 1, 0, &request, collided, fractions, motions);
    for (m = 0; status == OPX_OK && m < motions && report->first_colliding < 0; ++m)
        if (collided[m]) report->first_colliding = (int64_t)m, report->first_fraction = fractions[m];
    free(collided), free(fractions);
    return status == OPX_OK ? -1 : path_fail(c, status, "checking the motions");
}

/* Every link's pose at every waypoint (FK on the link set, per waypoint). */
static int path_poses(const check_context *c, opx_linkset *links, const path_csv *csv, const path_rows *rows,
                      opx_pose **out) {
    uint32_t link_count = 0, l;
    size_t w;
    opx_linkset_get_link_count(links, &link_count);
    *out = malloc(csv->waypoint_count * (link_count ? link_count : 1) * sizeof(opx_pose));
    if (*out == NULL) return cli_fail("check", CLI_EXIT_INTERNAL, "out of memory for the path's poses");
    for (w = 0; w < csv->waypoint_count; ++w) {
        const opx_status status = opx_linkset_set_joint_positions(links, rows->values + w * rows->joint_count,
                                                                  rows->joint_count, &c->robot->base_pose);
        if (status != OPX_OK) return path_fail(c, status, "the path's kinematics");
        for (l = 0; l < link_count; ++l) opx_linkset_get_pose(links, l, &(*out)[w * link_count + l]);
    }
    return -1;
}

/* The minimum distance and the swept cost over the waypoints. */
static int path_query(const check_context *c, opx_linkset *links, const path_csv *csv, const path_rows *rows,
                      opx_path_result *result) {
    opx_pose *poses = NULL;
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    opx_status status;
    int code = path_poses(c, links, csv, rows, &poses);
    request.unknown_policy = c->unknown_policy;
    request.obstacle_geometry = c->obstacle_geometry;
    request.compute_distance = c->want_distance;
    request.compute_cost = c->want_cost;
    request.max_cost_boxes = CHECK_MAX_LISTED;
    if (code < 0) {
        status = opx_query_path(c->query, c->map, links, poses, csv->waypoint_count, 0, 0, &request, result);
        if (status != OPX_OK) code = cli_library_fail("check", status, "the path query");
    }
    free(poses);
    return code;
}

static int check_rows(check_context *c, opx_linkset *links, const path_csv *csv, const path_rows *rows,
                      int *collided) {
    opx_path_result result = OPX_PATH_RESULT_INIT;
    check_motions_report motions = {0, -1, -1.0};
    int code = check_resolution(c, csv, rows);
    if (code < 0) code = check_waypoints(c, links, csv, rows, &result);
    if (code < 0) code = check_motions(c, links, csv, rows, &motions);
    if (code < 0 && (c->want_distance || c->want_cost)) {
        const int64_t first = result.first_colliding_waypoint;
        code = path_query(c, links, csv, rows, &result);
        result.first_colliding_waypoint = first, result.collided = first >= 0;
    }
    if (code >= 0) return code;
    *collided = result.collided || motions.first_colliding >= 0;
    check_print_path(c, csv->waypoint_count, &result);
    check_print_motions(c, &motions);
    if (c->want_cost) check_print_cost(c, result.total_cost, result.cost_boxes_found, result.cost_box_count);
    return -1;
}

int check_path(check_context *c, opx_linkset *links, int *collided) {
    char error[512];
    path_csv csv;
    path_rows rows = {NULL, 0};
    int code;
    if (path_csv_read(c->path_file, &csv, error, sizeof error) != 0)
        return cli_fail("check", CLI_EXIT_INPUT, "%s", error);
    code = fill_rows(c, links, &csv, &rows);
    if (code < 0) code = check_rows(c, links, &csv, &rows, collided);
    free(rows.values);
    path_csv_free(&csv);
    return code;
}
