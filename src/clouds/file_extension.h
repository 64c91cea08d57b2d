/* Whether a path ends in an extension, case-insensitively (".pcd"). */
#ifndef OPX_FILE_EXTENSION_H
#define OPX_FILE_EXTENSION_H

#include <ctype.h>
#include <string.h>

/* `extension` in lower case, dot included. */
static inline int file_has_extension(const char *path, const char *extension) {
    const size_t n = strlen(path), m = strlen(extension);
    size_t i;
    if (n < m) return 0;
    for (i = 0; i < m; ++i)
        if (tolower((unsigned char)path[n - m + i]) != extension[i]) return 0;
    return 1;
}

#endif
