/* octoprox export MAP --obj|--ply OUT: cells and a robot for mesh viewers. */
#include "cli.h"
#include "commands.h"
#include "mesh_out.h"
#include "robot_args.h"
#include "shape_mesh.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

static const char kHelp[] =
    "usage: octoprox export MAP.bt|MAP.ot (--obj OUT.obj | --ply OUT.ply) [--uncertain]\n"
    "                       [--points] [--urdf ROBOT.urdf --package-dir DIR\n"
    "                       --joints name=value,... --base-pose POSE] [--json]\n"
    "\n"
    "Writes the occupied (and with --uncertain the uncertain) cells as cubes,\n"
    "map frame, metres, for MeshLab or CloudCompare.  With --urdf the robot's\n"
    "collision shapes go in the same file (primitives triangulated, meshes as\n"
    "they are), and the links that collide with the map are marked.\n"
    "\n"
    "OBJ: groups and materials 'occupied', 'uncertain', 'link_<name>' and\n"
    "'colliding_<name>' (materials in OUT.obj.mtl).  PLY (binary little\n"
    "endian): vertex colours: occupied blue, uncertain yellow, robot green,\n"
    "colliding links red.  A cell is 8 vertices and 6 quads.\n"
    "\n"
    "options:\n"
    "  --obj OUT       write Wavefront OBJ (+ OUT.mtl)\n"
    "  --ply OUT       write PLY\n"
    "  --uncertain     also the uncertain cells\n"
    "  --points        PLY only: one vertex per cell (its centre), no cubes\n"
    "  --json          one JSON object: output, format, cells {occupied,\n"
    "                  uncertain}, robot_links, colliding_links [names],\n"
    "                  vertices, faces\n"
    "  -h, --help      this help\n"
    "\n"
    "%s"
    "\n"
    "exit codes: 0 ok, 2 usage error, 3 a file cannot be read or written, 4\n"
    "internal error\n";

typedef struct export_args {
    const char *map, *output;
    int ply, uncertain, points, json;
    robot_args robot;
} export_args;

static int set_output(const cli_args *args, export_args *a, int got, int ply) {
    if (got < 0) return cli_usage("export", "%s needs a file name", ply ? "--ply" : "--obj");
    if (a->output != NULL) return cli_usage("export", "give one of --obj and --ply, once");
    a->output = args->value;
    a->ply = ply;
    return -1;
}

static int parse_option(cli_args *args, void *context) {
    export_args *a = context;
    int got, code;
    if (robot_args_option(args, &a->robot, "export", &code)) return code;
    if (cli_flag(args, "--json")) a->json = 1;
    else if (cli_flag(args, "--uncertain")) a->uncertain = 1;
    else if (cli_flag(args, "--points")) a->points = 1;
    else if ((got = cli_value(args, "--obj")) != 0) return set_output(args, a, got, 0);
    else if ((got = cli_value(args, "--ply")) != 0) return set_output(args, a, got, 1);
    else return cli_usage("export", "unknown option '%s'", args->argv[args->index]);
    return -1;
}

static int parse_arguments(int argc, char **argv, export_args *a) {
    int code;
    memset(a, 0, sizeof *a);
    robot_args_init(&a->robot);
    code = cli_walk_map_arguments(argc, argv, "export", kHelp, kRobotOptionsHelp, &a->map, parse_option, a);
    if (code >= 0) return code;
    if (a->map == NULL) return cli_usage("export", "no map file given");
    if (a->output == NULL) return cli_usage("export", "no output given (--obj OUT or --ply OUT)");
    if (a->points && !a->ply) return cli_usage("export", "--points needs --ply");
    if (a->robot.urdf == NULL && (a->robot.joints || a->robot.package_dir_count))
        return cli_usage("export", "--joints and --package-dir need --urdf");
    return -1;
}

/* Adds the cells of one class; returns how many, or -1 (out of memory). */
static long long add_cells(const opx_octree *map, uint32_t mask, const export_args *a, mesh_out *mesh, uint32_t group) {
    size_t count = 0, i;
    opx_leaf *leaves;
    cli_progress progress;
    if (opx_octree_get_leaves(map, mask, NULL, 0, &count) != OPX_ERROR_BUFFER_TOO_SMALL && count != 0) return -1;
    if (count == 0) return 0;
    if ((leaves = malloc(count * sizeof *leaves)) == NULL || opx_octree_get_leaves(map, mask, leaves, count, &count) != OPX_OK) {
        free(leaves);
        return -1;
    }
    cli_progress_start(&progress, mask == OPX_MASK_OCCUPIED ? "occupied cells" : "uncertain cells", count);
    for (i = 0; i < count; ++i) {
        if (a->points) mesh_add_vertex(mesh, group, leaves[i].center);
        else mesh_add_cube(mesh, group, leaves[i].center, leaves[i].size);
        if ((i & 1023) == 0) cli_progress_update(&progress, i);
    }
    cli_progress_finish(&progress);
    free(leaves);
    return mesh->failed ? -1 : (long long)count;
}

