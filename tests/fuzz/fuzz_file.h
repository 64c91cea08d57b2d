/*
 * A scratch file per fuzz process, for readers that take a path: each
 * input is written over it (the file is made once, removed at exit).
 */
#ifndef OPX_FUZZ_FILE_H
#define OPX_FUZZ_FILE_H

#include <stddef.h>
#include <stdint.h>

/* Writes the input into the process's scratch file, whose name ends in
 * `suffix` (the same every call), and returns its path. */
const char *fuzz_scratch_file(const char *suffix, const uint8_t *data, size_t size);

/* How many of `count` xyz float triples are finite: what a reader's
 * finite_count must say. */
size_t fuzz_count_finite(const float *xyz, size_t count);

#endif /* OPX_FUZZ_FILE_H */
