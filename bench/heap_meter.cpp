// The replaced global allocation functions behind heap_meter.hpp.  They
// allocate with malloc / aligned_alloc and count malloc_usable_size.
#include "heap_meter.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<size_t> live{0};
std::atomic<size_t> peak{0};

void count_allocation(void *block) {
    if (block == nullptr) return;
    const size_t now = live.fetch_add(malloc_usable_size(block), std::memory_order_relaxed) + malloc_usable_size(block);
    size_t seen = peak.load(std::memory_order_relaxed);
    while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
    }
}

void *allocate(size_t size, size_t alignment) {
    if (size == 0) size = 1;
    void *block = nullptr;
    if (alignment <= alignof(std::max_align_t)) block = std::malloc(size);
    else block = std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    count_allocation(block);
    return block;
}

void *allocate_or_throw(size_t size, size_t alignment) {
    void *block = allocate(size, alignment);
    if (block == nullptr) throw std::bad_alloc();
    return block;
}

void release(void *block) {
    if (block == nullptr) return;
    live.fetch_sub(malloc_usable_size(block), std::memory_order_relaxed);
    std::free(block);
}

constexpr size_t kDefault = alignof(std::max_align_t);

}  // namespace

namespace bench {

size_t heap_live_bytes() { return live.load(std::memory_order_relaxed); }
size_t heap_peak_bytes() { return peak.load(std::memory_order_relaxed); }
void reset_heap_peak() { peak.store(live.load(std::memory_order_relaxed), std::memory_order_relaxed); }

}  // namespace bench

void *operator new(size_t size) { return allocate_or_throw(size, kDefault); }
void *operator new[](size_t size) { return allocate_or_throw(size, kDefault); }
void *operator new(size_t size, std::align_val_t a) { return allocate_or_throw(size, static_cast<size_t>(a)); }
void *operator new[](size_t size, std::align_val_t a) { return allocate_or_throw(size, static_cast<size_t>(a)); }
void *operator new(size_t size, const std::nothrow_t &) noexcept { return allocate(size, kDefault); }
void *operator new[](size_t size, const std::nothrow_t &) noexcept { return allocate(size, kDefault); }
void *operator new(size_t size, std::align_val_t a, const std::nothrow_t &) noexcept {
    return allocate(size, static_cast<size_t>(a));
}
void *operator new[](size_t size, std::align_val_t a, const std::nothrow_t &) noexcept {
    return allocate(size, static_cast<size_t>(a));
}
void operator delete(void *block) noexcept { release(block); }
void operator delete[](void *block) noexcept { release(block); }
void operator delete(void *block, size_t) noexcept { release(block); }
void operator delete[](void *block, size_t) noexcept { release(block); }
void operator delete(void *block, std::align_val_t) noexcept { release(block); }
void operator delete[](void *block, std::align_val_t) noexcept { release(block); }
void operator delete(void *block, size_t, std::align_val_t) noexcept { release(block); }
void operator delete[](void *block, size_t, std::align_val_t) noexcept { release(block); }
void operator delete(void *block, const std::nothrow_t &) noexcept { release(block); }
void operator delete[](void *block, const std::nothrow_t &) noexcept { release(block); }
void operator delete(void *block, std::align_val_t, const std::nothrow_t &) noexcept { release(block); }
void operator delete[](void *block, std::align_val_t, const std::nothrow_t &) noexcept { release(block); }
