/* Robot options of `check` and `export`: see robot_args.h. */
#define _POSIX_C_SOURCE 200809L

#include "robot_args.h"

#include <stdlib.h>
#include <string.h>

#define MAX_JOINTS 512

const char kRobotOptionsHelp[] =
    "robot options:\n"
    "  --urdf ROBOT.urdf     the robot: every link's collision shapes\n"
    "  --package-dir DIR     resolves package://NAME/... mesh URIs as DIR/NAME/...\n"
    "                        (or DIR/... when DIR ends in NAME); NAME=DIR maps\n"
    "                        one package explicitly; repeatable\n"
    "  --joints N=V,...      joint positions by name (radians, or metres for\n"
    "                        prismatic joints); unnamed joints stay at 0\n"
    "  --base-pose POSE      the URDF root link in the map frame: x,y,z or\n"
    "                        x,y,z,qx,qy,qz,qw (default: the map origin)\n";

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
    } else if ((got = cli_value(args, "--joints")) != 0) {
        if (got < 0) *code = cli_usage(command, "--joints needs name=value,...");
        else r->joints = args->value;
    } else if ((got = cli_value(args, "--base-pose")) != 0) {
        if (got < 0 || cli_parse_pose(args->value, &r->base_pose) != 0)
            *code = cli_usage(command, "--base-pose needs x,y,z or x,y,z,qx,qy,qz,qw (finite numbers)");
    } else {
        return 0;
    }
    return 1;
}

int robot_parse_joints(const char *text, char *buffer, size_t buffer_size, const char **names,
                       double *values, int capacity, char *error, size_t error_size) {
    char *item, *save = NULL;
    int count = 0;
    if (strlen(text) >= buffer_size) {
        snprintf(error, error_size, "--joints is too long");
        return -1;
    }
    strcpy(buffer, text);
    for (item = strtok_r(buffer, ",", &save); item != NULL; item = strtok_r(NULL, ",", &save)) {
        char *equals = strchr(item, '=');
        int i;
        if (count == capacity) {
            snprintf(error, error_size, "--joints names more than %d joints", capacity);
            return -1;
        }
        if (equals == NULL || equals == item || cli_parse_double(equals + 1, &values[count]) != 0) {
            snprintf(error, error_size, "--joints item '%s' is not name=value (a finite number)", item);
            return -1;
        }
        *equals = '\0';
        /* One joint cannot take two values. */
        for (i = 0; i < count; ++i)
            if (strcmp(names[i], item) == 0) {
                snprintf(error, error_size, "--joints names joint %s twice", item);
                return -1;
            }
        names[count++] = item;
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

int robot_load(const robot_args *r, const char *command, opx_linkset **out) {
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    opx_status status;
    int code;
    *out = NULL;
    if (r->urdf == NULL) return cli_usage(command, "no robot given (--urdf ROBOT.urdf)");
    options.package_dirs = r->package_dirs;
    options.package_dir_count = (size_t)r->package_dir_count;
    status = opx_linkset_load_urdf_file(r->urdf, &options, out);
    if (status != OPX_OK) return cli_library_fail(command, status, "loading the robot %s", r->urdf);
    code = apply_joints(r, command, *out);
    if (code >= 0) {
        opx_linkset_destroy(*out);
        *out = NULL;
    }
    return code;
}
