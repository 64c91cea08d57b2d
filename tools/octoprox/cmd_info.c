/* octoprox info MAP: what a map file holds. */
#include "cli.h"
#include "commands.h"

#include <string.h>

static const char kHelp[] =
    "usage: octoprox info MAP.bt|MAP.ot|MAP.opx [--json]\n"
    "\n"
    "Prints the map's resolution, its leaves by class (occupied, uncertain,\n"
    "free; unknown space has no cells), the bounds of the occupied and of all\n"
    "observed cells (map frame, metres) and the tree's memory.\n"
    "\n"
    "options:\n"
    "  --json      one JSON object: file, resolution, leaves {occupied, uncertain,\n"
    "              free}, inner_nodes, memory_bytes, occupied_bounds {min, max}\n"
    "              and known_bounds {min, max} (null when there are none)\n"
    "  -h, --help  this help\n"
    "\n"
    "exit codes: 0 ok, 2 usage error, 3 the map cannot be read, 4 internal error\n";

static void print_bounds_json(const char *name, int present, const double lo[3], const double hi[3]) {
    printf("  \"%s\": ", name);
    if (!present) {
        fputs("null", stdout);
        return;
    }
    fputs("{\"min\": ", stdout);
    json_vec3(stdout, lo);
    fputs(", \"max\": ", stdout);
    json_vec3(stdout, hi);
    fputc('}', stdout);
}

static void print_json(const char *path, const opx_octree_stats *s) {
    const int known = s->leaves_occupied + s->leaves_uncertain + s->leaves_free > 0;
    fputs("{\n  \"file\": ", stdout);
    json_string(stdout, path);
    fputs(",\n  \"resolution\": ", stdout);
    json_number(stdout, s->resolution);
    printf(",\n  \"leaves\": {\"occupied\": %llu, \"uncertain\": %llu, \"free\": %llu},\n",
           (unsigned long long)s->leaves_occupied, (unsigned long long)s->leaves_uncertain,
           (unsigned long long)s->leaves_free);
    printf("  \"occupied_with_point_extent\": %llu,\n", (unsigned long long)s->leaves_with_extent);
    printf("  \"inner_nodes\": %llu,\n  \"memory_bytes\": %llu,\n", (unsigned long long)s->inner_nodes,
           (unsigned long long)s->memory_bytes);
    print_bounds_json("occupied_bounds", s->has_occupied, s->occupied_min, s->occupied_max);
    fputs(",\n", stdout);
    print_bounds_json("known_bounds", known, s->known_min, s->known_max);
    fputs("\n}\n", stdout);
}

static void print_bounds(const char *label, const double lo[3], const double hi[3]) {
    printf("%-17s x %.3f .. %.3f, y %.3f .. %.3f, z %.3f .. %.3f m\n", label, lo[0], hi[0], lo[1], hi[1],
           lo[2], hi[2]);
}

static void print_human(const char *path, const opx_octree_stats *s) {
    const unsigned long long leaves = s->leaves_occupied + s->leaves_uncertain + s->leaves_free;
    printf("map               %s\n", path);
    printf("resolution        %g m\n", s->resolution);
    printf("leaves occupied   %llu\n", (unsigned long long)s->leaves_occupied);
    printf("leaves uncertain  %llu\n", (unsigned long long)s->leaves_uncertain);
    printf("leaves free       %llu\n", (unsigned long long)s->leaves_free);
    printf("point extents     %llu of the occupied leaves (the others are whole cells)\n",
           (unsigned long long)s->leaves_with_extent);
    printf("inner nodes       %llu\n", (unsigned long long)s->inner_nodes);
    if (s->has_occupied) print_bounds("occupied bounds", s->occupied_min, s->occupied_max);
    if (leaves > 0) print_bounds("observed bounds", s->known_min, s->known_max);
    printf("memory            %llu bytes (%.1f MiB)\n", (unsigned long long)s->memory_bytes,
           (double)s->memory_bytes / (1024.0 * 1024.0));
}

int cmd_info(int argc, char **argv) {
    cli_args args = {argc, argv, 1, NULL};
    const char *path = NULL;
    int json = 0, code;
    opx_octree *map = NULL;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    opx_status status;
    for (; args.index < argc; ++args.index) {
        const char *arg = argv[args.index];
        if (cli_is_help(arg)) {
            fputs(kHelp, stdout);
            return CLI_EXIT_OK;
        }
        if (cli_flag(&args, "--json")) json = 1;
        else if (arg[0] == '-') return cli_usage("info", "unknown option '%s'", arg);
        else if (path != NULL) return cli_usage("info", "one map only ('%s' and '%s' given)", path, arg);
        else path = arg;
    }
    if (path == NULL) return cli_usage("info", "no map file given");
    status = opx_octree_load_file(path, NULL, &map);
    if (status != OPX_OK) return cli_library_fail("info", status, "loading the map %s", path);
    status = opx_octree_get_stats(map, &stats);
    code = status == OPX_OK ? CLI_EXIT_OK : cli_library_fail("info", status, "reading the map");
    if (code == CLI_EXIT_OK) {
        if (json) print_json(path, &stats);
        else print_human(path, &stats);
    }
    opx_octree_destroy(map);
    return code;
}
