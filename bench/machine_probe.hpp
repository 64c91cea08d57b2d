// How fast this machine's two hardware threads are at the moment.  A
// virtual machine's processors may be hardware threads of its host's
// cores that other work shares: a thread alone then runs at half a core's
// speed on arithmetic-bound work, and two threads of one core share its
// adders.  The benchmarks print and record this at their start and end,
// so that their one- and two-thread rows can be read for what they are.
#pragma once

#include <string>

namespace bench {

// Integer additions a nanosecond of a loop that keeps a core's adders busy
// (several a cycle), best of three: on one thread alone, and on each of
// two threads at once.  On a core of its own a thread of a current x86-64
// processor does about 4 a cycle (13 at 3.3 GHz); half that means the core
// is shared.  About 60 ms to measure.
struct ThreadSpeed {
    double one_thread = 0.0;
    double each_of_two = 0.0;
};

ThreadSpeed measure_thread_speed();

// Prints the speeds measured at a run's start and end.
void print_thread_speeds(const ThreadSpeed &at_start, const ThreadSpeed &at_end);

// The same as the JSON fields every benchmark row carries, comma-separated
// without braces: "adds_per_ns_one_thread_at_start": ..., and so on.
std::string thread_speed_json_fields(const ThreadSpeed &at_start, const ThreadSpeed &at_end);

}  // namespace bench
