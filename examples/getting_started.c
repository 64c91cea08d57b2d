/* Getting started in C: a map from a file, a robot from URDF, one query,
 * then a batch of configurations.  Uses the shared data ($OPX_DATA_DIR,
 * else ../shared/data): the geb079 map and the PR2; exits 77 without it.
 *   cc -std=c99 getting_started.c $(pkg-config --cflags --libs octoprox) */
#include <octoprox/octoprox.h>
#include <stdio.h>
#include <stdlib.h>

#define ROWS 100

static int ok(opx_status status, const char *what) {
    if (status != OPX_OK)
        fprintf(stderr, "%s: %s: %s\n", what, opx_status_name(status), opx_last_error());
    return status == OPX_OK;
}

int main(void) {
    const char *data = getenv("OPX_DATA_DIR") ? getenv("OPX_DATA_DIR") : "../shared/data";
    char map_path[1024], urdf_path[1024], package[1100];
    snprintf(map_path, sizeof map_path, "%s/maps/geb079.bt", data);
    snprintf(urdf_path, sizeof urdf_path, "%s/robots/pr2_description/urdf/robot.xml", data);
    snprintf(package, sizeof package, "moveit_resources_pr2_description=%s/robots/pr2_description",
             data);
    FILE *probe = fopen(map_path, "rb");
    if (!probe) {
        printf("skipped: no %s (set OPX_DATA_DIR)\n", map_path);
        return 77;
    }
    fclose(probe);

    /* A map from a .bt file: the resolution comes from the file. */
    opx_octree *map = NULL;
    if (!ok(opx_octree_load_file(map_path, NULL, &map), "opx_octree_load_file")) return 1;

    /* A robot from URDF: package:// meshes resolved through NAME=DIR. */
    const char *package_dirs[] = {package};
    opx_urdf_options urdf = OPX_URDF_OPTIONS_INIT;
    urdf.package_dirs = package_dirs;
    urdf.package_dir_count = 1;
    opx_linkset *robot = NULL;
    opx_query *query = NULL;
    double *rows = NULL;
    int good = ok(opx_linkset_load_urdf_file(urdf_path, &urdf, &robot), "load_urdf_file") &&
               ok(opx_query_create(NULL, &query), "opx_query_create");

    /* One query: every joint at 0, the root at the map origin. */
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    opx_distance_result near = OPX_DISTANCE_RESULT_INIT;
    good = good && ok(opx_query_collide(query, map, robot, NULL, &hit), "opx_query_collide") &&
           ok(opx_query_distance(query, map, robot, NULL, &near), "opx_query_distance");
    if (good) printf("collided: %d, distance %.3f m\n", hit.collided, near.distance);

    /* A batch: 100 rows of every joint (model order), the right shoulder
     * swept from -2 to 0.5 rad, two threads, with distances. */
    uint32_t joints = 0, shoulder = 0;
    good = good && ok(opx_linkset_get_joint_count(robot, &joints), "get_joint_count") &&
           ok(opx_linkset_find_joint(robot, "r_shoulder_pan_joint", &shoulder), "find_joint");
    rows = good ? calloc((size_t)ROWS * joints, sizeof *rows) : NULL;
    uint8_t collided[ROWS];
    double distances[ROWS];
    if (rows) {
        for (size_t i = 0; i < ROWS; i++)
            rows[i * joints + shoulder] = -2.0 + 2.5 * (double)i / (ROWS - 1);
        opx_batch_request request = OPX_BATCH_REQUEST_INIT;
        request.compute_distance = 1;
        request.max_threads = 2;
        good = ok(opx_query_check_configurations(query, map, robot, rows, ROWS, joints, 0,
                                                 NULL, 0, 0, /* the root at the map origin */
                                                 &request, collided, distances, ROWS),
                  "check_configurations");
    } else {
        good = 0;
    }
    if (good) {
        size_t count = 0;
        double least = distances[0];
        for (size_t i = 0; i < ROWS; i++) {
            count += collided[i];
            if (distances[i] < least) least = distances[i];
        }
        printf("batch: %zu of %d configurations collide, least distance %.3f m\n", count, ROWS,
               least);
    }
    free(rows);
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(map);
    return good ? 0 : 1;
}
