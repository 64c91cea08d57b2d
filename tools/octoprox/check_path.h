/*
 * octoprox check --path: a joint-space path from CSV (path_csv.h), checked
 * with the batch calls of the library (batch.h): every waypoint at once
 * (opx_query_check_configurations) and the straight joint-space motion
 * between each two (opx_query_check_motions, at --resolution), on
 * --threads threads; with --distance or --cost, also opx_query_path over
 * the waypoints' link poses (the minimum distance, the swept cost).
 */
#ifndef OPX_TOOLS_CHECK_PATH_H
#define OPX_TOOLS_CHECK_PATH_H

#include "check_report.h"

/* -1 when done (*collided: some waypoint or motion collides), else the
 * exit code of a failure (reported). */
int check_path(check_context *c, opx_linkset *links, int *collided);

#endif /* OPX_TOOLS_CHECK_PATH_H */
