/* Robot options of `check` and `export`: see robot_args.h. */
#define _POSIX_C_SOURCE 200809L

#include "robot_args.h"

#include "package_paths.h"

#include <stdlib.h>
#include <string.h>

#define MAX_JOINTS 512

const char kRobotOptionsHelp[] =
    "robot options:\n"
    "  --urdf ROBOT.urdf     the robot: every link's collision shapes\n"
    "  --package-dir DIR     resolves package://NAME/... mesh URIs as DIR/NAME/...\n"
    "                        (or DIR/... when DIR ends in NAME); NAME=DIR maps\n"
    "                        one package explicitly; repeatable; tried before\n"
    "                        $ROS_PACKAGE_PATH and $AMENT_PREFIX_PATH (PREFIX/share)\n"
    "  --srdf ROBOT.srdf     the robot's SRDF (its disable_collisions pairs are\n"
    "                        reported)\n"
    "  --joints N=V,...      joint positions by name (radians, or metres for\n"
    "                        prismatic joints); unnamed joints stay at 0\n"
    "  --base-pose POSE      the URDF root link in the map frame: x,y,z or\n"
    "                        x,y,z,qx,qy,qz,qw (default: the map origin)\n"
    "  --padding M           metres added around every link's shapes (default 0)\n"
    "  --disable-link NAME   the link takes part in no query (e.g. one the\n"
    "                        sensor sees, or a gripper's finger); repeatable\n";

void robot_args_init(robot_args *r) {
    const opx_pose identity = OPX_POSE_IDENTITY;
    memset(r, 0, sizeof *r);
    r->base_pose = identity;
}

int robot_args_option(cli_args *args, robot_args *r, const char *command, int *code) {
    int got;
    *code = -1;
    if ((got = cli_value(args, "--urdf")) != 0) {
        if (got < 0) *code = cli_usage(command, "--urdf needs a file name");
        else r->urdf = args->value;
    } else if ((got = cli_value(args, "--package-dir")) != 0) {
        if (got < 0) *code = cli_usage(command, "--package-dir needs a directory");
        else if (r->package_dir_count == ROBOT_MAX_PACKAGE_DIRS)
            *code = cli_usage(command, "more than %d --package-dir options", ROBOT_MAX_PACKAGE_DIRS);
        else r->package_dirs[r->package_dir_count++] = args->value;
    } else if ((got = cli_value(args, "--srdf")) != 0) {
        if (got < 0) *code = cli_usage(command, "--srdf needs a file name");
        else r->srdf = args->value;
    } else if ((got = cli_value(args, "--padding")) != 0) {
        if (got < 0 || cli_parse_double(args->value, &r->padding) != 0 || !(r->padding >= 0.0))
            *code = cli_usage(command, "--padding needs a distance in metres (a finite decimal number >= 0)");
    } else if ((got = cli_value(args, "--disable-link")) != 0) {
        if (got < 0) *code = cli_usage(command, "--disable-link needs a link name");
        else if (r->disabled_link_count == ROBOT_MAX_DISABLED_LINKS)
            *code = cli_usage(command, "more than %d --disable-link options", ROBOT_MAX_DISABLED_LINKS);
        else r->disabled_links[r->disabled_link_count++] = args->value;
    } else if ((got = cli_value(args, "--joints")) != 0) {
        if (got < 0) *code = cli_usage(command, "--joints needs name=value,...");
        else r->joints = args->value;
    } else if ((got = cli_value(args, "--base-pose")) != 0) {
        if (got < 0 || cli_parse_pose(args->value, &r->base_pose) != 0)
            *code = cli_usage(command, "--base-pose needs x,y,z or x,y,z,qx,qy,qz,qw (finite decimal numbers)");
    } else {
        return 0;
    }
    return 1;
}

/* One "name=value" item (cut in place at '='); 0, or -1 with a message
 * naming the item (1-based `number`). */
static int parse_joint_item(char *item, int number, const char **name, double *value, char *error,
                            size_t error_size) {
    char *equals = strchr(item, '=');
    if (*item == '\0') {
        snprintf(error, error_size, "--joints item %d is empty (name=value,... with no empty items)", number);
        return -1;
    }
    if (equals == NULL || equals == item || cli_parse_double(equals + 1, value) != 0) {
        snprintf(error, error_size, "--joints item %d '%s' is not name=value (a finite decimal number)", number,
                 item);
        return -1;
    }
    *equals = '\0';
    *name = item;
    return 0;
}

