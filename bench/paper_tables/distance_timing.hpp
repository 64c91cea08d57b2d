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
    std::vector<DistanceTiming> timings(queries.size());
    std::vector<double> total_ms(queries.size(), 0.0);
    for (size_t q = 0; q < queries.size(); ++q) timings[q].distance = queries[q]();
    rounds = std::max(1, std::min(rounds, count));
    for (int round = 0; round < rounds; ++round) {
        const int batch = count / rounds + (round < count % rounds ? 1 : 0);
        for (size_t q = 0; q < queries.size(); ++q) {
            int disagreements = 0;
            const Clock::time_point start = Clock::now();
            for (int i = 0; i < batch; ++i) disagreements += queries[q]() != timings[q].distance;
            total_ms[q] += milliseconds_between(start, Clock::now());
            if (disagreements != 0) timings[q].consistent = false;
        }
    }
    for (size_t q = 0; q < queries.size(); ++q) timings[q].mean_ms = count > 0 ? total_ms[q] / count : 0.0;
    return timings;
}

}  // namespace paper_tables
