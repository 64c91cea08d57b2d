// run_tasks on the library's pool of threads: every task runs once, task 0
// on the caller's thread; the threads are kept between calls; callers on
// several threads at once, calls from inside a task, a task that throws
// and a child made by fork() all get their work done.
#include "base/parallel.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace octoprox {
namespace {

TEST(TaskPool, RunsEveryTaskOnceTaskZeroOnTheCaller) {
    for (const size_t count : {size_t{1}, size_t{2}, size_t{3}, size_t{8}}) {
        std::vector<std::atomic<int>> runs(count);
        std::vector<std::thread::id> ids(count);
        run_tasks(count, [&](size_t i) {
            ++runs[i];
            ids[i] = std::this_thread::get_id();
        });
        for (size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << "task " << i << " of " << count;
        EXPECT_EQ(ids[0], std::this_thread::get_id());
        for (size_t i = 1; i < count; ++i) EXPECT_NE(ids[i], ids[0]) << "task " << i << " of " << count;
    }
}

TEST(TaskPool, KeepsItsThreadsBetweenCalls) {
    std::set<std::thread::id> helpers;
    for (int call = 0; call < 200; ++call) {
        std::thread::id helper;
        run_tasks(2, [&](size_t i) {
            if (i == 1) helper = std::this_thread::get_id();
        });
        helpers.insert(helper);
    }
    // One caller at a time needs one helper; the earlier tests' threads
    // may take turns.
    EXPECT_LE(helpers.size(), 8u);
}

TEST(TaskPool, CallersOnManyThreadsAtOnce) {
    std::atomic<size_t> total{0};
    std::vector<std::thread> callers;
    for (int c = 0; c < 4; ++c)
        callers.emplace_back([&] {
            for (int call = 0; call < 300; ++call) run_tasks(3, [&](size_t i) { total += i + 1; });
        });
    for (std::thread &caller : callers) caller.join();
    EXPECT_EQ(total.load(), size_t{4 * 300 * (1 + 2 + 3)});
}

TEST(TaskPool, CallsFromInsideATask) {
    std::atomic<int> inner{0};
    run_tasks(3, [&](size_t) { run_tasks(3, [&](size_t) { ++inner; }); });
    EXPECT_EQ(inner.load(), 9);
}

TEST(TaskPool, RethrowsAndKeepsWorking) {
    std::atomic<int> runs{0};
    EXPECT_THROW(run_tasks(4,
                           [&](size_t i) {
                               ++runs;
                               if (i == 2) throw std::runtime_error("task 2");
                           }),
                 std::runtime_error);
    EXPECT_EQ(runs.load(), 4);
    runs = 0;
    run_tasks(4, [&](size_t) { ++runs; });
    EXPECT_EQ(runs.load(), 4);
}

TEST(TaskPool, ChildOfForkGetsItsOwnThreads) {
    run_tasks(2, [](size_t) {});  // the parent's pool has a thread now
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        alarm(20);  // a child waiting on its parent's threads would hang
        std::atomic<int> runs{0};
        for (int call = 0; call < 50; ++call) run_tasks(3, [&](size_t) { ++runs; });
        _exit(runs.load() == 150 ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "the child did not finish (signal " << WTERMSIG(status) << ")";
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace octoprox
