/* The seed generator: see seeds.h.  Maps and message payloads here. */
#define _POSIX_C_SOURCE 200809L /* mkdir */
#include "seeds.h"

#include <octoprox/octoprox.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void make_folder(const char *path) {
    if (mkdir(path, 0755) != 0 && errno != EEXIST) {
        fprintf(stderr, "make_seeds: cannot make %s: %s\n", path, strerror(errno));
        exit(1);
    }
}

void write_seed(const char *out_dir, const char *target, const char *name, const void *data, size_t size) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", out_dir, target);
    make_folder(path);
    snprintf(path, sizeof path, "%s/%s/%s", out_dir, target, name);
    FILE *file = fopen(path, "wb");
    if (file == NULL || fwrite(data, 1, size, file) != size || fclose(file) != 0) {
        fprintf(stderr, "make_seeds: cannot write %s\n", path);
        exit(1);
    }
}

void write_text_seed(const char *out_dir, const char *target, const char *name, const char *text) {
    write_seed(out_dir, target, name, text, strlen(text));
}

static void require_ok(opx_status status, const char *what) {
    if (status == OPX_OK) return;
    fprintf(stderr, "make_seeds: %s: %s\n", what, opx_last_error());
    exit(1);
}

/* A small map: a wall of points seen from a sensor, free space between. */
static opx_octree *make_map(double resolution, double free_threshold, int points) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    options.free_threshold = free_threshold;
    opx_octree *tree = NULL;
    require_ok(opx_octree_create(&options, &tree), "opx_octree_create");
    double xyz[3 * 64];
    for (int i = 0; i < points && i < 64; ++i) {
        xyz[3 * i] = 0.5 + 0.01 * (i % 3);
        xyz[3 * i + 1] = -0.2 + 0.05 * (i % 8);
        xyz[3 * i + 2] = -0.1 + 0.05 * (i / 8);
    }
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    for (int frame = 0; frame < 2; ++frame)
        require_ok(opx_octree_insert_points(tree, xyz, (size_t)points, 0, OPX_SCALAR_FLOAT64, &insert, NULL),
                   "opx_octree_insert_points");
    return tree;
}

/* The map's file image in `format`; *size gets its length. */
static unsigned char *save_image(const opx_octree *tree, int32_t format, size_t *size) {
    opx_octree_save_memory(tree, format, NULL, 0, size);
    unsigned char *image = malloc(*size + 1);
    if (image == NULL) exit(1);
    require_ok(opx_octree_save_memory(tree, format, image, *size, size), "opx_octree_save_memory");
    image[*size] = '\0';
    return image;
}

/* A message seed: flags, the resolution's 8 bytes, the image's body. */
static void write_message_seed(const char *out_dir, const char *name, const unsigned char *image, size_t size,
                               int binary, double resolution) {
    const char *body = strstr((const char *)image, "\ndata\n");
    if (body == NULL) exit(1);
    body += 6;
    const size_t body_size = size - (size_t)(body - (const char *)image);
    unsigned char *seed = malloc(9 + body_size);
    if (seed == NULL) exit(1);
    seed[0] = (unsigned char)(binary ? 1 : 0);
    memcpy(seed + 1, &resolution, 8); /* little-endian hosts only, as the target */
    memcpy(seed + 9, body, body_size);
    write_seed(out_dir, "fuzz_octree_message", name, seed, 9 + body_size);
    free(seed);
}

static void write_map_seeds(const char *out_dir) {
    static const struct {
        const char *name;
        double resolution, free_threshold;
        int points;
    } maps[] = {
        {"empty", 0.05, 0.5, 0},
        {"wall", 0.05, 0.5, 24},
        {"coarse_uncertain", 0.2, 0.3, 40},
        {"fine", 0.01, 0.5, 8},
    };
    for (size_t m = 0; m < sizeof maps / sizeof maps[0]; ++m) {
        opx_octree *tree = make_map(maps[m].resolution, maps[m].free_threshold, maps[m].points);
        for (int full = 0; full < 2; ++full) {
            size_t size = 0;
            unsigned char *image = save_image(tree, full ? OPX_FORMAT_OT : OPX_FORMAT_BT, &size);
            char name[64];
            snprintf(name, sizeof name, "%s.%s", maps[m].name, full ? "ot" : "bt");
            write_seed(out_dir, "fuzz_octree_file", name, image, size);
            write_message_seed(out_dir, name, image, size, !full, maps[m].resolution);
            free(image);
        }
        opx_octree_destroy(tree);
    }
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: make_seeds OUT_DIR\n");
        return 2;
    }
    make_folder(argv[1]);
    write_map_seeds(argv[1]);
    write_pcd_seeds(argv[1]);
    write_ply_seeds(argv[1]);
    write_depth_seeds(argv[1]);
    write_urdf_seeds(argv[1]);
    write_api_seeds(argv[1]);
    return 0;
}
