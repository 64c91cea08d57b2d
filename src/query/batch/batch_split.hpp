// Splitting a batch's items over threads: each task (task 0 on the
// caller's thread, base/parallel.hpp) takes the next chunk of items until
// none is left, so threads that draw cheap items (a configuration that
// collides early) take more, and the chunks shrink towards the end.
// Which thread answers an item never changes the answer: every item is
// checked on its own.
#pragma once

#include "base/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>

namespace octoprox {

// Items in the next chunk when `left` items are left: a share of them
// small enough that the tasks finish close together (the last chunks hold
// a single item), at most 64 so the shared counter is touched rarely.
inline size_t chunk_size(size_t left, size_t tasks) {
    return std::clamp<size_t>(left / (tasks * 4), 1, 64);
}

// Runs chunk(task, begin, end) over [0, items) on `tasks` tasks.
template <class Chunk>
void split_items(size_t tasks, size_t items, Chunk &&chunk) {
    if (tasks <= 1) {
        if (items > 0) chunk(size_t{0}, size_t{0}, items);
        return;
    }
    std::atomic<size_t> next{0};
    run_tasks(tasks, [&](size_t task) {
        size_t begin = next.load(std::memory_order_relaxed);
        for (;;) {
            if (begin >= items) return;
            const size_t end = begin + chunk_size(items - begin, tasks);
            // On failure `begin` is reloaded with the counter's new value.
            if (!next.compare_exchange_weak(begin, end, std::memory_order_relaxed)) continue;
            chunk(task, begin, end);
            begin = next.load(std::memory_order_relaxed);
        }
    });
}

}  // namespace octoprox
