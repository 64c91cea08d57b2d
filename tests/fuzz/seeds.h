/*
 * The seed generator of the fuzz targets (make_seeds OUT_DIR): it writes
 * OUT_DIR/<target>/<seed> for every target, from maps the library saves,
 * small PCD and PLY files, depth images, URDFs and call sequences.
 */
#ifndef OPX_FUZZ_SEEDS_H
#define OPX_FUZZ_SEEDS_H

#include <stddef.h>

/* Writes one seed file; exits with a message when it cannot. */
void write_seed(const char *out_dir, const char *target, const char *name, const void *data, size_t size);
void write_text_seed(const char *out_dir, const char *target, const char *name, const char *text);

/* seed_clouds.c */
void write_pcd_seeds(const char *out_dir);
void write_ply_seeds(const char *out_dir);
/* seed_depth.c */
void write_depth_seeds(const char *out_dir);
/* seed_robots.c */
void write_urdf_seeds(const char *out_dir);
void write_api_seeds(const char *out_dir);

#endif /* OPX_FUZZ_SEEDS_H */
