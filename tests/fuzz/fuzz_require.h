/*
 * FUZZ_REQUIRE: a check of a fuzz target.  A broken check prints what
 * failed and aborts, which libFuzzer records as a finding with its input.
 */
#ifndef OPX_FUZZ_REQUIRE_H
#define OPX_FUZZ_REQUIRE_H

#include <stdio.h>
#include <stdlib.h>

#define FUZZ_REQUIRE(condition)                                                              \
    do {                                                                                     \
        if (!(condition)) fuzz_fail(__FILE__, __LINE__, #condition, NULL);                   \
    } while (0)

static inline void fuzz_fail(const char *file, int line, const char *what, const char *detail) {
    fprintf(stderr, "%s:%d: fuzz check failed: %s%s%s\n", file, line, what,
            detail != NULL ? ": " : "", detail != NULL ? detail : "");
    abort();
}

#endif /* OPX_FUZZ_REQUIRE_H */
