/* Shared scaffolding of the cloud readers: see cloud_io.h. */
#define _POSIX_C_SOURCE 200809L

#include "cloud_io.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

/* Points allocated at first when the file's size cannot bound them. */
#define CLOUD_FIRST_SLICE ((size_t)1 << 16)

void cloud_set_error(char *error, size_t error_size, const char *format, ...) {
    va_list args;
    if (error == NULL || error_size == 0) return;
    va_start(args, format);
    vsnprintf(error, error_size, format, args);
    va_end(args);
}

int cloud_parse_count(const char *word, uint64_t max, uint64_t *out) {
    char *end = NULL;
    unsigned long long value;
    /* strtoull would take a sign ("-1" wraps) and leading blanks. */
    if (word[0] < '0' || word[0] > '9') return -1;
    errno = 0;
    value = strtoull(word, &end, 10);
    if (errno == ERANGE || *end != '\0' || value > max) return -1;
    *out = (uint64_t)value;
    return 0;
}

int cloud_bytes_left(FILE *file, uint64_t *out) {
    struct stat info;
    off_t position;
    if (fstat(fileno(file), &info) != 0 || !S_ISREG(info.st_mode)) return -1;
    position = ftello(file);
    if (position < 0) return -1;
    *out = info.st_size > position ? (uint64_t)(info.st_size - position) : 0;
    return 0;
}

int cloud_read_line(FILE *file, char *line, size_t size) {
    size_t n = 0;
    int c;
    while ((c = getc(file)) != EOF) {
        if (n + 1 >= size) return -2;
        line[n++] = (char)c;
        if (c == '\n') break;
    }
    line[n] = '\0';
    return n == 0 ? -1 : 0;
}

static int is_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

int cloud_read_word(FILE *file, char *word, size_t size) {
    size_t n = 0;
    int c = getc(file);
    while (c != EOF && is_blank(c)) c = getc(file);
    if (c == EOF) return -1;
    while (c != EOF && !is_blank(c)) {
        if (n + 1 >= size) return -2;
        word[n++] = (char)c;
        c = getc(file);
    }
    word[n] = '\0';
    return 0;
}

int cloud_reserve_points(float **xyz, size_t *capacity, size_t needed, size_t total) {
    size_t bigger;
    float *grown;
    if (needed <= *capacity) return 0;
    if (total > CLOUD_MAX_POINTS) total = CLOUD_MAX_POINTS;
    bigger = *capacity < total / 2 ? 2 * *capacity : total;
    if (bigger < needed) bigger = needed;
    if (bigger > CLOUD_MAX_POINTS) return -1;
    grown = realloc(*xyz, bigger * 3 * sizeof(float));
    if (grown == NULL) return -1;
    *xyz = grown;
    *capacity = bigger;
    return 0;
}

size_t cloud_first_capacity(size_t total, int size_known) {
    const size_t first = size_known || total < CLOUD_FIRST_SLICE ? total : CLOUD_FIRST_SLICE;
    return first > 0 ? first : 1;
}

size_t cloud_count_finite(const float *xyz, size_t count) {
    size_t i, n = 0;
    for (i = 0; i < count; ++i) {
        const float *p = &xyz[3 * i];
        if (isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2])) ++n;
    }
    return n;
}

int cloud_read_path(const char *path, cloud_format_reader read, void *out, char *error, size_t error_size) {
    char reason[512] = "";
    int status;
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        cloud_set_error(error, error_size, "%s: cannot open for reading: %s", path, strerror(errno));
        return CLOUD_ERROR_IO;
    }
    status = read(file, out, reason, sizeof reason);
    fclose(file);
    if (status != 0) cloud_set_error(error, error_size, "%s: %s", path, reason);
    return status;
}
