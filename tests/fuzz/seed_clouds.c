/* PCD and PLY seeds: a few points in each storage the readers support
 * (PCD binary_compressed written with liblzf). */
#include "seeds.h"

#include <lzf.h>

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define SEED_POINTS 4

static const float cloud[SEED_POINTS][3] = {{0.1f, 0.2f, 0.3f}, {-1.0f, 0.5f, 2.0f}, {3.25f, -0.75f, 0.0f},
                                            {1e-3f, 1e3f, -7.5f}};

/* Header text followed by binary records, into one buffer. */
typedef struct seed_buffer {
    unsigned char bytes[2048];
    size_t size;
} seed_buffer;

static void append(seed_buffer *buffer, const void *data, size_t size) {
    if (buffer->size + size > sizeof buffer->bytes) return;
    memcpy(buffer->bytes + buffer->size, data, size);
    buffer->size += size;
}

static void append_text(seed_buffer *buffer, const char *text) { append(buffer, text, strlen(text)); }

/* Binary records of x y z (as float or double) and one extra float. */
static void append_records(seed_buffer *buffer, int doubles, int extra) {
    for (int i = 0; i < SEED_POINTS; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            if (doubles) {
                const double value = cloud[i][axis];
                append(buffer, &value, sizeof value);
            } else {
                append(buffer, &cloud[i][axis], sizeof cloud[i][axis]);
            }
        }
        if (extra) {
            const float intensity = (float)i;
            append(buffer, &intensity, sizeof intensity);
        }
    }
}

static const char PCD_ASCII[] =
    "# .PCD v0.7 - Point Cloud Data file format\n"
    "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
    "WIDTH 4\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n"
    "0.1 0.2 0.3\n-1 0.5 2\n3.25 -0.75 0\nnan nan nan\n";

static const char PCD_ORGANIZED[] =
    "VERSION 0.7\nFIELDS rgb x y z\nSIZE 4 4 4 4\nTYPE U F F F\nCOUNT 1 1 1 1\n"
    "WIDTH 2\nHEIGHT 2\nVIEWPOINT 1 2 3 1 0 0 0\nPOINTS 4\nDATA ascii\n"
    "4278190335 1 2 3\n0 4 5 6\n0 7 8 9\n0 nan 1 1\n";

/* DATA binary_compressed as PCL writes it: the LZF block's size, the size
 * it decompresses to (uint32 each, little-endian as on the machines the
 * fuzzers run on), then the block of the fields one after another. */
static void append_compressed(seed_buffer *buffer, const void *fields, unsigned int size) {
    unsigned char block[1024];
    const unsigned int packed = lzf_compress(fields, size, block, sizeof block);
    const uint32_t sizes[2] = {packed, size};
    append(buffer, sizes, sizeof sizes);
    append(buffer, block, packed);
}

/* Sixteen points of x y z and an intensity, repeating enough for LZF's
 * back references; and four points of float64 x y z behind an rgb. */
static void write_compressed_seeds(const char *out_dir) {
    float xyzi[4][16];
    double rgb_xyz[2 + 3 * SEED_POINTS];
    seed_buffer repeated = {{0}, 0}, doubles = {{0}, 0};
    for (int i = 0; i < 16; ++i)
        for (int field = 0; field < 4; ++field) xyzi[field][i] = field < 3 ? cloud[i % SEED_POINTS][field] : 1.0f;
    append_text(&repeated, "VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
                           "WIDTH 8\nHEIGHT 2\nVIEWPOINT 0 0 0 0 1 0 0\nPOINTS 16\nDATA binary_compressed\n");
    append_compressed(&repeated, xyzi, sizeof xyzi);
    write_seed(out_dir, "fuzz_pcd", "compressed.pcd", repeated.bytes, repeated.size);
    memset(rgb_xyz, 0, sizeof rgb_xyz); /* the rgb field: 4 x 4 bytes, the first 2 doubles */
    for (int axis = 0; axis < 3; ++axis)
        for (int i = 0; i < SEED_POINTS; ++i) rgb_xyz[2 + axis * SEED_POINTS + i] = cloud[i][axis];
    append_text(&doubles, "VERSION 0.7\nFIELDS rgb x y z\nSIZE 4 8 8 8\nTYPE U F F F\nCOUNT 1 1 1 1\n"
                          "WIDTH 2\nHEIGHT 2\nPOINTS 4\nDATA binary_compressed\n");
    append_compressed(&doubles, rgb_xyz, sizeof rgb_xyz);
    write_seed(out_dir, "fuzz_pcd", "compressed_doubles.pcd", doubles.bytes, doubles.size);
}

void write_pcd_seeds(const char *out_dir) {
    write_text_seed(out_dir, "fuzz_pcd", "ascii.pcd", PCD_ASCII);
    write_text_seed(out_dir, "fuzz_pcd", "organized_rgb.pcd", PCD_ORGANIZED);
    seed_buffer floats = {{0}, 0};
    append_text(&floats, "VERSION 0.7\nFIELDS x y z intensity\nSIZE 4 4 4 4\nTYPE F F F F\nCOUNT 1 1 1 1\n"
                         "WIDTH 4\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA binary\n");
    append_records(&floats, 0, 1);
    write_seed(out_dir, "fuzz_pcd", "binary_float.pcd", floats.bytes, floats.size);
    seed_buffer doubles = {{0}, 0};
    append_text(&doubles, "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\n"
                          "WIDTH 4\nHEIGHT 1\nPOINTS 4\nDATA binary\n");
    append_records(&doubles, 1, 0);
    write_seed(out_dir, "fuzz_pcd", "binary_double.pcd", doubles.bytes, doubles.size);
    write_compressed_seeds(out_dir);
}

static const char PLY_ASCII[] =
    "ply\nformat ascii 1.0\ncomment a seed\nelement vertex 4\n"
    "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0.1 0.2 0.3 255\n-1 0.5 2 0\n3.25 -0.75 0 7\n1e-3 1e3 -7.5 9\n3 0 1 2\n";

static const char PLY_LIST_FIRST[] =
    "ply\nformat ascii 1.0\nelement camera 1\nproperty list uchar float params\n"
    "element vertex 2\nproperty double x\nproperty double y\nproperty double z\nend_header\n"
    "2 0.5 0.25\n1 2 3\n4 5 6\n";

void write_ply_seeds(const char *out_dir) {
    write_text_seed(out_dir, "fuzz_ply", "ascii.ply", PLY_ASCII);
    write_text_seed(out_dir, "fuzz_ply", "list_before_vertex.ply", PLY_LIST_FIRST);
    seed_buffer floats = {{0}, 0};
    append_text(&floats, "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                         "property float x\nproperty float y\nproperty float z\nproperty float intensity\n"
                         "end_header\n");
    append_records(&floats, 0, 1);
    write_seed(out_dir, "fuzz_ply", "binary_float.ply", floats.bytes, floats.size);
    seed_buffer doubles = {{0}, 0};
    append_text(&doubles, "ply\nformat binary_little_endian 1.0\nelement marker 1\nproperty short id\n"
                          "property uint code\nelement vertex 4\nproperty double x\nproperty double y\n"
                          "property double z\nend_header\n");
    const int16_t id = -3;
    const uint32_t code = 77;
    append(&doubles, &id, sizeof id);
    append(&doubles, &code, sizeof code);
    append_records(&doubles, 1, 0);
    write_seed(out_dir, "fuzz_ply", "binary_double.ply", doubles.bytes, doubles.size);
    write_text_seed(out_dir, "fuzz_ply", "big_endian.ply",
                    "ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nend_header\n");
}
