/*
 * Paths of joint waypoints from CSV: the first line names the joints,
 * each further line gives their values for one waypoint (radians or
 * metres).  Blank lines and lines starting with '#' are skipped.
 */
#ifndef OPX_TOOLS_PATH_CSV_H
#define OPX_TOOLS_PATH_CSV_H

#include <stddef.h>

typedef struct path_csv {
    char **names;        /* joint_count names */
    size_t joint_count;
    double *values;      /* waypoint_count rows of joint_count values */
    size_t waypoint_count;
} path_csv;

/* 0 on success; -1 with a message (file, line) in error. */
int path_csv_read(const char *path, path_csv *out, char *error, size_t error_size);
void path_csv_free(path_csv *csv);

#endif /* OPX_TOOLS_PATH_CSV_H */
