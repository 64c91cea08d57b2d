// Splitting a batch's items over threads: each task (task 0 on the
// caller's thread, base/parallel.hpp) takes the next chunk of items until
// none is left, so threads that draw cheap items (a configuration that
// collides early) take more.  Which thread answers an item never changes
// the answer: every item is checked on its own.
#pragma once

#include "base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>

namespace octoprox {

// Items per chunk: a few chunks per task for the balance, at most 64 so
// the shared counter is touched rarely.
inline size_t chunk_size(size_t items, size_t tasks) {
    return std::clamp<size_t>(items / (tasks * 8), 1, 64);
}

// Runs chunk(task, begin, end) over [0, items) on `tasks` tasks.
template <class Chunk>
void split_items(size_t tasks, size_t items, Chunk &&chunk) {
    if (tasks <= 1) {
        if (items > 0) chunk(size_t{0}, size_t{0}, items);
        return;
    }
    std::atomic<size_t> next{0};
    const size_t size = chunk_size(items, tasks);
    run_tasks(tasks, [&](size_t task) {
        for (;;) {
            const size_t begin = next.fetch_add(size, std::memory_order_relaxed);
            if (begin >= items) return;
            chunk(task, begin, std::min(items, begin + size));
        }
    });
}

}  // namespace octoprox
