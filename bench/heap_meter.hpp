// Heap bytes of this process, counted by replacing the global operator new
// and delete (heap_meter.cpp): every C++ allocation of the program, of
// OctoProx, OctoMap and FCL goes through them (none of the three calls
// malloc directly for its data).  Bytes are malloc_usable_size of each
// block, so allocator rounding is included.  Single counters: read them
// from one thread at a time.
#pragma once

#include <cstddef>

namespace bench {

// Bytes allocated by operator new and not yet freed.
size_t heap_live_bytes();

// The largest heap_live_bytes() since the last reset_heap_peak().
size_t heap_peak_bytes();
void reset_heap_peak();

// What one piece of work did to the heap: bytes it left allocated (may be
// negative) and how far above the starting level it went.
struct HeapDelta {
    long long retained = 0;
    size_t peak_above_start = 0;
};

template <class Work>
HeapDelta measure_heap(Work &&work) {
    const size_t start = heap_live_bytes();
    reset_heap_peak();
    work();
    HeapDelta delta;
    delta.retained = static_cast<long long>(heap_live_bytes()) - static_cast<long long>(start);
    delta.peak_above_start = heap_peak_bytes() - start;
    return delta;
}

}  // namespace bench
