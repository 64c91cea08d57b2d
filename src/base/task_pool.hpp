// Threads kept between parallel calls (base/parallel.hpp), so that a call
// does not pay for starting and joining threads: about 0.1 ms each on a
// virtual machine, several times a frame in the insert.
//
// Any thread may use the pool, several at once: a call takes idle threads
// for itself and starts new ones when none is idle, so the pool holds as
// many threads as the most tasks ever run at once, less one.  A thread
// done with its task waits about 50 microseconds for the next (the
// insert's phases follow one another closely), then sleeps until it is
// handed one.  A child made by fork() starts a pool of its own (its
// parent's threads are not in it); unloading the library stops and joins
// the threads.
#pragma once

#include <cstddef>
#include <functional>

namespace octoprox {

// Runs run(0) on the caller's thread and run(1) .. run(count - 1) on pool
// threads, returning when all have returned.  A task for which no thread
// can be had (none idle, none can be started) runs on the caller's thread
// after run(0).  `run` must not throw.
void run_on_pool(size_t count, const std::function<void(size_t)> &run);

}  // namespace octoprox
