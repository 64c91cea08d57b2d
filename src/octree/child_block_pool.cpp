#include "octree/child_block_pool.hpp"

#include <algorithm>
#include <new>
#include <utility>

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
    release_spares();
}

size_t ChildBlockPool::next_slab_bytes() const {
    const size_t bytes = slabs_.empty() && spares_.empty() ? kFirstSlabBytes : std::min(2 * reserved_, kLargestSlabBytes);
    return bytes / kBlockBytes * kBlockBytes;
}

void ChildBlockPool::add_slab() {
    // The newest slab's unused blocks go on the free list, not to waste.
    for (; next_ != end_; next_ += kBlockBytes) push_free(next_);
    slabs_.reserve(slabs_.size() + 1);  // no leak if the vector cannot grow
    Slab slab;
    if (!spares_.empty()) {
        slab = spares_.front();  // the smallest: the larger ones may go back unused
        spares_.erase(spares_.begin());
    } else {
        slab.bytes = next_slab_bytes();
        slab.memory = ::operator new(slab.bytes, std::align_val_t{kAlignment});
        reserved_ += slab.bytes;
    }
    slabs_.push_back(slab.memory);
    next_ = static_cast<char *>(slab.memory);
    end_ = next_ + slab.bytes;
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

void ChildBlockPool::swap(ChildBlockPool &other) noexcept {
    slabs_.swap(other.slabs_);
    spares_.swap(other.spares_);
    std::swap(free_, other.free_);
    std::swap(next_, other.next_);
    std::swap(end_, other.end_);
    std::swap(in_use_, other.in_use_);
    std::swap(free_count_, other.free_count_);
    std::swap(peak_in_use_, other.peak_in_use_);
    std::swap(reserved_, other.reserved_);
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
    size_t spare_blocks = 0;
    for (const Slab &slab : spares_) spare_blocks += slab.bytes / kBlockBytes;
    return free_count_ + static_cast<size_t>(end_ - next_) / kBlockBytes + spare_blocks;
}

// Spare slabs are carved only when the free list and the current slab are
// used up, so the ones an update did not need can go back to the heap whole.
void ChildBlockPool::reserve(size_t blocks) {
    try {
        reserve_spares(blocks);
    } catch (...) {
        release_spares();  // a reserve that fails holds no more memory than before
        throw;
    }
}

void ChildBlockPool::reserve_spares(size_t blocks) {
    size_t available = blocks_available();
    while (available < blocks) {
        Slab slab;
        slab.bytes = next_slab_bytes();
        spares_.reserve(spares_.size() + 1);  // no leak if the vector cannot grow
        slab.memory = ::operator new(slab.bytes, std::align_val_t{kAlignment});
        spares_.push_back(slab);
        reserved_ += slab.bytes;
        available += slab.bytes / kBlockBytes;
    }
    slabs_.reserve(slabs_.size() + spares_.size());  // taking a spare allocates nothing
}

void ChildBlockPool::release_spares() {
    for (const Slab &slab : spares_) {
        ::operator delete(slab.memory, std::align_val_t{kAlignment});
        reserved_ -= slab.bytes;
    }
    spares_.clear();
}

}  // namespace octoprox
