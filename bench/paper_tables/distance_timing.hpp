// Timing of distance queries, interleaved as in timing.hpp: each query
// returns a distance, which must be the same on every call.
#pragma once

#include <functional>
#include <vector>

#include "timing.hpp"

namespace paper_tables {

struct DistanceTiming {
    double mean_ms = 0.0;
    double distance = 0.0;   // the answer of the queries, metres
    bool consistent = true;  // every call gave the same distance, bit for bit
};

// A distance query; each call is the same query on the same scene.
using DistanceQuery = std::function<double()>;

// Times `count` calls of each query, interleaved in `rounds` rounds (see
// time_queries_interleaved), after one untimed call that warms caches and
// gives the answer.  T_q is the total time over `count` calls / count.
inline std::vector<DistanceTiming> time_distance_queries_interleaved(int count,
                                                                     const std::vector<DistanceQuery> &queries,
                                                                     int rounds = 10) {
    std::vector<DistanceTiming> out;
    for (const TimingOf<double> &t : time_interleaved<double>(count, queries, rounds))
        out.push_back(DistanceTiming{t.mean_ms, t.answer, t.consistent});
    return out;
}

}  // namespace paper_tables
