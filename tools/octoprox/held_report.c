/* Whole JSON reports or one error object: see held_report.h. */
#define _POSIX_C_SOURCE 200809L

#include "held_report.h"

#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static FILE *g_held = NULL; /* the report so far */
static int g_stdout_fd = -1; /* the real stdout while it is held */

int held_report_wanted(int argc, char **argv) {
    int i;
    for (i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--json") == 0) return 1;
    return 0;
}

void held_report_begin(void) {
    fflush(stdout);
    g_held = tmpfile();
    if (g_held == NULL) return;
    g_stdout_fd = dup(STDOUT_FILENO);
    if (g_stdout_fd < 0 || dup2(fileno(g_held), STDOUT_FILENO) < 0) {
        if (g_stdout_fd >= 0) close(g_stdout_fd);
        fclose(g_held);
        g_held = NULL, g_stdout_fd = -1;
    }
}

/* Copies the held report to stdout, read whole first so that a failed
 * read prints nothing; 0, or -1 when it could not be read. */
static int copy_held(void) {
    long size;
    char *text;
    if (fseek(g_held, 0, SEEK_END) != 0 || (size = ftell(g_held)) < 0) return -1;
    rewind(g_held);
    text = malloc((size_t)size + 1);
    if (text == NULL || fread(text, 1, (size_t)size, g_held) != (size_t)size) {
        free(text);
        return -1;
    }
    fwrite(text, 1, (size_t)size, stdout);
    free(text);
    return 0;
}

static const char *status_of(int code) {
    switch (code) {
    case CLI_EXIT_USAGE: return "usage_error";
    case CLI_EXIT_INPUT: return "input_error";
    default: return "internal_error";
    }
}

static void print_error(const char *command, int code) {
    const char *library_status = cli_failed_library_status();
    fputs("{\"error\": {\"command\": ", stdout);
    if (command != NULL) json_string(stdout, command);
    else fputs("null", stdout);
    printf(", \"exit_code\": %d, \"status\": \"%s\", \"library_status\": ", code, status_of(code));
    if (library_status != NULL) json_string(stdout, library_status);
    else fputs("null", stdout);
    fputs(", \"message\": ", stdout);
    json_string(stdout, cli_first_failure());
    fputs("}}\n", stdout);
}

int held_report_end(const char *command, int code) {
    /* A report that did not reach its file whole (a file size limit) is
     * no report: an I/O error, told as one. */
    const int held_broken = fflush(stdout) != 0 || ferror(stdout);
    const char *name = command != NULL ? command : "--json";
    if (g_held == NULL) return code;
    dup2(g_stdout_fd, STDOUT_FILENO);
    close(g_stdout_fd);
    clearerr(stdout);
    if (held_broken && (code == CLI_EXIT_OK || code == CLI_EXIT_COLLISION))
        code = cli_fail(name, CLI_EXIT_INPUT, "the JSON report could not be written whole to a temporary file");
    if ((code == CLI_EXIT_OK || code == CLI_EXIT_COLLISION) && copy_held() != 0)
        code = cli_fail(name, CLI_EXIT_INPUT, "the JSON report could not be read back from its temporary file");
    if (code != CLI_EXIT_OK && code != CLI_EXIT_COLLISION) print_error(command, code);
    fclose(g_held);
    g_held = NULL, g_stdout_fd = -1;
    return code;
}
