/* octoprox check MAP --urdf ...: collision, distance and cost of a robot. */
#include "check_path.h"
#include "check_report.h"
#include "check_self.h"
#include "cli.h"
#include "commands.h"
#include "robot_args.h"

#include <stdlib.h>
#include <string.h>

static const char kHelp[] =
    "usage: octoprox check [MAP.bt|MAP.ot|MAP.opx] [--scene FILE] --urdf ROBOT.urdf [--package-dir DIR]...\n"
    "                      [--srdf ROBOT.srdf] [--joints name=value,...]\n"
    "                      [--base-pose POSE] [--padding M] [--disable-link NAME]...\n"
    "                      [--self] [--distance] [--cost] [--unknown free|occupied]\n"
    "                      [--obstacles cells|point-extents]\n"
    "                      [--path FILE.csv [--resolution R | --certified] [--threads N]] [--json]\n"
    "\n"
    "Checks one robot configuration (or a path of them) against the map:\n"
    "collision with the occupied cells (every contact's link is listed), and\n"
    "optionally the minimum distance and the cost of uncertain and unknown\n"
    "space the robot overlaps (probability x volume, m^3; paper IV.C).\n"
    "With --scene, also the known objects of a MoveIt planning scene; with --self,\n"
    "also the robot against itself; the map may then be left out.\n"
    "\n"
    "options:\n"
    "  --scene FILE          also the objects of a MoveIt planning scene: a\n"
    "                        moveit_msgs/PlanningScene as YAML (.yaml, .yml) or\n"
    "                        MoveIt's scene text (.scene); its frame is the map's;\n"
    "                        contacts and the distance name the object (not\n"
    "                        with --path)\n"
    "  --self                also self-collision: every pair of links but the\n"
    "                        SRDF's disabled pairs (adjacent links are not skipped\n"
    "                        unless the SRDF lists them); with --distance also the\n"
    "                        self-distance; with --path every waypoint and motion\n"
    "                        against itself too (without a map: only itself)\n"
    "  --distance            also the minimum distance to an obstacle (metres)\n"
    "  --cost                also the cost of uncertain/unknown space\n"
    "  --unknown free|occupied\n"
    "                        what never-observed space is (default free)\n"
    "  --obstacles cells|point-extents\n"
    "                        what an occupied cell is: its whole cube (default),\n"
    "                        or the box of the sensed points in it, where the map\n"
    "                        keeps one (maps made from clouds, saved as .opx;\n"
    "                        .bt and .ot keep none)\n"
    "  --path FILE.csv       check a path: the first line names joints, each\n"
    "                        further line is one waypoint's values; joints not\n"
    "                        in the file keep their --joints values; every\n"
    "                        waypoint and the straight joint-space motion\n"
    "                        between each two are checked\n"
    "  --resolution R        --path: the largest joint step between two checked\n"
    "                        configurations of a motion (rad or m; default 0.01)\n"
    "  --certified           --path: check every configuration of each motion, not\n"
    "                        samples (conservative advancement on exact distances;\n"
    "                        a collision's fraction is within 1e-3 of the first)\n"
    "  --threads N           --path: threads checking it (default 1; 0: every core)\n"
    "  --json                one JSON object: map, scene, scene_objects, urdf,\n"
    "                        links, padding, disabled_links [names], srdf,\n"
    "                        srdf_disabled_pairs, unknown, obstacles; then\n"
    "                        contact_count, colliding_links [names], contacts\n"
    "                        [{link, object: null, cell_class, cell_center,\n"
    "                        cell_size} or {link, object, object_shape}] (one\n"
    "                        configuration) or path {file, waypoints,\n"
    "                        first_colliding_waypoint, min_distance,\n"
    "                        min_distance_waypoint} and motions {count,\n"
    "                        certified, resolution (null when certified),\n"
    "                        first_colliding,\n"
    "                        first_collision_fraction} (--path); distance {found,\n"
    "                        distance, link, object, point_on_link,\n"
    "                        point_on_cell} with --distance; cost {total,\n"
    "                        boxes_found, boxes [{link, cell_class, min, max,\n"
    "                        probability, cost}]} with --cost; self\n"
    "                        {checked_pairs, collided, contact_count,\n"
    "                        contacts [{link_a, link_b, depth, position}]} and\n"
    "                        self_distance {found, distance, link_a, link_b,\n"
    "                        point_on_a, point_on_b} with --self (one\n"
    "                        configuration); collided, query_ms\n"
    "  -h, --help            this help\n"
    "\n"
    "%s"
    "\n"
    "exit codes: 0 no collision, 1 collision with the map, a scene object or (--self)\n"
    "itself (with\n"
    "--path: some waypoint or motion),\n"
    "2 usage error, 3 a file cannot be read or is malformed, 4 internal error\n";