int robot_parse_joints(const char *text, char *buffer, size_t buffer_size, const char **names,
                       double *values, int capacity, char *error, size_t error_size) {
    char *item, *comma;
    int count = 0, i;
    if (strlen(text) >= buffer_size) {
        snprintf(error, error_size, "--joints is too long");
        return -1;
    }
    strcpy(buffer, text);
    for (item = buffer; item != NULL; item = comma != NULL ? comma + 1 : NULL) {
        if ((comma = strchr(item, ',')) != NULL) *comma = '\0';
        if (count == capacity) {
            snprintf(error, error_size, "--joints names more than %d joints", capacity);
            return -1;
        }
        if (parse_joint_item(item, count + 1, &names[count], &values[count], error, error_size) != 0) return -1;
        /* One joint cannot take two values. */
        for (i = 0; i < count; ++i)
            if (strcmp(names[i], names[count]) == 0) {
                snprintf(error, error_size, "--joints names joint %s twice", names[count]);
                return -1;
            }
        ++count;
    }
    return count;
}

static int apply_joints(const robot_args *r, const char *command, opx_linkset *links) {
    static char buffer[65536];
    static const char *names[MAX_JOINTS];
    static double values[MAX_JOINTS];
    char error[256];
    int count = 0;
    opx_status status;
    if (r->joints != NULL) {
        count = robot_parse_joints(r->joints, buffer, sizeof buffer, names, values, MAX_JOINTS, error, sizeof error);
        if (count < 0) return cli_usage(command, "%s", error);
    }
    status = opx_linkset_set_named_joint_positions(links, names, values, (size_t)count, &r->base_pose);
    if (status == OPX_ERROR_INVALID_ARGUMENT)
        return cli_usage(command, "--joints: %s", opx_last_error()); /* e.g. an unknown joint name */
    return status == OPX_OK ? -1 : cli_library_fail(command, status, "setting the joints");
}

/* --padding and --disable-link: -1, or an exit code. */
static int apply_link_options(const robot_args *r, const char *command, opx_linkset *links) {
    opx_status status = opx_linkset_set_padding(links, r->padding);
    int i;
    if (status != OPX_OK) return cli_library_fail(command, status, "--padding %g", r->padding);
    for (i = 0; i < r->disabled_link_count; ++i) {
        uint32_t link;
        if (opx_linkset_find_link(links, r->disabled_links[i], &link) != OPX_OK)
            return cli_usage(command, "--disable-link: the robot has no link named '%s'", r->disabled_links[i]);
        if ((status = opx_linkset_set_link_enabled(links, link, 0)) != OPX_OK)
            return cli_library_fail(command, status, "disabling link %s", r->disabled_links[i]);
    }
    return -1;
}

static int load_urdf(const robot_args *r, const char *command, opx_linkset **out) {
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    package_paths packages;
    opx_status status;
    if (package_paths_build(r->package_dirs, (size_t)r->package_dir_count, &packages) != 0)
        return cli_fail(command, CLI_EXIT_INTERNAL, "out of memory for the package folders");
    options.package_dirs = (const char *const *)packages.entries;
    options.package_dir_count = packages.count;
    options.srdf_path = r->srdf;
    status = opx_linkset_load_urdf_file(r->urdf, &options, out);
    package_paths_free(&packages);
    return status == OPX_OK ? -1 : cli_library_fail(command, status, "loading the robot %s", r->urdf);
}

int robot_load(const robot_args *r, const char *command, opx_linkset **out) {
    int code;
    *out = NULL;
    if (r->urdf == NULL) return cli_usage(command, "no robot given (--urdf ROBOT.urdf)");
    code = load_urdf(r, command, out);
    if (code < 0) code = apply_joints(r, command, *out);
    if (code < 0) code = apply_link_options(r, command, *out);
    if (code >= 0) {
        opx_linkset_destroy(*out);
        *out = NULL;
    }
    return code;
}
