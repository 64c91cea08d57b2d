/* The robot options shared by `check` and `export`: --urdf, --package-dir,
 * --srdf, --joints, --base-pose, --padding, --disable-link. */
#ifndef OPX_TOOLS_ROBOT_ARGS_H
#define OPX_TOOLS_ROBOT_ARGS_H

#include "cli.h"

#define ROBOT_MAX_PACKAGE_DIRS 64
#define ROBOT_MAX_DISABLED_LINKS 256

typedef struct robot_args {
    const char *urdf;
    const char *package_dirs[ROBOT_MAX_PACKAGE_DIRS];
    int package_dir_count;
    const char *srdf;    /* SRDF file or NULL */
    const char *joints;  /* "name=value,..." or NULL */
    opx_pose base_pose;  /* the URDF root link in the map frame */
    double padding;      /* metres added around every link */
    const char *disabled_links[ROBOT_MAX_DISABLED_LINKS];
    int disabled_link_count;
} robot_args;

/* The help text of these options. */
extern const char kRobotOptionsHelp[];

void robot_args_init(robot_args *r);
/* Consumes argv[args->index] when it is a robot option: returns 1 (and
 * *code = -1, or an exit code after a usage error), else 0. */
int robot_args_option(cli_args *args, robot_args *r, const char *command, int *code);

/* Loads the URDF (and the SRDF) with package:// resolved as
 * package_paths.h says, applies --joints, --base-pose, --padding and
 * --disable-link; -1 on success, else an exit code (the message
 * printed). */
int robot_load(const robot_args *r, const char *command, opx_linkset **out);

/* Splits "name=value,..." into at most `capacity` names (pointers into
 * the copy `buffer`) and values; returns the count, or -1 when malformed
 * (a message in error). */
int robot_parse_joints(const char *text, char *buffer, size_t buffer_size, const char **names,
                       double *values, int capacity, char *error, size_t error_size);

#endif /* OPX_TOOLS_ROBOT_ARGS_H */
