// Running a few tasks on the caller's thread and the library's pool of
// threads (base/task_pool.hpp).
#pragma once

#include <cstddef>
#include <functional>

namespace octoprox {

// Runs task(0) .. task(count - 1): task 0 on the caller's thread, every
// other on a pool thread.  A task no thread can be had for (none idle, and
// none can be started: no resources, no memory) runs on the caller's thread,
// so the work is done either way.  Returns when all are done; the first
// exception a task threw (by index) is then rethrown.
void run_tasks(size_t count, const std::function<void(size_t)> &task);

// One per hardware thread when `requested` is 0, else `requested`, and
// never more than `work_items`, never less than 1.
size_t task_count(size_t requested, size_t work_items);

}  // namespace octoprox
