#include "octree/child_block_pool.hpp"

#include <algorithm>
#include <new>

namespace octoprox {
namespace {

// Slabs double from 4 KiB (21 blocks: a small map stays small) to 64 KiB
// (341 blocks), then stay there: at most one slab's worth, or a third of
// a small map, is reserved and not yet used.
constexpr size_t kFirstSlabBytes = 4096;
constexpr size_t kLargestSlabBytes = size_t{64} << 10;

}  // namespace

ChildBlockPool::~ChildBlockPool() {
    for (void *slab : slabs_) ::operator delete(slab, std::align_val_t{kAlignment});
}

void ChildBlockPool::add_slab() {
    // The newest slab's unused blocks go on the free list, not to waste.
    for (; next_ != end_; next_ += kBlockBytes) push_free(next_);
    const size_t bytes = slabs_.empty() ? kFirstSlabBytes : std::min(2 * reserved_, kLargestSlabBytes);
    const size_t usable = bytes / kBlockBytes * kBlockBytes;
    slabs_.reserve(slabs_.size() + 1);  // no leak if the vector cannot grow
    void *slab = ::operator new(usable, std::align_val_t{kAlignment});
    slabs_.push_back(slab);
    reserved_ += usable;
    next_ = static_cast<char *>(slab);
    end_ = next_ + usable;
}

void *ChildBlockPool::allocate() {
    void *block = free_;
    if (block != nullptr) {
        free_ = *static_cast<void **>(block);
        --free_count_;
    } else {
        if (next_ == end_) add_slab();
        block = next_;
        next_ += kBlockBytes;
    }
    ++in_use_;
    peak_in_use_ = std::max(peak_in_use_, in_use_);
    return block;
}

void ChildBlockPool::release(void *block) {
    push_free(block);
    --in_use_;
}

void ChildBlockPool::push_free(void *block) {
    *static_cast<void **>(block) = free_;
    free_ = block;
    ++free_count_;
}

size_t ChildBlockPool::blocks_available() const {
    return free_count_ + static_cast<size_t>(end_ - next_) / kBlockBytes;
}

void ChildBlockPool::reserve(size_t blocks) {
    while (blocks_available() < blocks) add_slab();
}

}  // namespace octoprox
