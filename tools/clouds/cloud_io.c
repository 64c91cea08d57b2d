/* Shared scaffolding of the cloud readers: see cloud_io.h. */
#include "cloud_io.h"

#include <math.h>
#include <stdarg.h>

void cloud_set_error(char *error, size_t error_size, const char *format, ...) {
    va_list args;
    if (error == NULL || error_size == 0) return;
    va_start(args, format);
    vsnprintf(error, error_size, format, args);
    va_end(args);
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
        cloud_set_error(error, error_size, "%s: cannot open for reading", path);
        return -1;
    }
    status = read(file, out, reason, sizeof reason);
    fclose(file);
    if (status != 0) {
        cloud_set_error(error, error_size, "%s: %s", path, reason);
        return -1;
    }
    return 0;
}
