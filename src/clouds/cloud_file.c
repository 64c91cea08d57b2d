/* Point clouds from .pcd and .ply files: see cloud_file.h. */
#include "cloud_file.h"
#include "file_extension.h"

#include "pcd_reader.h"
#include "ply_reader.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cloud_file_supported(const char *path) {
    return path != NULL && (file_has_extension(path, ".pcd") || file_has_extension(path, ".ply"));
}

int cloud_read_file(const char *path, cloud_points *out, char *error, size_t error_size) {
    memset(out, 0, sizeof *out);
    if (file_has_extension(path, ".pcd")) {
        pcd_cloud pcd;
        if (pcd_read_file(path, &pcd, error, error_size) != 0) return -1;
        out->xyz = pcd.xyz;
        out->count = pcd.count;
        out->finite_count = pcd.finite_count;
        snprintf(out->format, sizeof out->format, "pcd %s", pcd.data_format);
        return 0;
    }
    if (file_has_extension(path, ".ply")) {
        ply_cloud ply;
        if (ply_read_file(path, &ply, error, error_size) != 0) return -1;
        out->xyz = ply.xyz;
        out->count = ply.count;
        out->finite_count = ply.finite_count;
        snprintf(out->format, sizeof out->format, "ply %s", ply.format);
        return 0;
    }
    if (error != NULL && error_size > 0)
        snprintf(error, error_size, "%s: unknown cloud format (use .pcd or .ply)", path);
    return -1;
}

void cloud_free(cloud_points *cloud) {
    if (cloud == NULL) return;
    free(cloud->xyz);
    memset(cloud, 0, sizeof *cloud);
}
