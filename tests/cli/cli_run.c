/* Helpers of the octoprox tool's tests: see cli_run.h. */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"

#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include <cmocka.h>

const char *scratch_dir(void) {
    static char dir[256] = "";
    if (dir[0] == '\0') {
        snprintf(dir, sizeof dir, "/tmp/opx-cli-test-XXXXXX");
        if (mkdtemp(dir) == NULL) fail_msg("cannot make a scratch folder");
    }
    return dir;
}

const char *scratch_path(const char *name) {
    static char paths[4][512];
    static int slot = 0;
    char *path = paths[slot++ % 4];
    snprintf(path, 512, "%s/%s", scratch_dir(), name);
    return path;
}

int scratch_files_starting(const char *prefix) {
    DIR *dir = opendir(scratch_dir());
    struct dirent *entry;
    int count = 0;
    if (dir == NULL) fail_msg("cannot list %s", scratch_dir());
    while ((entry = readdir(dir)) != NULL) count += strncmp(entry->d_name, prefix, strlen(prefix)) == 0;
    closedir(dir);
    return count;
}

const char *write_bytes(const char *name, const void *bytes, size_t size) {
    const char *path = scratch_path(name);
    FILE *file = fopen(path, "wb");
    if (file == NULL || fwrite(bytes, 1, size, file) != size || fclose(file) != 0) fail_msg("cannot write %s", path);
    return path;
}

const char *write_text(const char *name, const char *text) { return write_bytes(name, text, strlen(text)); }

static void read_all(const char *path, char *buffer, size_t size) {
    FILE *file = fopen(path, "rb");
    size_t n = 0;
    if (file != NULL) {
        n = fread(buffer, 1, size - 1, file);
        fclose(file);
    }
    buffer[n] = '\0';
}

/* Runs `shell_prefix 'tool' arguments >stdout_target 2>scratch/stderr.txt`
 * through the shell; stdout_target NULL is scratch/stdout.txt. */
static void run_command(cli_result *r, const char *shell_prefix, const char *stdout_target, const char *arguments) {
    char command[8192 + 1600], out_path[512], err_path[512];
    int status;
    snprintf(out_path, sizeof out_path, "%s/stdout.txt", scratch_dir());
    snprintf(err_path, sizeof err_path, "%s/stderr.txt", scratch_dir());
    remove(out_path);
    snprintf(command, sizeof command, "%s'%s' %s >'%s' 2>'%s'", shell_prefix, OPX_CLI_PATH, arguments,
             stdout_target != NULL ? stdout_target : out_path, err_path);
    status = system(command);
    r->code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    read_all(out_path, r->out, sizeof r->out);
    read_all(err_path, r->err, sizeof r->err);
}

void run_cli(cli_result *r, const char *arguments_format, ...) {
    char arguments[8192];
    va_list args;
    va_start(args, arguments_format);
    vsnprintf(arguments, sizeof arguments, arguments_format, args);
    va_end(args);
    run_command(r, "", NULL, arguments);
}

void run_cli_to(cli_result *r, const char *stdout_path, const char *arguments_format, ...) {
    char arguments[8192];
    va_list args;
    va_start(args, arguments_format);
    vsnprintf(arguments, sizeof arguments, arguments_format, args);
    va_end(args);
    run_command(r, "", stdout_path, arguments);
}

void run_cli_file_limit(cli_result *r, unsigned blocks, const char *arguments_format, ...) {
    char arguments[8192], prefix[64];
    va_list args;
    va_start(args, arguments_format);
    vsnprintf(arguments, sizeof arguments, arguments_format, args);
    va_end(args);
    snprintf(prefix, sizeof prefix, "ulimit -f %u && exec ", blocks);
    run_command(r, prefix, NULL, arguments);
}

double json_field(const char *json, const char *key) {
    char pattern[128];
    const char *at;
    char *end = NULL;
    double value;
    snprintf(pattern, sizeof pattern, "\"%s\": ", key);
    at = strstr(json, pattern);
    if (at == NULL) fail_msg("no field \"%s\" in %s", key, json);
    value = strtod(at + strlen(pattern), &end);
    if (end == at + strlen(pattern)) fail_msg("field \"%s\" is not a number in %s", key, json);
    return value;
}

double json_field_in(const char *json, const char *object, const char *key) {
    char pattern[128];
    const char *at;
    snprintf(pattern, sizeof pattern, "\"%s\": {", object);
    at = strstr(json, pattern);
    if (at == NULL) fail_msg("no object \"%s\" in %s", object, json);
    return json_field(at + strlen(pattern), key);
}

int json_bool(const char *json, const char *key) {
    char yes[128], no[128];
    snprintf(yes, sizeof yes, "\"%s\": true", key);
    snprintf(no, sizeof no, "\"%s\": false", key);
    if (strstr(json, yes) != NULL) return 1;
    if (strstr(json, no) != NULL) return 0;
    fail_msg("no boolean field \"%s\" in %s", key, json);
    return -1;
}

size_t count_lines_with_prefix(const char *path, const char *prefix) {
    static char line[4096];
    FILE *file = fopen(path, "r");
    size_t n = 0;
    if (file == NULL) fail_msg("cannot read %s", path);
    while (fgets(line, sizeof line, file) != NULL)
        if (strncmp(line, prefix, strlen(prefix)) == 0) ++n;
    fclose(file);
    return n;
}
