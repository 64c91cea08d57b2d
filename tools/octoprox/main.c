/*
 * octoprox: the command-line face of the library.  Subcommands info,
 * ingest, check and export; see `octoprox --help` and docs/cli.md.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli.h"
#include "commands.h"
#include "held_report.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

static const char kUsage[] =
    "usage: octoprox COMMAND [ARGS...]\n"
    "\n"
    "Collision and distance queries between robots and occupancy octrees.\n"
    "\n"
    "commands:\n"
    "  info MAP.bt|.ot                     resolution, cells by class, bounds, memory\n"
    "  ingest CLOUD.pcd|.ply ... -o MAP.bt build or update a map from point clouds\n"
    "  check MAP --urdf ROBOT.urdf ...     collision, distance and cost of a robot\n"
    "                                      configuration or a CSV path of them\n"
    "  export MAP --obj OUT | --ply OUT    cells (and a robot) as a mesh for viewers\n"
    "\n"
    "Run 'octoprox COMMAND --help' for a command's options.  Every command\n"
    "prints a human-readable report; --json prints one JSON object instead\n"
    "(field names are stable; see docs/cli.md), and on failure one error\n"
    "object {\"error\": {command, exit_code, status, library_status,\n"
    "message}} in its place.  A progress bar is drawn on stderr during long\n"
    "work when stderr is a terminal.\n"
    "\n"
    "Units: metres and radians.  Poses: x,y,z or x,y,z,qx,qy,qz,qw (ROS order),\n"
    "in the map frame.\n"
    "\n"
    "exit codes:\n"
    "  0  success (check: no collision)\n"
    "  1  check: a collision was found\n"
    "  2  usage error (unknown command or option, bad value: an empty list\n"
    "     item, a number that is not decimal, a --resolution of too many steps)\n"
    "  3  input/output error (a file is missing, unreadable, malformed or beyond\n"
    "     the readers' bounds, or a file or the standard output cannot be written)\n"
    "  4  internal error (out of memory, a library bug)\n"
    "\n"
    "options:\n"
    "  -h, --help     this help\n"
    "  --version      the library's version\n";

static int run(int argc, char **argv) {
    const char *command;
    if (argc < 2) {
        fputs(kUsage, stderr);
        return CLI_EXIT_USAGE;
    }
    command = argv[1];
    if (cli_is_help(command)) {
        fputs(kUsage, stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(command, "--version") == 0) {
        printf("octoprox %s\n", opx_version());
        return CLI_EXIT_OK;
    }
    if (strcmp(command, "info") == 0) return cmd_info(argc - 1, argv + 1);
    if (strcmp(command, "ingest") == 0) return cmd_ingest(argc - 1, argv + 1);
    if (strcmp(command, "check") == 0) return cmd_check(argc - 1, argv + 1);
    if (strcmp(command, "export") == 0) return cmd_export(argc - 1, argv + 1);
    return cli_usage(NULL, "unknown command '%s'", command);
}

/* The command argv names, or NULL (none, an option, an unknown name). */
static const char *command_of(int argc, char **argv) {
    static const char *const commands[] = {"info", "ingest", "check", "export"};
    size_t i;
    for (i = 0; argc > 1 && i < sizeof commands / sizeof commands[0]; ++i)
        if (strcmp(argv[1], commands[i]) == 0) return commands[i];
    return NULL;
}

/* A report that never reached its file (a full disk, /dev/full, a file
 * size limit) is an input/output error, not a success: stdout is flushed
 * and closed here, where its last write errors show. */
static int close_stdout(int code) {
    int failed = 0, error = 0;
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        failed = 1;
        error = errno;
    }
    if (fclose(stdout) != 0 && !failed) {
        failed = 1;
        error = errno;
    }
    if (!failed) return code;
    fprintf(stderr, "octoprox: cannot write the standard output: %s\n", error != 0 ? strerror(error) : "write error");
    return code == CLI_EXIT_OK || code == CLI_EXIT_COLLISION ? CLI_EXIT_INPUT : code;
}

int main(int argc, char **argv) {
    /* Past a file size limit (ulimit -f) a write then fails with EFBIG,
     * which is reported (exit 3), instead of the signal killing the
     * process halfway through a file. */
    const int json = held_report_wanted(argc, argv);
    int code;
    signal(SIGXFSZ, SIG_IGN);
    if (json) held_report_begin();
    code = run(argc, argv);
    if (json) code = held_report_end(command_of(argc, argv), code);
    return close_stdout(code);
}
