/* Point clouds from .pcd and .ply files: see cloud_file.h. */
#include "cloud_file.h"
#include "file_extension.h"

#include "pcd_reader.h"
#include "ply_reader.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cloud_file_supported(const char *path) {
    return path != NULL && (file_has_extension(path, ".pcd") || file_has_extension(path, ".ply"));
}

static void take_pcd(pcd_cloud *pcd, cloud_points *out) {
    out->xyz = pcd->xyz;
    out->count = pcd->count;
    out->finite_count = pcd->finite_count;
    out->kind = CLOUD_FILE_PCD;
    out->width = pcd->width;
    out->height = pcd->height;
    memcpy(out->viewpoint, pcd->viewpoint, sizeof out->viewpoint);
    out->has_viewpoint = pcd->has_viewpoint;
    snprintf(out->encoding, sizeof out->encoding, "%s", pcd->data_format);
    snprintf(out->format, sizeof out->format, "pcd %s", pcd->data_format);
}

static void take_ply(ply_cloud *ply, cloud_points *out) {
    static const double identity[7] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};
    out->xyz = ply->xyz;
    out->count = ply->count;
    out->finite_count = ply->finite_count;
    out->kind = CLOUD_FILE_PLY;
    out->width = ply->count;
    out->height = 1;
    memcpy(out->viewpoint, identity, sizeof out->viewpoint);
    snprintf(out->encoding, sizeof out->encoding, "%s", ply->format);
    snprintf(out->format, sizeof out->format, "ply %s", ply->format);
}

int cloud_read_file(const char *path, cloud_points *out, char *error, size_t error_size) {
    int status;
    if (path == NULL || out == NULL) {
        if (error != NULL && error_size > 0) snprintf(error, error_size, "cloud_read_file: path and out must not be NULL");
        return CLOUD_ERROR_INVALID;
    }
    memset(out, 0, sizeof *out);
    if (file_has_extension(path, ".pcd")) {
        pcd_cloud pcd;
        if ((status = pcd_read_file(path, &pcd, error, error_size)) != 0) return status;
        take_pcd(&pcd, out);
        return 0;
    }
    if (file_has_extension(path, ".ply")) {
        ply_cloud ply;
        if ((status = ply_read_file(path, &ply, error, error_size)) != 0) return status;
        take_ply(&ply, out);
        return 0;
    }
    if (error != NULL && error_size > 0)
        snprintf(error, error_size, "%s: unknown cloud format (use .pcd or .ply)", path);
    return CLOUD_ERROR_UNSUPPORTED;
}

void cloud_free(cloud_points *cloud) {
    if (cloud == NULL) return;
    free(cloud->xyz);
    memset(cloud, 0, sizeof *cloud);
}