typedef struct check_args {
    const char *map;
    robot_args robot;
    check_context context;
} check_args;

static int parse_option(cli_args *args, void *context) {
    check_args *a = context;
    int got, code;
    if (robot_args_option(args, &a->robot, "check", &code)) return code;
    if (cli_flag(args, "--json")) a->context.json = 1;
    else if (cli_flag(args, "--distance")) a->context.want_distance = 1;
    else if (cli_flag(args, "--cost")) a->context.want_cost = 1;
    else if (cli_flag(args, "--self")) a->context.want_self = 1;
    else if (cli_flag(args, "--certified")) a->context.certified = 1;
    else if ((got = cli_value(args, "--unknown")) != 0) {
        if (got > 0 && strcmp(args->value, "free") == 0) a->context.unknown_policy = OPX_UNKNOWN_FREE;
        else if (got > 0 && strcmp(args->value, "occupied") == 0) a->context.unknown_policy = OPX_UNKNOWN_OCCUPIED;
        else return cli_usage("check", "--unknown needs 'free' or 'occupied'");
    } else if ((got = cli_value(args, "--scene")) != 0) {
        if (got < 0) return cli_usage("check", "--scene needs a scene file (.yaml, .yml or .scene)");
        a->context.scene_path = args->value;
    } else if ((got = cli_value(args, "--obstacles")) != 0) {
        if (got > 0 && strcmp(args->value, "cells") == 0) a->context.obstacle_geometry = OPX_OBSTACLE_CELLS;
        else if (got > 0 && strcmp(args->value, "point-extents") == 0)
            a->context.obstacle_geometry = OPX_OBSTACLE_POINT_EXTENTS;
        else return cli_usage("check", "--obstacles needs 'cells' or 'point-extents'");
    } else if ((got = cli_value(args, "--path")) != 0) {
        if (got < 0) return cli_usage("check", "--path needs a CSV file");
        a->context.path_file = args->value;
    } else if ((got = cli_value(args, "--resolution")) != 0) {
        if (got < 0 || cli_parse_double(args->value, &a->context.resolution) != 0 || !(a->context.resolution > 0.0))
            return cli_usage("check", "--resolution needs a step > 0 (rad or m)");
    } else if ((got = cli_value(args, "--threads")) != 0) {
        const int digits = got > 0 && args->value[0] != '\0' && args->value[strspn(args->value, "0123456789")] == '\0';
        const long threads = digits && strlen(args->value) <= 4 ? strtol(args->value, NULL, 10) : -1;
        if (threads < 0 || threads > 1024)
            return cli_usage("check", "--threads needs a count from 0 (every core) to 1024");
        a->context.threads = (uint32_t)threads;
    } else {
        return cli_usage("check", "unknown option '%s'", args->argv[args->index]);
    }
    return -1;
}

static int parse_arguments(int argc, char **argv, check_args *a) {
    int code;
    memset(a, 0, sizeof *a);
    a->context.resolution = 0.01;
    a->context.threads = 1;
    robot_args_init(&a->robot);
    code = cli_walk_map_arguments(argc, argv, "check", kHelp, kRobotOptionsHelp, &a->map, parse_option, a);
    if (code >= 0) return code;
    if (a->map == NULL && !a->context.want_self && a->context.scene_path == NULL)
        return cli_usage("check", "no map file given (or --self) and no --scene");
    if (a->context.scene_path != NULL && a->context.path_file != NULL)
        return cli_usage("check", "--scene and --path do not go together: paths check no scene objects");
    if (a->map == NULL && (a->context.path_file || a->context.want_cost))
        return cli_usage("check", "--path and --cost need a map file");
    if (a->context.certified && a->context.path_file == NULL)
        return cli_usage("check", "--certified checks the motions of a --path");
    if (a->robot.urdf == NULL) return cli_usage("check", "no robot given (--urdf ROBOT.urdf)");
    a->context.map_path = a->map;
    a->context.urdf_path = a->robot.urdf;
    a->context.robot = &a->robot;
    return -1;
}

