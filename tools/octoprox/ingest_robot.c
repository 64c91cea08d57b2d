/* Self-filtering in `octoprox ingest`: see ingest_robot.h. */
#include "ingest_robot.h"

#include <string.h>

const char kIngestRobotHelp[] =
    "  --robot-padding M     metres added to every link's padding (--padding's\n"
    "                        included) for the filter only (default 0)\n"
    "  --clear-robot-volume  cells lying entirely inside the robot's unpadded\n"
    "                        shapes become free in the same update (an obstacle\n"
    "                        where the arm now stands, its own earlier image)\n"
    "\n"
    "With --urdf the robot, at --joints and --base-pose, is filtered out of\n"
    "every input (self-filtering): a point within a link's padding of it (on\n"
    "the robot) or whose ray passes through the padded robot (shadowed) gives\n"
    "no occupied cell, and its ray frees the cells up to the robot.  Links\n"
    "disabled with --disable-link filter nothing.  The robot options need\n"
    "--urdf.\n";

void ingest_robot_init(ingest_robot *r) {
    memset(r, 0, sizeof *r);
    robot_args_init(&r->args);
}

/* --robot-padding and --clear-robot-volume: 1 when taken (*code set). */
static int filter_option(cli_args *args, ingest_robot *r, int *code) {
    int got;
    *code = -1;
    if (cli_flag(args, "--clear-robot-volume")) {
        r->clear_volume = 1;
    } else if ((got = cli_value(args, "--robot-padding")) != 0) {
        if (got < 0 || cli_parse_double(args->value, &r->padding) != 0 || !(r->padding >= 0.0))
            *code = cli_usage("ingest", "--robot-padding needs a distance in metres (a finite number >= 0)");
    } else {
        return 0;
    }
    return 1;
}

int ingest_robot_option(cli_args *args, ingest_robot *r, int *code) {
    const char *arg = args->argv[args->index];
    if (!robot_args_option(args, &r->args, "ingest", code) && !filter_option(args, r, code)) return 0;
    if (r->needs_urdf == NULL && strncmp(arg, "--urdf", 6) != 0) r->needs_urdf = arg;
    return 1;
}

int ingest_robot_check(const ingest_robot *r) {
    if (r->args.urdf != NULL || r->needs_urdf == NULL) return -1;
    /* The option's name, without a "=VALUE" part. */
    return cli_usage("ingest", "%.*s needs --urdf (the robot to filter out)", (int)strcspn(r->needs_urdf, "="),
                     r->needs_urdf);
}

int ingest_robot_load(ingest_robot *r, opx_insert_options *insert) {
    int code;
    if (r->args.urdf == NULL) return -1;
    code = robot_load(&r->args, "ingest", &r->links);
    if (code >= 0) return code;
    insert->robot = r->links;
    insert->robot_padding = r->padding;
    insert->clear_robot_volume = (uint32_t)r->clear_volume;
    return -1;
}

void ingest_robot_free(ingest_robot *r) {
    opx_linkset_destroy(r->links);
    r->links = NULL;
}
