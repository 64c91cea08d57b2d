#include "base/task_pool.hpp"

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace octoprox {
namespace {

// How long a thread with nothing to do, or a caller waiting for its
// tasks, checks for work or completion before it sleeps.
constexpr std::chrono::microseconds kSpin{50};

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Calls done() (which must not block) until it holds or kSpin has passed.
template <class Done>
void spin_until(Done &&done) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (;;) {
        for (int i = 0; i < 64; ++i) {
            if (done()) return;
            cpu_relax();
        }
        if (std::chrono::steady_clock::now() >= until) return;
    }
}

// The tasks of one call still running on pool threads.
class Completion {
public:
    explicit Completion(size_t pending) : pending_(pending) {}

    void finish_one() {
        // Under the lock: wait() takes it before returning, so this object
        // outlives the last use here.
        std::lock_guard<std::mutex> lock(mutex_);
        if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) done_.notify_one();
    }

    void wait() {
        spin_until([this] { return pending_.load(std::memory_order_acquire) == 0; });
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return pending_.load(std::memory_order_acquire) == 0; });
    }

private:
    std::mutex mutex_;
    std::condition_variable done_;
    std::atomic<size_t> pending_;
};

struct Job {
    const std::function<void(size_t)> *run = nullptr;
    size_t index = 0;
    Completion *completion = nullptr;
};

class Pool;

// One thread of the pool and the slot its jobs are handed in.
class PoolThread {
public:
    explicit PoolThread(Pool &pool) : pool_(pool), thread_([this] { loop(); }) {}
    ~PoolThread() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
        }
        wake_.notify_one();
        thread_.join();
    }

    void hand(const Job &job) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            job_ = job;
            has_job_ = true;
            posted_.store(true, std::memory_order_release);
        }
        wake_.notify_one();
    }

private:
    void loop();

    Pool &pool_;
    std::mutex mutex_;
    std::condition_variable wake_;
    Job job_;              // under mutex_
    bool has_job_ = false;  // under mutex_
    bool stop_ = false;     // under mutex_
    std::atomic<bool> posted_{false};  // has_job_, read without the lock while spinning
    std::thread thread_;    // last: starts once the fields above exist
};

class Pool {
public:
    ~Pool() {
        // No call runs while the library unloads: every thread is idle,
        // or about to be (outside the lock, so it can give itself back).
        std::vector<std::unique_ptr<PoolThread>> threads;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            threads.swap(threads_);
        }
        threads.clear();
    }

    // An idle thread, else a new one; null when none can be started.
    PoolThread *take() {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!idle_.empty()) {
            PoolThread *thread = idle_.back();
            idle_.pop_back();
            return thread;
        }
        try {
            idle_.reserve(threads_.size() + 1);  // give_back cannot throw
            threads_.push_back(std::make_unique<PoolThread>(*this));
            return threads_.back().get();
        } catch (const std::exception &) {  // no thread, or no memory for one
            return nullptr;
        }
    }

    void give_back(PoolThread *thread) {
        std::lock_guard<std::mutex> lock(mutex_);
        idle_.push_back(thread);
    }

private:
    std::mutex mutex_;
    std::vector<std::unique_ptr<PoolThread>> threads_;
    std::vector<PoolThread *> idle_;
};

void PoolThread::loop() {
    for (;;) {
        spin_until([this] { return posted_.load(std::memory_order_acquire); });
        Job job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return has_job_ || stop_; });
            if (!has_job_) return;
            job = job_;
            has_job_ = false;
            posted_.store(false, std::memory_order_relaxed);
        }
        (*job.run)(job.index);
        // Idle again before the caller hears of it, so that the caller's
        // next call finds this thread.
        pool_.give_back(this);
        job.completion->finish_one();
    }
}

// The pool of this process.  After fork() the child drops its parent's
// pool without touching it (its threads do not exist in the child, its
// mutex may have been held by one of them) and makes its own.
std::atomic<Pool *> current_pool{nullptr};
std::mutex pool_creation;

void forget_pool_after_fork() { current_pool.store(nullptr, std::memory_order_relaxed); }

Pool &pool() {
    Pool *pool = current_pool.load(std::memory_order_acquire);
    if (pool != nullptr) return *pool;
    std::lock_guard<std::mutex> lock(pool_creation);
    pool = current_pool.load(std::memory_order_relaxed);
    if (pool == nullptr) {
        static const bool registered = pthread_atfork(nullptr, nullptr, forget_pool_after_fork) == 0;
        (void)registered;
        pool = new Pool();
        current_pool.store(pool, std::memory_order_release);
    }
    return *pool;
}

// Stops and joins the threads when the library is unloaded or the
// process exits.
struct PoolOwner {
    ~PoolOwner() { delete current_pool.exchange(nullptr); }
} pool_owner;

}  // namespace

void run_on_pool(size_t count, const std::function<void(size_t)> &run) {
    if (count == 0) return;
    std::vector<size_t> inline_tasks;
    inline_tasks.reserve(count);
    Completion completion(count - 1);
    Pool &threads = pool();
    for (size_t i = 1; i < count; ++i) {
        if (PoolThread *thread = threads.take()) thread->hand(Job{&run, i, &completion});
        else inline_tasks.push_back(i);  // reserved above: cannot throw
    }
    run(0);
    for (const size_t i : inline_tasks) {
        run(i);
        completion.finish_one();
    }
    completion.wait();
}

}  // namespace octoprox
