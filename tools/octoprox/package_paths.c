/* package:// lookup folders from the options and the environment: see
 * package_paths.h. */
#define _POSIX_C_SOURCE 200809L

#include "package_paths.h"

#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define PACKAGE_XML_MAX 65536

static int add(package_paths *p, const char *entry) {
    if (p->count == p->capacity) {
        const size_t bigger = p->capacity ? 2 * p->capacity : 16;
        char **grown = realloc(p->entries, bigger * sizeof *grown);
        if (grown == NULL) return -1;
        p->entries = grown, p->capacity = bigger;
    }
    if ((p->entries[p->count] = strdup(entry)) == NULL) return -1;
    ++p->count;
    return 0;
}

/* The <name> of DIR/package.xml into name (size bytes); 0, or -1 when
 * there is none or it is not a plain package name. */
static int package_name(const char *dir, char *name, size_t size) {
    static char text[PACKAGE_XML_MAX];
    char path[4096];
    const char *start, *end;
    size_t n;
    FILE *file;
    snprintf(path, sizeof path, "%s/package.xml", dir);
    if ((file = fopen(path, "rb")) == NULL) return -1;
    n = fread(text, 1, sizeof text - 1, file);
    fclose(file);
    text[n] = '\0';
    if ((start = strstr(text, "<name>")) == NULL || (end = strstr(start, "</name>")) == NULL) return -1;
    for (start += strlen("<name>"); start < end && isspace((unsigned char)*start); ++start) {}
    while (end > start && isspace((unsigned char)end[-1])) --end;
    if (end == start || (size_t)(end - start) >= size) return -1;
    for (n = 0; start + n < end; ++n)
        if (!isalnum((unsigned char)start[n]) && start[n] != '_' && start[n] != '-') return -1;
    memcpy(name, start, (size_t)(end - start));
    name[end - start] = '\0';
    return 0;
}

/* "NAME=DIR" for a folder holding a package.xml. */
static int add_named(package_paths *p, const char *dir) {
    char name[256], entry[4400];
    if (package_name(dir, name, sizeof name) != 0) return 0;
    snprintf(entry, sizeof entry, "%s=%s", name, dir);
    return add(p, entry);
}

/* The package.xml files of the folder's subfolders. */
static int add_named_children(package_paths *p, const char *dir) {
    DIR *folder = opendir(dir);
    struct dirent *child;
    int status = 0;
    if (folder == NULL) return 0;
    while (status == 0 && (child = readdir(folder)) != NULL) {
        char path[4096];
        struct stat info;
        if (child->d_name[0] == '.') continue;
        /* A path too long for the buffer is no package folder of ours. */
        if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, child->d_name) >= sizeof path) continue;
        if (stat(path, &info) == 0 && S_ISDIR(info.st_mode)) status = add_named(p, path);
    }
    closedir(folder);
    return status;
}

/* Each non-empty item of a colon-separated list, with `suffix` appended. */
static int add_list(package_paths *p, const char *list, const char *suffix, int read_packages) {
    char item[4096];
    while (list != NULL && *list != '\0') {
        const char *colon = strchr(list, ':');
        const size_t n = colon != NULL ? (size_t)(colon - list) : strlen(list);
        if (n > 0 && n + strlen(suffix) < sizeof item) {
            snprintf(item, sizeof item, "%.*s%s", (int)n, list, suffix);
            if (add(p, item) != 0) return -1;
            if (read_packages && (add_named(p, item) != 0 || add_named_children(p, item) != 0)) return -1;
        }
        list = colon != NULL ? colon + 1 : NULL;
    }
    return 0;
}

static int add_explicit(package_paths *p, const char *const *entries, size_t count) {
    size_t i;
    for (i = 0; i < count; ++i)
        if (add(p, entries[i]) != 0) return -1;
    return 0;
}

int package_paths_build(const char *const *explicit_entries, size_t explicit_count, package_paths *out) {
    memset(out, 0, sizeof *out);
    if (add_explicit(out, explicit_entries, explicit_count) != 0 ||
        add_list(out, getenv("ROS_PACKAGE_PATH"), "", 1) != 0 ||
        add_list(out, getenv("AMENT_PREFIX_PATH"), "/share", 0) != 0) {
        package_paths_free(out);
        return -1;
    }
    return 0;
}

void package_paths_free(package_paths *paths) {
    size_t i;
    if (paths == NULL) return;
    for (i = 0; i < paths->count; ++i) free(paths->entries[i]);
    free(paths->entries);
    memset(paths, 0, sizeof *paths);
}
