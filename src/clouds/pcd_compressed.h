/*
 * DATA binary_compressed of a PCD file (internal to opx_clouds), as PCL
 * writes it: two little-endian uint32, the size of the compressed block
 * and the size it decompresses to, then the block, LZF-compressed
 * (liblzf).  Decompressed, the fields lie one after another in FIELDS
 * order, each for every point (all x, then all y, ...), so the size must
 * be POINTS times the bytes of one point.  Bytes after the block are
 * ignored (PCL may leave some).
 */
#ifndef OPX_CLOUDS_PCD_COMPRESSED_H
#define OPX_CLOUDS_PCD_COMPRESSED_H

#include "pcd_header.h"

#include <stddef.h>
#include <stdio.h>

/* Reads the `count` points after the DATA line into *xyz (allocated here,
 * packed x y z).  0, or a CLOUD_ERROR_* with the reason; sizes that
 * disagree with the header, with each other (more than LZF can expand) or
 * with the bytes the file has left are errors before the block is read. */
int pcd_read_compressed(FILE *file, const pcd_layout *layout, size_t count, float **xyz, char *error,
                        size_t error_size);

#endif /* OPX_CLOUDS_PCD_COMPRESSED_H */
