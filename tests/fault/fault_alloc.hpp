// An allocator that fails on request: the test program defines malloc and
// its relatives (fault_alloc.cpp), forwarding to glibc's own allocator, so
// every allocation of the library and of the libraries it uses (operator
// new included, which calls malloc) can be made to fail.
//
// Only allocations on the thread that armed the countdown are counted.
#pragma once

#include <cstdint>

namespace fault {

enum class FailMode {
    kOnce,       // only the k-th allocation fails
    kFromThenOn  // the k-th and every later one fail (memory stays short)
};

// Fails the k-th allocation (k >= 1) from now on this thread.
void arm(uint64_t k, FailMode mode);

struct ArmedRun {
    bool failure_hit = false;  // the k-th allocation was reached (and failed)
    uint64_t allocations = 0;  // allocations asked for while armed
    int64_t live_blocks = 0;   // allocations that succeeded minus blocks freed
};

// Stops counting and tells what happened since arm().
ArmedRun disarm();

}  // namespace fault
