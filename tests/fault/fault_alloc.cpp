#include "fault_alloc.hpp"

#include <cerrno>
#include <cstddef>

// glibc's allocator under its own names, so the wrappers below can replace
// the public ones (glibc supports replacing malloc this way).
extern "C" {
void *__libc_malloc(size_t size);
void *__libc_calloc(size_t count, size_t size);
void *__libc_realloc(void *pointer, size_t size);
void __libc_free(void *pointer);
void *__libc_memalign(size_t alignment, size_t size);
}

namespace {

// Thread-local: a static TLS block of the executable, reachable from
// malloc without allocating.
struct Countdown {
    bool armed = false;
    fault::FailMode mode = fault::FailMode::kOnce;
    uint64_t target = 0;
    uint64_t seen = 0;
    bool hit = false;
    int64_t live = 0;
};
thread_local Countdown t_countdown;

// True when this allocation must fail.
bool next_allocation_fails() {
    Countdown &c = t_countdown;
    if (!c.armed) return false;
    ++c.seen;
    if (c.seen == c.target) c.hit = true;
    if (c.seen == c.target) return true;
    return c.hit && c.mode == fault::FailMode::kFromThenOn;
}

void *counted(void *block) {
    if (block != nullptr && t_countdown.armed) ++t_countdown.live;
    return block;
}

void count_free(void *block) {
    if (block != nullptr && t_countdown.armed) --t_countdown.live;
}

void *refused() {
    errno = ENOMEM;
    return nullptr;
}

}  // namespace

namespace fault {

void arm(uint64_t k, FailMode mode) {
    Countdown &c = t_countdown;
    c = Countdown();
    c.mode = mode;
    c.target = k;
    c.armed = true;
}

ArmedRun disarm() {
    Countdown &c = t_countdown;
    c.armed = false;
    ArmedRun run;
    run.failure_hit = c.hit;
    run.allocations = c.seen;
    run.live_blocks = c.live;
    return run;
}

}  // namespace fault

extern "C" {

void *malloc(size_t size) {
    if (next_allocation_fails()) return refused();
    return counted(__libc_malloc(size));
}

void *calloc(size_t count, size_t size) {
    if (next_allocation_fails()) return refused();
    return counted(__libc_calloc(count, size));
}

// realloc(p, 0) frees p (glibc); realloc(NULL, n) is malloc.  A failed
// realloc leaves p as it was.
void *realloc(void *pointer, size_t size) {
    if (pointer != nullptr && size == 0) {
        count_free(pointer);
        return __libc_realloc(pointer, 0);
    }
    if (next_allocation_fails()) return refused();
    if (pointer == nullptr) return counted(__libc_realloc(nullptr, size));
    return __libc_realloc(pointer, size);
}

void free(void *pointer) {
    count_free(pointer);
    __libc_free(pointer);
}

void *memalign(size_t alignment, size_t size) {
    if (next_allocation_fails()) return refused();
    return counted(__libc_memalign(alignment, size));
}

void *aligned_alloc(size_t alignment, size_t size) {
    if (next_allocation_fails()) return refused();
    return counted(__libc_memalign(alignment, size));
}

int posix_memalign(void **out, size_t alignment, size_t size) {
    if (alignment % sizeof(void *) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
    if (next_allocation_fails()) return ENOMEM;
    void *block = counted(__libc_memalign(alignment, size));
    if (block == nullptr) return ENOMEM;
    *out = block;
    return 0;
}

void *valloc(size_t size) {
    if (next_allocation_fails()) return refused();
    return counted(__libc_memalign(4096, size));
}

}  // extern "C"
