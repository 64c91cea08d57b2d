#include "base/parallel.hpp"

#include "base/task_pool.hpp"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace octoprox {

void run_tasks(size_t count, const std::function<void(size_t)> &task) {
    std::vector<std::exception_ptr> errors(count);
    auto run = [&](size_t i) {
        try {
            task(i);
        } catch (...) {
            errors[i] = std::current_exception();
        }
    };
    run_on_pool(count, run);
    for (const std::exception_ptr &error : errors)
        if (error) std::rethrow_exception(error);
}

size_t task_count(size_t requested, size_t work_items) {
    const size_t wanted = requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
    return std::max<size_t>(1, std::min(wanted, work_items));
}

}  // namespace octoprox
