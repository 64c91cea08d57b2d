/*
 * Reading a fuzz input as a stream of choices.  Every reader returns a
 * value even when the input is exhausted (zeros), so a harness never has to
 * check the remaining size: a short input simply makes plain choices.
 */
#ifndef OPX_FUZZ_INPUT_H
#define OPX_FUZZ_INPUT_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct fuzz_input {
    const uint8_t *data;
    size_t size;
} fuzz_input;

static inline uint8_t take_u8(fuzz_input *in) {
    uint8_t value = 0;
    if (in->size > 0) {
        value = in->data[0];
        ++in->data;
        --in->size;
    }
    return value;
}

/* Little-endian bytes; missing bytes are zeros. */
static inline uint64_t take_bits(fuzz_input *in, int bytes) {
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value |= (uint64_t)take_u8(in) << (8 * i);
    return value;
}

static inline uint32_t take_u32(fuzz_input *in) { return (uint32_t)take_bits(in, 4); }

/* A number in [0, n); 0 when n is 0.  One byte when n <= 256. */
static inline size_t take_below(fuzz_input *in, size_t n) {
    if (n == 0) return 0;
    return (size_t)(n <= 256 ? take_u8(in) : take_bits(in, 4)) % n;
}

static inline int take_bool(fuzz_input *in) { return take_u8(in) & 1; }

/* The 8 bytes of a double as they are: NaN payloads, denormals, anything. */
static inline double take_raw_double(fuzz_input *in) {
    const uint64_t bits = take_bits(in, 8);
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

/* A double chosen the way bugs like: edge values, small multiples of a
 * tenth, or raw bits.  The first byte picks the kind. */
static inline double take_double(fuzz_input *in) {
    static const double edges[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 0.05, 0.1, 1e-6, 1e-7, 1e6, 1e7, 1e300, -1e300,
        DBL_MAX, -DBL_MAX, DBL_MIN, 4.9406564584124654e-324, 1638.4, -1638.4, 3276.8,
        2147483648.0, 1e-12, 0.999999, 1.0000001, NAN, INFINITY, -INFINITY,
    };
    const uint8_t kind = take_u8(in);
    if (kind < 96) return (double)(int8_t)take_u8(in) / 10.0;
    if (kind < 160) return edges[take_below(in, sizeof edges / sizeof edges[0])];
    if (kind < 224) return (double)(int16_t)take_bits(in, 2) / 1000.0;
    return take_raw_double(in);
}

/* A probability-like double: mostly in (0, 1), sometimes anything. */
static inline double take_fraction(fuzz_input *in) {
    const uint8_t kind = take_u8(in);
    if (kind < 192) return (kind % 101) / 100.0;
    return take_double(in);
}

/* A struct_size for a struct of `real` bytes: mostly right, else one of
 * the values a careless or newer caller passes. */
static inline uint32_t take_struct_size(fuzz_input *in, size_t real) {
    const uint8_t kind = take_u8(in);
    if (kind < 224) return (uint32_t)real;
    switch (kind % 8) {
    case 0: return 0;
    case 1: return 3;
    case 2: return 4;
    case 3: return 8;
    case 4: return (uint32_t)real - 8;
    case 5: return (uint32_t)real + 8;
    case 6: return UINT32_MAX;
    default: return take_u32(in);
    }
}

#endif /* OPX_FUZZ_INPUT_H */