/* Marks links touching an obstacle (every contact of one query). */
static int mark_colliding(const opx_octree *map, const opx_linkset *links, unsigned char *colliding, uint32_t link_count) {
    opx_query *query = NULL;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    uint64_t i;
    opx_status status = opx_query_create(NULL, &query);
    request.max_contacts = UINT32_MAX;
    if (status == OPX_OK) status = opx_query_collide(query, map, links, &request, &result);
    for (i = 0; status == OPX_OK && i < result.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(query, (size_t)i, &contact) == OPX_OK && contact.link < link_count)
            colliding[contact.link] = 1;
    }
    opx_query_destroy(query);
    return status == OPX_OK ? -1 : cli_library_fail("export", status, "the collision query");
}

static void print_report(const export_args *a, const long long cells[2], const opx_linkset *links,
                         const unsigned char *colliding, uint32_t link_count, const mesh_out *mesh) {
    uint32_t l;
    int first = 1;
    if (a->json) {
        fputs("{\n  \"output\": ", stdout);
        json_string(stdout, a->output);
        printf(",\n  \"format\": \"%s\",\n  \"cells\": {\"occupied\": %lld, \"uncertain\": %lld},\n"
               "  \"robot_links\": %u,\n  \"colliding_links\": [", a->ply ? "ply" : "obj", cells[0], cells[1], link_count);
    } else {
        printf("wrote %s: %lld occupied and %lld uncertain cells, %u robot links; %zu vertices, %zu faces\n",
               a->output, cells[0], cells[1], link_count, mesh->vertex_count, mesh->face_count);
        if (link_count) printf("colliding links:");
    }
    for (l = 0; l < link_count; ++l) {
        const char *name = "?";
        if (!colliding[l]) continue;
        opx_linkset_get_link_name(links, l, &name);
        if (a->json) {
            fputs(first ? "" : ", ", stdout);
            json_string(stdout, name);
        } else {
            printf(" %s", name);
        }
        first = 0;
    }
    if (a->json) printf("],\n  \"vertices\": %zu,\n  \"faces\": %zu\n}\n", mesh->vertex_count, mesh->face_count);
    else if (link_count) printf("%s\n", first ? " none" : "");
}

static int add_robot(const export_args *a, const opx_octree *map, mesh_out *mesh, opx_linkset **links,
                     unsigned char **colliding, uint32_t *link_count) {
    uint32_t *groups, l;
    int code = robot_load(&a->robot, "export", links);
    if (code >= 0) return code;
    opx_linkset_get_link_count(*links, link_count);
    *colliding = calloc(*link_count + 1, 1);
    groups = calloc(*link_count + 1, sizeof *groups);
    if (*colliding == NULL || groups == NULL) code = cli_fail("export", CLI_EXIT_INTERNAL, "out of memory");
    if (code < 0) code = mark_colliding(map, *links, *colliding, *link_count);
    for (l = 0; code < 0 && l < *link_count; ++l) {
        char name[160];
        const char *link_name = "?";
        opx_linkset_get_link_name(*links, l, &link_name);
        snprintf(name, sizeof name, "%s_%s", (*colliding)[l] ? "colliding" : "link", link_name);
        groups[l] = (*colliding)[l] ? mesh_add_group(mesh, name, 220, 30, 30) : mesh_add_group(mesh, name, 60, 180, 75);
    }
    if (code < 0 && linkset_to_mesh(*links, mesh, groups) != 0)
        code = cli_fail("export", CLI_EXIT_INTERNAL, "the robot's shapes could not be triangulated (out of memory?)");
    free(groups);
    return code;
}

static int export_map(const export_args *a, const opx_octree *map) {
    mesh_out mesh;
    opx_linkset *links = NULL;
    unsigned char *colliding = NULL;
    uint32_t link_count = 0;
    long long cells[2] = {0, 0};
    int code = -1;
    mesh_init(&mesh);
    cells[0] = add_cells(map, OPX_MASK_OCCUPIED, a, &mesh, mesh_add_group(&mesh, "occupied", 70, 90, 200));
    if (a->uncertain && cells[0] >= 0)
        cells[1] = add_cells(map, OPX_MASK_UNCERTAIN, a, &mesh, mesh_add_group(&mesh, "uncertain", 240, 200, 40));
    if (cells[0] < 0 || cells[1] < 0) code = cli_fail("export", CLI_EXIT_INTERNAL, "out of memory for the cells");
    if (code < 0 && a->robot.urdf != NULL) code = add_robot(a, map, &mesh, &links, &colliding, &link_count);
    if (code < 0 && (a->ply ? mesh_write_ply(&mesh, a->output) : mesh_write_obj(&mesh, a->output)) != 0)
        code = cli_fail("export", CLI_EXIT_INPUT, "%s: cannot be written (%s)", a->output, strerror(errno));
    if (code < 0) print_report(a, cells, links, colliding, link_count, &mesh);
    free(colliding);
    opx_linkset_destroy(links);
    mesh_free(&mesh);
    return code < 0 ? CLI_EXIT_OK : code;
}

int cmd_export(int argc, char **argv) {
    export_args a;
    opx_octree *map = NULL;
    opx_status status;
    int code = parse_arguments(argc, argv, &a);
    if (code >= 0) return code;
    status = opx_octree_load_file(a.map, NULL, &map);
    if (status != OPX_OK) return cli_library_fail("export", status, "loading the map %s", a.map);
    code = export_map(&a, map);
    opx_octree_destroy(map);
    return code;
}
