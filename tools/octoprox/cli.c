/* Shared pieces of the octoprox tool: see cli.h. */
#define _POSIX_C_SOURCE 200809L

#include "cli.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* What the first failure said, for --json's error object. */
static char g_first_failure[2048];
static int g_failed = 0;
static const char *g_library_status = NULL;

/* Prints "octoprox COMMAND: message" ("octoprox: message" without a
 * command) and keeps the first such message. */
static void vprint_message(const char *command, const char *format, va_list args) {
    va_list copy;
    va_copy(copy, args);
    if (!g_failed) {
        vsnprintf(g_first_failure, sizeof g_first_failure, format, copy);
        g_failed = 1;
    }
    va_end(copy);
    fprintf(stderr, command != NULL ? "octoprox %s: " : "octoprox: ", command);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
}

const char *cli_first_failure(void) { return g_first_failure; }

const char *cli_failed_library_status(void) { return g_library_status; }

int cli_fail(const char *command, int code, const char *format, ...) {
    va_list args;
    va_start(args, format);
    vprint_message(command, format, args);
    va_end(args);
    return code;
}

int cli_usage(const char *command, const char *format, ...) {
    va_list args;
    va_start(args, format);
    vprint_message(command, format, args);
    va_end(args);
    if (command != NULL) fprintf(stderr, "try 'octoprox %s --help'\n", command);
    else fputs("try 'octoprox --help'\n", stderr);
    return CLI_EXIT_USAGE;
}

int cli_library_fail(const char *command, opx_status status, const char *what_format, ...) {
    char what[1024];
    va_list args;
    if (!g_failed) g_library_status = opx_status_name(status);
    va_start(args, what_format);
    vsnprintf(what, sizeof what, what_format, args);
    va_end(args);
    const int code = status == OPX_ERROR_IO || status == OPX_ERROR_CORRUPT || status == OPX_ERROR_UNSUPPORTED ||
                             status == OPX_ERROR_INVALID_ARGUMENT
                         ? CLI_EXIT_INPUT
                         : CLI_EXIT_INTERNAL;
    return cli_fail(command, code, "%s: %s (%s)", what, opx_last_error(), opx_status_name(status));
}

int cli_flag(const cli_args *args, const char *name) { return strcmp(args->argv[args->index], name) == 0; }

int cli_value(cli_args *args, const char *name) {
    const char *arg = args->argv[args->index];
    const size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0) return 0;
    if (arg[n] == '=') {
        args->value = arg + n + 1;
        return 1;
    }
    if (arg[n] != '\0') return 0;
    if (args->index + 1 >= args->argc) return -1;
    args->value = args->argv[++args->index];
    return 1;
}

int cli_is_help(const char *arg) { return strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0; }

int cli_is_decimal(const char *text) {
    const char *p = text;
    size_t digits;
    if (*p == '+' || *p == '-') ++p;
    digits = strspn(p, "0123456789");
    p += digits;
    if (*p == '.') {
        const size_t fraction = strspn(p + 1, "0123456789");
        digits += fraction;
        p += 1 + fraction;
    }
    if (digits == 0) return 0;
    if (*p == 'e' || *p == 'E') {
        size_t exponent;
        ++p;
        if (*p == '+' || *p == '-') ++p;
        if ((exponent = strspn(p, "0123456789")) == 0) return 0;
        p += exponent;
    }
    return *p == '\0';
}

int cli_parse_double(const char *text, double *out) {
    if (text == NULL || !cli_is_decimal(text)) return -1;
    *out = strtod(text, NULL);
    return isfinite(*out) ? 0 : -1;
}

int cli_parse_numbers(const char *text, double *values, int capacity) {
    char item[128];
    int count = 0;
    for (;;) {
        const char *comma = strchr(text, ',');
        const size_t length = comma != NULL ? (size_t)(comma - text) : strlen(text);
        if (count == capacity || length >= sizeof item) return -1;
        memcpy(item, text, length);
        item[length] = '\0';
        if (cli_parse_double(item, &values[count]) != 0) return -1;
        ++count;
        if (comma == NULL) return count;
        text = comma + 1;
    }
}

int cli_parse_pose(const char *text, opx_pose *out) {
    double v[7];
    const int n = cli_parse_numbers(text, v, 7);
    const opx_pose identity = OPX_POSE_IDENTITY;
    if (n != 3 && n != 7) return -1;
    *out = identity;
    memcpy(out->position, v, sizeof out->position);
    if (n == 7) {
        const double norm = sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
        if (!(norm > 1e-9)) return -1;
        memcpy(out->orientation, v + 3, sizeof out->orientation);
    }
    return 0;
}

void json_string(FILE *out, const char *text) {
    fputc('"', out);
    for (; *text != '\0'; ++text) {
        const unsigned char c = (unsigned char)*text;
        if (c == '"' || c == '\\') fprintf(out, "\\%c", c);
        else if (c < 0x20) fprintf(out, "\\u%04x", c);
        else fputc(c, out);
    }
    fputc('"', out);
}

void json_number(FILE *out, double value) {
    char text[32];
    if (!isfinite(value)) {
        fputs("null", out);
        return;
    }
    /* The shortest of %.15g .. %.17g that reads back exactly. */
    snprintf(text, sizeof text, "%.15g", value);
    if (strtod(text, NULL) != value) snprintf(text, sizeof text, "%.16g", value);
    if (strtod(text, NULL) != value) snprintf(text, sizeof text, "%.17g", value);
    fputs(text, out);
}

void json_vec3(FILE *out, const double v[3]) {
    fputc('[', out);
    json_number(out, v[0]);
    fputs(", ", out);
    json_number(out, v[1]);
    fputs(", ", out);
    json_number(out, v[2]);
    fputc(']', out);
}

void cli_progress_start(cli_progress *p, const char *label, size_t total) {
    p->enabled = isatty(STDERR_FILENO) && total > 0;
    p->label = label;
    p->total = total;
    p->last_percent = -1;
    cli_progress_update(p, 0);
}

void cli_progress_update(cli_progress *p, size_t done) {
    enum { kWidth = 30 };
    char bar[kWidth + 1];
    int percent, filled, i;
    if (!p->enabled) return;
    percent = (int)(100.0 * (double)done / (double)p->total);
    if (percent == p->last_percent) return;
    p->last_percent = percent;
    filled = percent * kWidth / 100;
    for (i = 0; i < kWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kWidth] = '\0';
    fprintf(stderr, "\r%-24.24s [%s] %3d%% (%zu/%zu)", p->label, bar, percent, done, p->total);
    fflush(stderr);
}

void cli_progress_finish(cli_progress *p) {
    if (!p->enabled) return;
    cli_progress_update(p, p->total);
    fputs("\r\033[K", stderr); /* clear the line: the result follows on stdout */
    fflush(stderr);
}

double cli_now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

int cli_walk_map_arguments(int argc, char **argv, const char *command, const char *help,
                           const char *help_part, const char **out_map, cli_option_parser parse_option,
                           void *context) {
    cli_args args = {argc, argv, 1, NULL};
    *out_map = NULL;
    for (; args.index < argc; ++args.index) {
        const char *arg = argv[args.index];
        int code;
        if (cli_is_help(arg)) {
            printf(help, help_part);
            return CLI_EXIT_OK;
        }
        if (arg[0] != '-') {
            if (*out_map != NULL) return cli_usage(command, "one map only ('%s' and '%s' given)", *out_map, arg);
            *out_map = arg;
        } else if ((code = parse_option(&args, context)) >= 0) {
            return code;
        }
    }
    return -1;
}
