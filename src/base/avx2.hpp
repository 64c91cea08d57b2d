// AVX2 paths chosen at run time: a function that uses AVX2 carries the
// target attribute OPX_AVX2 (not a compiler flag for its file) and runs
// only where cpu_has_avx2() says so, so the library runs on any x86-64.
// OPX_AVX2_LANES is defined where the compiler can build such functions.
#pragma once

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define OPX_AVX2_LANES 1
#define OPX_AVX2 __attribute__((target("avx2")))
#endif

namespace octoprox {

// Whether this processor runs AVX2 (asked once); false without OPX_AVX2_LANES.
bool cpu_has_avx2();

}  // namespace octoprox
