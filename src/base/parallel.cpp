#include "base/parallel.hpp"

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
    // Reserved before any thread starts, so that nothing below allocates
    // while one runs (but a thread's own start).
    std::vector<std::thread> threads;
    std::vector<size_t> inline_tasks;
    threads.reserve(count);
    inline_tasks.reserve(count);
    for (size_t i = 1; i < count; ++i) {
        try {
            threads.emplace_back(run, i);
        } catch (const std::exception &) {  // no thread, or no memory for one
            inline_tasks.push_back(i);  // reserved above: cannot throw
        }
    }
    run(0);
    for (const size_t i : inline_tasks) run(i);
    for (std::thread &t : threads) t.join();
    for (const std::exception_ptr &error : errors)
        if (error) std::rethrow_exception(error);
}

size_t task_count(size_t requested, size_t work_items) {
    const size_t wanted = requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
    return std::max<size_t>(1, std::min(wanted, work_items));
}

}  // namespace octoprox
