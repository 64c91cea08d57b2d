// Wall-clock timing helpers (std::chrono::steady_clock), in milliseconds.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

namespace paper_tables {

using Clock = std::chrono::steady_clock;

inline double milliseconds_between(Clock::time_point start, Clock::time_point end) {
    return std::chrono::duration<double, std::milli>(end - start).count();
}

// The median (the mean of the two middle values for an even count).
inline double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t middle = values.size() / 2;
    if (values.size() % 2 == 1) return values[middle];
    return 0.5 * (values[middle - 1] + values[middle]);
}

struct QueryTiming {
    double mean_ms = 0.0;
    bool collided = false;    // the answer of the queries
    bool consistent = true;   // every query gave the same answer
};

// A query returning "collided"; each call is the same query on the same
// scene, as in the paper.
using CollisionQuery = std::function<bool()>;

// Times `count` calls of each query, interleaved: in each of `rounds`
// rounds every query runs count/rounds times in turn, so a change of the
// machine's load during the run (other builds on a shared machine) hits
// all of them alike.  Each query runs once untimed first, to warm caches
// and get its answer.  T_q is the total time over `count` calls / count.
template <class Answer>
struct TimingOf {
    double mean_ms = 0.0;
    Answer answer{};         // the answer of the first (untimed) call
    bool consistent = true;  // every call gave the same answer, bit for bit
};

// The loop behind both kinds of query (collision yes/no, distance).
template <class Answer>
std::vector<TimingOf<Answer>> time_interleaved(int count, const std::vector<std::function<Answer()>> &queries,
                                               int rounds) {
    std::vector<TimingOf<Answer>> timings(queries.size());
    std::vector<double> total_ms(queries.size(), 0.0);
    for (size_t q = 0; q < queries.size(); ++q) timings[q].answer = queries[q]();
    rounds = std::max(1, std::min(rounds, count));
    for (int round = 0; round < rounds; ++round) {
        const int batch = count / rounds + (round < count % rounds ? 1 : 0);
        for (size_t q = 0; q < queries.size(); ++q) {
            int disagreements = 0;
            const Clock::time_point start = Clock::now();
            for (int i = 0; i < batch; ++i) disagreements += queries[q]() != timings[q].answer;
            total_ms[q] += milliseconds_between(start, Clock::now());
            if (disagreements != 0) timings[q].consistent = false;
        }
    }
    for (size_t q = 0; q < queries.size(); ++q) timings[q].mean_ms = count > 0 ? total_ms[q] / count : 0.0;
    return timings;
}

inline std::vector<QueryTiming> time_queries_interleaved(int count, const std::vector<CollisionQuery> &queries,
                                                         int rounds = 10) {
    std::vector<QueryTiming> out;
    for (const TimingOf<bool> &t : time_interleaved<bool>(count, queries, rounds))
        out.push_back(QueryTiming{t.mean_ms, t.answer, t.consistent});
    return out;
}

// The time of one call of `work`, in milliseconds.
template <class Work>
double time_once_ms(Work &&work) {
    const Clock::time_point start = Clock::now();
    work();
    return milliseconds_between(start, Clock::now());
}

}  // namespace paper_tables
