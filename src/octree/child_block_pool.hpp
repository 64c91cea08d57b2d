// Where a map's child blocks (bounded_tree.hpp) come from: slabs of
// 64-byte aligned blocks, carved in allocation order and reused through a
// free list.  A heap allocation per block would cost a malloc per node of
// every insert, and aligning each one leaves unusable gaps around it
// (glibc: a third more memory on geb079).  Slabs go back to the heap with
// the map; one map is changed by one thread at a time, so no lock.
#pragma once

#include <cstddef>
#include <vector>

namespace octoprox {

// A block's layout (child_blocks.cpp, read by OctreeView).
namespace child_block {
constexpr size_t kSlotsOffset = 64;  // the nodes follow the 8 pointers
constexpr size_t kSlotBytes = 16;    // a BoundedNode
constexpr size_t kBytes = kSlotsOffset + 8 * kSlotBytes;
}  // namespace child_block

class ChildBlockPool {
public:
    static constexpr size_t kBlockBytes = child_block::kBytes;
    static constexpr size_t kAlignment = 64;

    ChildBlockPool() = default;
    ~ChildBlockPool();
    ChildBlockPool(const ChildBlockPool &) = delete;
    ChildBlockPool &operator=(const ChildBlockPool &) = delete;

    void *allocate();
    void release(void *block);  // a block from this pool
    // Makes the next `blocks` allocate() calls take no memory from the heap
    // (they cannot throw); throws std::bad_alloc if the slabs cannot grow.
    void reserve(size_t blocks);
    // Gives the reserved slabs no allocation has reached back to the heap.
    void release_spares();

    size_t blocks_in_use() const { return in_use_; }
    // The most blocks in use at once since the last reset: what an update
    // really drew from the pool (blocks a prune frees are reused).
    size_t peak_blocks_in_use() const { return peak_in_use_; }
    void reset_peak() { peak_in_use_ = in_use_; }
    size_t bytes_reserved() const { return reserved_; }  // all slabs
    // Blocks the slabs hold beyond those in use (free, or not yet carved).
    size_t blocks_idle() const { return reserved_ / kBlockBytes - in_use_; }
    void swap(ChildBlockPool &other) noexcept;

private:
    struct Slab {
        void *memory = nullptr;
        size_t bytes = 0;
    };
    void add_slab();
    size_t next_slab_bytes() const;
    void reserve_spares(size_t blocks);
    void push_free(void *block);
    size_t blocks_available() const;

    std::vector<void *> slabs_;
    std::vector<Slab> spares_;  // reserved, not yet carved
    void *free_ = nullptr;  // released blocks, linked through their first word
    char *next_ = nullptr;  // the unused rest of the newest slab
    char *end_ = nullptr;
    size_t in_use_ = 0;
    size_t free_count_ = 0;  // blocks on the free list
    size_t peak_in_use_ = 0;
    size_t reserved_ = 0;
};

}  // namespace octoprox
