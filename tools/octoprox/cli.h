/*
 * Shared pieces of the octoprox command-line tool: exit codes, messages,
 * argument parsing, JSON output and a progress bar.
 */
#ifndef OPX_TOOLS_CLI_H
#define OPX_TOOLS_CLI_H

#include <octoprox/octoprox.h>

#include <stddef.h>
#include <stdio.h>

/* Exit codes (documented in `octoprox --help` and docs/cli.md). */
#define CLI_EXIT_OK 0        /* done; for check: no collision */
#define CLI_EXIT_COLLISION 1 /* check: the robot (or a path waypoint) collides */
#define CLI_EXIT_USAGE 2     /* bad command line */
#define CLI_EXIT_INPUT 3     /* a file cannot be read or written, or is malformed */
#define CLI_EXIT_INTERNAL 4  /* out of memory or a library bug */

/* Prints "octoprox COMMAND: message" on stderr; returns code. */
int cli_fail(const char *command, int code, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The exit code of a failed library call; prints what was being done
 * (a format) and the library's message. */
int cli_library_fail(const char *command, opx_status status, const char *what_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* The first message any of the calls above printed (without "octoprox
 * COMMAND: "), "" when none; the status name of the failed library call
 * when the first failure was one, else NULL.  For --json's error object. */
const char *cli_first_failure(void);
const char *cli_failed_library_status(void);
/* A usage error: the message, then "try 'octoprox COMMAND --help'"
 * (command NULL: an error of the command line before any command). */
int cli_usage(const char *command, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Command-line walking: `--name VALUE`, `--name=VALUE` and flags. */
typedef struct cli_args {
    int argc;
    char **argv;
    int index;          /* the argument being looked at */
    const char *value;  /* set by cli_value */
} cli_args;

/* 1 when argv[index] is exactly `name` (a flag). */
int cli_flag(const cli_args *args, const char *name);
/* 1 when argv[index] is `name VALUE` or `name=VALUE`: args->value gets
 * VALUE and index moves past it.  -1 when the value is missing. */
int cli_value(cli_args *args, const char *name);
/* 1 for --help and -h. */
int cli_is_help(const char *arg);

/* Takes the option at args->index: -1 when taken, else an exit code. */
typedef int (*cli_option_parser)(cli_args *args, void *context);
/* Walks the arguments of a command that works on one map: --help prints
 * `help` (a printf format with one %s, `help_part`) and gives CLI_EXIT_OK;
 * the one positional argument is the map (*out_map; a second one is a
 * usage error); every option goes to parse_option.  -1 when every
 * argument was taken, else the exit code. */
int cli_walk_map_arguments(int argc, char **argv, const char *command, const char *help,
                           const char *help_part, const char **out_map, cli_option_parser parse_option,
                           void *context);

/* 1 when text is a decimal number: an optional sign, digits with an
 * optional fraction, an optional exponent; nothing else (no blanks, no
 * hexadecimal, no inf or nan). */
int cli_is_decimal(const char *text);
/* Numbers and poses; 0 on success, -1 when malformed or not finite. */
int cli_parse_double(const char *text, double *out);
/* Comma-separated decimal numbers: their count, or -1 when an item is
 * empty or no finite decimal number, or there are more than capacity. */
int cli_parse_numbers(const char *text, double *values, int capacity);
/* "x,y,z" or "x,y,z,qx,qy,qz,qw" (metres, quaternion in ROS order). */
int cli_parse_pose(const char *text, opx_pose *out);

/* JSON: a quoted, escaped string, and an [x, y, z] array. */
void json_string(FILE *out, const char *text);
void json_vec3(FILE *out, const double v[3]);
/* A number; non-finite values print as null (JSON has no infinity). */
void json_number(FILE *out, double value);

/* A progress bar on stderr, drawn only when stderr is a terminal. */
typedef struct cli_progress {
    int enabled;
    const char *label;
    size_t total;
    int last_percent;
} cli_progress;

void cli_progress_start(cli_progress *p, const char *label, size_t total);
void cli_progress_update(cli_progress *p, size_t done);
void cli_progress_finish(cli_progress *p);

/* Milliseconds on a monotonic clock. */
double cli_now_ms(void);

#endif /* OPX_TOOLS_CLI_H */
