// Counts heap allocations (the test program's global operator new is
// replaced in alloc_counter.cpp), to check code paths that must not allocate.
#pragma once

#include <cstdint>

namespace unit {

uint64_t allocation_count();

}  // namespace unit
