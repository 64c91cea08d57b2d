// One thread's share of a map update that runs on several threads
// (frame_update.cpp splits a frame's cells by subtree).  The map's pool of
// child blocks and its node count belong to the map, one thread at a time;
// a worker draws blocks from the pool in batches under a lock, keeps the
// blocks its prunes free for its own next nodes, and counts the nodes it
// adds and deletes apart.  The child-block store (child_blocks.cpp) goes
// through the worker installed on the calling thread, if any.
#pragma once

#include "octree/child_block_pool.hpp"

#include <cstddef>
#include <mutex>

namespace octoprox {

class UpdateWorker {
public:
    // Blocks a worker draws at once.  An update on `threads` threads
    // reserves this many more per thread (update_reserve.hpp), so a batch
    // never takes the pool past what the update reserved.
    static constexpr size_t kBatch = 64;

    UpdateWorker(ChildBlockPool &pool, std::mutex &pool_lock) : pool_(pool), pool_lock_(pool_lock) {}
    // Gives the blocks it holds back to the pool.
    ~UpdateWorker();
    UpdateWorker(const UpdateWorker &) = delete;
    UpdateWorker &operator=(const UpdateWorker &) = delete;

    void *allocate();
    void release(void *block);
    void count_nodes(long delta) {
        nodes_added_ += delta;
        size_changed_ = true;
    }
    // Nodes created less nodes deleted, and whether there were any.
    long nodes_added() const { return nodes_added_; }
    bool size_changed() const { return size_changed_; }

    // The worker installed on this thread, nullptr when none.
    static UpdateWorker *current() { return t_current; }

    // Installs a worker on this thread for its lifetime.
    class Scope {
    public:
        explicit Scope(UpdateWorker &worker);
        ~Scope();
        Scope(const Scope &) = delete;
        Scope &operator=(const Scope &) = delete;

    private:
        UpdateWorker *previous_;
    };

private:
    void draw_batch();

    // Read on every node an update creates or frees: the library is built
    // with TLS descriptors (-mtls-dialect=gnu2, src/CMakeLists.txt), which
    // make that read cheap in a library loaded with dlopen too.
    static thread_local UpdateWorker *t_current;

    ChildBlockPool &pool_;
    std::mutex &pool_lock_;
    void *free_ = nullptr;  // blocks held, linked through their first word
    long nodes_added_ = 0;
    bool size_changed_ = false;
};

}  // namespace octoprox
