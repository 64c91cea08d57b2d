// fault_malloc_sweep: every case of sweep_cases.hpp with its allocations
// failing one at a time (FailMode::kOnce) and then with memory staying short
// from the failing one on (kFromThenOn).  Each case runs in a child process,
// so a crash or an abort is reported with the case, k and a backtrace, and
// the other cases still run.
//
// Usage: fault_malloc_sweep [substring of case names]
#include "fault_alloc.hpp"
#include "fault_sweep.hpp"
#include "sweep_cases.hpp"

#include <execinfo.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace {

// Enough for every case of a call making thousands of allocations to end
// within seconds; calls making fewer are swept whole.
constexpr uint64_t kMaxAttempts = 1500;

void write_text(const char *text) {
    ssize_t ignored = write(STDOUT_FILENO, text, std::strlen(text));
    (void)ignored;
}

// Async-signal-safe enough for a dying child: fixed buffers, write(2), and
// backtrace(), loaded before any case runs.
void report_crash(int signal_number) {
    char text[512];
    std::snprintf(text, sizeof text, "  CRASH %s, allocation %llu failing: signal %d (%s); backtrace:\n",
                  fault::current_case(), static_cast<unsigned long long>(fault::current_k()), signal_number,
                  strsignal(signal_number));
    write_text(text);
    void *frames[64];
    const int count = backtrace(frames, 64);
    backtrace_symbols_fd(frames, count, STDOUT_FILENO);
    _exit(2);
}

void install_crash_handlers() {
    void *frame[1];
    backtrace(frame, 1);  // loads libgcc now, not in the handler
    for (int signal_number : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) signal(signal_number, report_crash);
}

// urdfdom logs every value it failed to parse (here: for want of memory)
// on stderr; the sweep reports on stdout.
void silence_stderr() {
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, STDERR_FILENO), close(null);
}

// Runs one case in a child; true when it passed.
bool run_isolated(const fault::SweepCase &sweep_case, fault::FailMode mode) {
    std::fflush(stdout);
    const pid_t child = fork();
    if (child < 0) {
        std::perror("fork");
        return false;
    }
    if (child == 0) {
        install_crash_handlers();
        silence_stderr();
        const bool passed = fault::sweep(sweep_case, mode, kMaxAttempts);
        std::fflush(stdout);
        _exit(passed ? 0 : 1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFSIGNALED(status))
        std::printf("  CRASH %s: killed by signal %d\n", sweep_case.name.c_str(), WTERMSIG(status));
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int main(int argc, char **argv) {
    setvbuf(stdout, nullptr, _IOLBF, 0);
    const std::string filter = argc > 1 ? argv[1] : "";
    std::vector<fault::SweepCase> cases = fault::map_and_robot_cases();
    for (fault::SweepCase &c : fault::query_cases()) cases.push_back(std::move(c));
    int passed = 0, failed = 0;
    for (fault::FailMode mode : {fault::FailMode::kOnce, fault::FailMode::kFromThenOn}) {
        for (const fault::SweepCase &sweep_case : cases) {
            if (sweep_case.name.find(filter) == std::string::npos) continue;
            if (run_isolated(sweep_case, mode)) ++passed;
            else ++failed;
        }
    }
    std::printf("fault_malloc_sweep: %d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
