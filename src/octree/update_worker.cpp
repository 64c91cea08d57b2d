#include "octree/update_worker.hpp"

namespace octoprox {
namespace {

void push(void *&list, void *block) {
    *static_cast<void **>(block) = list;
    list = block;
}

void *pop(void *&list) {
    void *block = list;
    list = *static_cast<void **>(block);
    return block;
}

}  // namespace

UpdateWorker::~UpdateWorker() {
    const std::lock_guard<std::mutex> guard(pool_lock_);
    while (free_ != nullptr) pool_.release(pop(free_));
}

void UpdateWorker::draw_batch() {
    const std::lock_guard<std::mutex> guard(pool_lock_);
    for (size_t i = 0; i < kBatch; ++i) push(free_, pool_.allocate());
}

void *UpdateWorker::allocate() {
    if (free_ == nullptr) draw_batch();
    return pop(free_);
}

void UpdateWorker::release(void *block) { push(free_, block); }

thread_local UpdateWorker *UpdateWorker::t_current = nullptr;

UpdateWorker::Scope::Scope(UpdateWorker &worker) : previous_(t_current) { t_current = &worker; }

UpdateWorker::Scope::~Scope() { t_current = previous_; }

}  // namespace octoprox
