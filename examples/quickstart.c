/* OctoProx quickstart: insert one sensor frame, classify a point, print the
 * map's stats.  cc -std=c99 quickstart.c $(pkg-config --cflags --libs octoprox) */
#include <octoprox/octoprox.h>
#include <stdio.h>

static int ok(opx_status status, const char *what) {
    if (status != OPX_OK)
        fprintf(stderr, "%s failed: %s: %s\n", what, opx_status_name(status), opx_last_error());
    return status == OPX_OK;
}

int main(void) {
    static const char *const class_names[] = {"unknown", "free", "uncertain", "occupied"};
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = 0.1; /* metres */
    opx_octree *tree = NULL;
    if (!ok(opx_octree_create(&options, &tree), "opx_octree_create")) return 1;

    /* Three points in the SENSOR frame (x y z, float32, packed). */
    const float points[3][3] = {{2.05f, 0.05f, 0.05f}, {2.05f, 0.25f, 0.05f}, {2.05f, -0.15f, 0.45f}};
    /* The sensor 1 m above the map origin, turned 90 degrees about z:
     * position x y z, orientation qx qy qz qw (ROS order). */
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.sensor_pose.position[2] = 1.0;
    insert.sensor_pose.orientation[2] = 0.70710678118654752;
    insert.sensor_pose.orientation[3] = 0.70710678118654752;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    const double query[3] = {-0.05, 2.05, 1.05}; /* map frame: where the first point lands */
    opx_cell_info cell = OPX_CELL_INFO_INIT;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    const int good =
        ok(opx_octree_insert_points(tree, points, 3, 0, OPX_SCALAR_FLOAT32, &insert, &report),
           "opx_octree_insert_points") &&
        ok(opx_octree_classify(tree, query, &cell), "opx_octree_classify") &&
        ok(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
    if (good) {
        printf("octoprox %s: %llu points used, %llu cells hit, %llu cells free\n", opx_version(),
               (unsigned long long)report.points_used, (unsigned long long)report.cells_hit,
               (unsigned long long)report.cells_missed);
        printf("(%.2f, %.2f, %.2f) is %s, p = %.3f\n", query[0], query[1], query[2],
               class_names[cell.cell_class], cell.probability);
        printf("leaves: %llu occupied, %llu free; occupied box (%.2f %.2f %.2f)-(%.2f %.2f %.2f)\n",
               (unsigned long long)stats.leaves_occupied, (unsigned long long)stats.leaves_free,
               stats.occupied_min[0], stats.occupied_min[1], stats.occupied_min[2],
               stats.occupied_max[0], stats.occupied_max[1], stats.occupied_max[2]);
    }
    opx_octree_destroy(tree);
    return good ? 0 : 1;
}
