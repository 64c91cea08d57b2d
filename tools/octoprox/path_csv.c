/* CSV paths of joint waypoints: see path_csv.h. */
#define _POSIX_C_SOURCE 200809L

#include "path_csv.h"

#include "cli.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CSV_LINE_MAX 65536
#define CSV_MAX_COLUMNS 512

static char *trim(char *s) {
    char *end;
    while (*s == ' ' || *s == '\t') ++s;
    end = s + strlen(s);
    while (end > s && (end[-1] == ' ' || end[-1] == '\t' || end[-1] == '\r' || end[-1] == '\n')) *--end = '\0';
    return s;
}

/* Splits a line at commas in place; returns the number of cells. */
static size_t split_cells(char *line, char **cells, size_t capacity) {
    size_t n = 0;
    char *start = line;
    for (;;) {
        char *comma = strchr(start, ',');
        if (n == capacity) return capacity + 1;
        if (comma != NULL) *comma = '\0';
        cells[n++] = trim(start);
        if (comma == NULL) return n;
        start = comma + 1;
    }
}

static int read_header(char *line, path_csv *out, char *error, size_t error_size) {
    char *cells[CSV_MAX_COLUMNS];
    size_t n = split_cells(line, cells, CSV_MAX_COLUMNS), i, j;
    if (n > CSV_MAX_COLUMNS) {
        snprintf(error, error_size, "more than %d columns", CSV_MAX_COLUMNS);
        return -1;
    }
    out->names = calloc(n, sizeof *out->names);
    if (out->names == NULL) return -1;
    for (i = 0; i < n; ++i) {
        if (cells[i][0] == '\0') {
            snprintf(error, error_size, "header column %zu has no joint name", i + 1);
            return -1;
        }
        /* One joint cannot take two values in one waypoint. */
        for (j = 0; j < i; ++j)
            if (strcmp(out->names[j], cells[i]) == 0) {
                snprintf(error, error_size, "joint %s is named twice in the header (columns %zu and %zu)", cells[i],
                         j + 1, i + 1);
                return -1;
            }
        if ((out->names[i] = strdup(cells[i])) == NULL) return -1;
        out->joint_count = i + 1;
    }
    return 0;
}

static int read_row(char *line, path_csv *out, size_t *capacity, char *error, size_t error_size) {
    char *cells[CSV_MAX_COLUMNS];
    const size_t n = split_cells(line, cells, CSV_MAX_COLUMNS);
    size_t i;
    if (n != out->joint_count) {
        snprintf(error, error_size, "%zu values, but the header names %zu joints", n, out->joint_count);
        return -1;
    }
    if (out->waypoint_count == *capacity) {
        const size_t bigger = *capacity ? 2 * *capacity : 64;
        double *values;
        if (bigger > SIZE_MAX / sizeof(double) / out->joint_count) return -1;
        values = realloc(out->values, bigger * out->joint_count * sizeof(double));
        if (values == NULL) return -1;
        out->values = values;
        *capacity = bigger;
    }
    for (i = 0; i < n; ++i) {
        double *value = &out->values[out->waypoint_count * out->joint_count + i];
        if (cli_parse_double(cells[i], value) != 0) {
            snprintf(error, error_size, "value '%s' of joint %s is not a finite decimal number", cells[i],
                     out->names[i]);
            return -1;
        }
    }
    ++out->waypoint_count;
    return 0;
}

static int read_lines(FILE *file, path_csv *out, char *reason, size_t reason_size, size_t *line_number) {
    static char line[CSV_LINE_MAX];
    size_t capacity = 0;
    while (fgets(line, sizeof line, file) != NULL) {
        char *text;
        ++*line_number;
        if (strchr(line, '\n') == NULL && !feof(file)) {
            snprintf(reason, reason_size, "the line is longer than %d bytes", CSV_LINE_MAX - 2);
            return -1;
        }
        text = trim(line);
        if (text[0] == '\0' || text[0] == '#') continue;
        if (out->names == NULL ? read_header(text, out, reason, reason_size) != 0
                               : read_row(text, out, &capacity, reason, reason_size) != 0)
            return -1;
    }
    if (out->names == NULL) snprintf(reason, reason_size, "no header line of joint names");
    else if (out->waypoint_count == 0) snprintf(reason, reason_size, "no waypoint after the header");
    else return 0;
    return -1;
}

int path_csv_read(const char *path, path_csv *out, char *error, size_t error_size) {
    char reason[300] = "out of memory";
    size_t line_number = 0;
    FILE *file;
    memset(out, 0, sizeof *out);
    file = fopen(path, "r");
    if (file == NULL) {
        snprintf(error, error_size, "%s: cannot open for reading", path);
        return -1;
    }
    if (read_lines(file, out, reason, sizeof reason, &line_number) != 0) {
        snprintf(error, error_size, "%s:%zu: %s", path, line_number, reason);
        fclose(file);
        path_csv_free(out);
        return -1;
    }
    fclose(file);
    return 0;
}

void path_csv_free(path_csv *csv) {
    size_t i;
    if (csv->names != NULL)
        for (i = 0; i < csv->joint_count; ++i) free(csv->names[i]);
    free(csv->names);
    free(csv->values);
    memset(csv, 0, sizeof *csv);
}
