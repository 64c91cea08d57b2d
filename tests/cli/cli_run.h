/*
 * Helpers of the octoprox tool's tests: a scratch folder, files written
 * there, the tool run with its output captured, and JSON fields read back.
 */
#ifndef OPX_TESTS_CLI_RUN_H
#define OPX_TESTS_CLI_RUN_H

#include <stddef.h>

typedef struct cli_result {
    int code;          /* the exit code; -1 when the tool did not exit normally */
    char out[1 << 16]; /* stdout */
    char err[1 << 14]; /* stderr */
} cli_result;

/* A fresh scratch folder (made once per test program). */
const char *scratch_dir(void);
/* scratch_dir()/name, in a static buffer per call slot (4 slots: copy a
 * path that must outlive four more calls). */
const char *scratch_path(const char *name);
/* Writes text to scratch_dir()/name; returns the full path. */
const char *write_text(const char *name, const char *text);
const char *write_bytes(const char *name, const void *bytes, size_t size);

/* Entries of scratch_dir() whose name starts with prefix (temporaries
 * such as ".NAME." left behind). */
int scratch_files_starting(const char *prefix);

/* Runs the tool with `arguments` (a shell command tail, format string). */
void run_cli(cli_result *r, const char *arguments_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* As run_cli, with the tool's stdout sent to stdout_path (e.g. /dev/full);
 * r->out is then empty. */
void run_cli_to(cli_result *r, const char *stdout_path, const char *arguments_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* As run_cli, with the tool's files limited to `blocks` blocks of 512
 * bytes (the shell's ulimit -f, which limits its stdout and stderr too). */
void run_cli_file_limit(cli_result *r, unsigned blocks, const char *arguments_format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The number after "\"key\": " in json (the first one); fails the test
 * when missing. */
double json_field(const char *json, const char *key);
/* The number after "\"key\": " inside the object "\"object\": {...". */
double json_field_in(const char *json, const char *object, const char *key);
/* 1 when "\"key\": true" is in json, 0 for false; fails otherwise. */
int json_bool(const char *json, const char *key);

/* Lines of a file starting with prefix (e.g. "v " in an OBJ). */
size_t count_lines_with_prefix(const char *path, const char *prefix);

#endif /* OPX_TESTS_CLI_RUN_H */