/* The robot against the map: contacts, cost, distance. */
static int check_map(check_context *c, int *collided) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    opx_distance_request distance_request = OPX_DISTANCE_REQUEST_INIT;
    opx_distance_result distance = OPX_DISTANCE_RESULT_INIT;
    opx_status status;
    request.unknown_policy = c->unknown_policy;
    request.obstacle_geometry = c->obstacle_geometry;
    request.max_contacts = UINT32_MAX; /* every contact: the report names each colliding link */
    request.compute_cost = c->want_cost;
    request.max_cost_boxes = CHECK_MAX_LISTED;
    status = opx_query_collide(c->query, c->map, c->links, &request, &result);
    if (status != OPX_OK) return cli_library_fail("check", status, "the collision query");
    *collided = result.collided;
    check_print_contacts(c, &result);
    if (c->want_cost) check_print_cost(c, result.total_cost, result.cost_boxes_found, result.cost_box_count);
    if (!c->want_distance) return -1;
    distance_request.unknown_policy = c->unknown_policy;
    distance_request.obstacle_geometry = c->obstacle_geometry;
    status = opx_query_distance(c->query, c->map, c->links, &distance_request, &distance);
    if (status != OPX_OK) return cli_library_fail("check", status, "the distance query");
    check_print_distance(c, &distance);
    return -1;
}

/* One configuration: the map (when given), then the robot itself (--self). */
static int check_one(check_context *c, int *collided) {
    int self_collided = 0, code = c->map != NULL || c->world != NULL ? check_map(c, collided) : -1;
    if (code < 0 && c->want_self) code = check_self(c, &self_collided);
    *collided = *collided || self_collided;
    return code;
}

static int run(check_args *a, opx_octree *map, opx_linkset *links, const opx_world *world) {
    check_context *c = &a->context;
    int collided = 0, code;
    double start;
    opx_status status = opx_query_create(NULL, &c->query);
    if (status != OPX_OK) return cli_library_fail("check", status, "creating a query");
    c->world = world;
    if (world != NULL && (status = opx_query_set_world(c->query, world)) != OPX_OK) {
        opx_query_destroy(c->query);
        return cli_library_fail("check", status, "setting the scene");
    }
    c->map = map;
    c->links = links;
    check_print_head(c);
    start = cli_now_ms();
    code = c->path_file ? check_path(c, links, &collided) : check_one(c, &collided);
    if (code < 0) check_print_tail(c, collided, cli_now_ms() - start);
    opx_query_destroy(c->query);
    return code >= 0 ? code : (collided ? CLI_EXIT_COLLISION : CLI_EXIT_OK);
}

int cmd_check(int argc, char **argv) {
    check_args a;
    opx_octree *map = NULL;
    opx_linkset *links = NULL;
    opx_world *world = NULL;
    opx_status status;
    int code = parse_arguments(argc, argv, &a);
    if (code >= 0) return code;
    status = a.map != NULL ? opx_octree_load_file(a.map, NULL, &map) : OPX_OK;
    if (status != OPX_OK) return cli_library_fail("check", status, "loading the map %s", a.map);
    status = a.context.scene_path != NULL ? opx_world_load_scene_file(a.context.scene_path, &world) : OPX_OK;
    if (status != OPX_OK) {
        opx_octree_destroy(map);
        return cli_library_fail("check", status, "loading the scene %s", a.context.scene_path);
    }
    code = robot_load(&a.robot, "check", &links);
    if (code < 0) code = run(&a, map, links, world);
    opx_linkset_destroy(links);
    opx_world_destroy(world);
    opx_octree_destroy(map);
    return code;
}
