// opx-frame-bench's summaries: per stage and in total, the median and the
// worst frame of each pipeline, memory, ratios; printed and as JSON.
#pragma once

#include <string>
#include <vector>

#include "frame_run.hpp"

namespace frame_bench {

struct Spread {
    double median_ms = 0.0, worst_ms = 0.0;
};

// Totals: every stage but the other ingest mode.  total: with the ray-cast
// ingest (the map the queries use); total_endpoints: the same frame with
// endpoint-only ingest instead.
enum Summary { kPoseAndCollision = kStageCount, kTotal, kTotalEndpoints, kSummaryCount };
constexpr const char *kSummaryKeys[kSummaryCount - kStageCount] = {"pose_update_plus_collision", "total",
                                                                   "total_endpoints_ingest"};

// [pipeline][stage or summary]
using RunSpreads = std::vector<std::vector<Spread>>;
RunSpreads summarize(const RunResult &run);

// Everything the report states beside the runs.
struct ReportContext {
    std::string cpu, load_start, load_end;
    bool quick = false;
    double seconds = 0.0;        // wall time of the whole program
    double peak_rss_mib = 0.0;   // getrusage: the whole process
    size_t robot_heap_opx = 0;   // the link set (all meshes and their trees)
    size_t robot_heap_fcl = 0;   // the FCL objects and their manager
};

void print_run(const RunResult &run);
bool write_report_json(const std::string &path, const std::vector<RunResult> &runs, const ReportContext &context);

}  // namespace frame_bench
