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
    } else {
        if (next_ == end_) add_slab();
        block = next_;
        next_ += kBlockBytes;
    }
    ++in_use_;
    return block;
}

void ChildBlockPool::release(void *block) {
    *static_cast<void **>(block) = free_;
    free_ = block;
    --in_use_;
}

}  // namespace octoprox
