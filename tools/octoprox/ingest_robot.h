/*
 * Self-filtering in `octoprox ingest`: the robot options (robot_args.h's,
 * and --robot-padding, --clear-robot-volume), the robot loaded at its
 * --joints and --base-pose, and the insert options that filter it out of
 * every input (opx_insert_options.robot; see "The robot in its own frame"
 * in octoprox/octree.h).
 */
#ifndef OPX_TOOLS_INGEST_ROBOT_H
#define OPX_TOOLS_INGEST_ROBOT_H

#include "robot_args.h"

typedef struct ingest_robot {
    robot_args args;
    double padding;         /* --robot-padding, metres */
    int clear_volume;       /* --clear-robot-volume */
    const char *needs_urdf; /* the first option given that needs --urdf, or NULL */
    opx_linkset *links;     /* the robot, once loaded; NULL without --urdf */
} ingest_robot;

/* The help text of the self-filtering options (after kRobotOptionsHelp). */
extern const char kIngestRobotHelp[];

void ingest_robot_init(ingest_robot *r);

/* Consumes argv[args->index] when it is a robot option: returns 1 (and
 * *code = -1, or an exit code after a usage error), else 0. */
int ingest_robot_option(cli_args *args, ingest_robot *r, int *code);

/* After the arguments: a usage exit code when a robot option was given
 * without --urdf, else -1. */
int ingest_robot_check(const ingest_robot *r);

/* With --urdf, loads the robot and makes `insert` filter it out: -1 on
 * success (nothing to do without --urdf), else the exit code after a
 * message. */
int ingest_robot_load(ingest_robot *r, opx_insert_options *insert);

/* Frees the loaded robot (NULL-safe). */
void ingest_robot_free(ingest_robot *r);

#endif /* OPX_TOOLS_INGEST_ROBOT_H */
