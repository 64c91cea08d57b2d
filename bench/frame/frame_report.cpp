#include "frame_report.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "report.hpp"
#include "timing.hpp"

namespace frame_bench {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;

double value_of(const StageTimes &t, int summary) {
    if (summary < kStageCount) return t[summary];
    const double queries = t[kPoseUpdate] + t[kCollision];
    if (summary == kPoseAndCollision) return queries;
    const double ingest = summary == kTotal ? t[kIngestRaycast] : t[kIngestEndpoints];
    return ingest + t[kStructure] + queries + t[kDistance];
}

bool fcl_distance_scaled(const RunResult &run) {
    return run.plan.fcl_distance_queries < run.plan.distance_queries;
}

const TreeMemory &tree_of(const RunResult &run, int p) { return p == kFcl ? run.octomap_raycast : run.opx_raycast; }

std::string cell(const Spread &s) {
    char text[48];
    std::snprintf(text, sizeof text, "%s/%s", paper_tables::three_significant(s.median_ms).c_str(),
                  paper_tables::three_significant(s.worst_ms).c_str());
    return text;
}

void print_header(const RunResult &run) {
    const Checks &c = run.checks;
    std::printf("\n%s stream, %.0f cm: %d frame(s); %d collision configurations per frame (%.0f%% colliding), %d "
                "distance queries (%d collision-free)%s\n",
                run.stream.c_str(), run.plan.resolution * 100, run.plan.frames, run.configurations,
                100.0 * c.collided / std::max<long long>(1, c.collision_compared), run.plan.distance_queries,
                c.distance_free,
                fcl_distance_scaled(run) ? (" - FCL distance measured on " + std::to_string(run.plan.fcl_distance_queries) +
                                            " per frame, its distance stage SCALED to " +
                                            std::to_string(run.plan.distance_queries))
                                               .c_str()
                                         : "");
    std::printf("map after the last frame (heap it holds, measured): octoprox %llu occupied / %llu known cells, %.1f B "
                "per occupied, %.1f B per known cell; OctoMap %llu / %llu, %.1f / %.1f B (endpoints maps: octoprox "
                "%.1f, OctoMap %.1f B per known cell)\n",
                (unsigned long long)run.opx_raycast.occupied, (unsigned long long)run.opx_raycast.known,
                run.opx_raycast.per_occupied(), run.opx_raycast.per_known(),
                (unsigned long long)run.octomap_raycast.occupied, (unsigned long long)run.octomap_raycast.known,
                run.octomap_raycast.per_occupied(), run.octomap_raycast.per_known(), run.opx_endpoints.per_known(),
                run.octomap_endpoints.per_known());
}

const char *const kColumns[kSummaryCount] = {"ingest rc",  "ingest ep", "structure", "pose upd",
                                             "collide",    "distance",  "pose+coll", "TOTAL rc",
                                             "TOTAL ep"};
const int kOrder[kSummaryCount] = {kIngestRaycast, kIngestEndpoints, kStructure, kPoseUpdate, kCollision,
                                   kPoseAndCollision, kDistance, kTotal, kTotalEndpoints};

// The batch call's time per frame, and the frame's total with it in place
// of the single calls (ray-cast ingest, structure, batch, distances).
Spread spread_of(std::vector<double> values) {
    Spread s;
    s.median_ms = paper_tables::median(values);
    s.worst_ms = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
    return s;
}

Spread batch_spread(const RunResult &run, int p, bool total) {
    std::vector<double> values;
    for (size_t f = 0; f < run.batch_ms.size() && f < run.frames.size(); ++f) {
        const StageTimes &t = run.frames[f][p];
        values.push_back(run.batch_ms[f][p] +
                         (total ? t[kIngestRaycast] + t[kStructure] + t[kDistance] : 0.0));
    }
    return spread_of(values);
}

void print_batch(const RunResult &run) {
    if (run.batch_ms.empty()) return;
    std::printf("batch (opx_query_check_configurations, every core, forward kinematics included), ms median/worst:");
    for (int p : {kDirect, kAmortized})
        std::printf(" %s %s, frame total %s;", kPipelineNames[p], cell(batch_spread(run, p, false)).c_str(),
                    cell(batch_spread(run, p, true)).c_str());
    std::printf(" answers %s\n", run.checks.batch_mismatches == 0 ? "equal the single calls'" : "DIFFER");
}

}  // namespace

RunSpreads summarize(const RunResult &run) {
    RunSpreads spreads(kPipelineCount, std::vector<Spread>(kSummaryCount));
    for (int p = 0; p < kPipelineCount; ++p) {
        for (int s = 0; s < kSummaryCount; ++s) {
            std::vector<double> values;
            for (const auto &frame : run.frames) values.push_back(value_of(frame[p], s));
            spreads[p][s].median_ms = paper_tables::median(values);
            spreads[p][s].worst_ms = values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
        }
    }
    return spreads;
}

void print_run(const RunResult &run) {
    print_header(run);
    const RunSpreads spreads = summarize(run);
    std::printf("ms per frame, median/worst over the frames:\n%-20s", "pipeline");
    for (int s : kOrder) std::printf(" %15s", kColumns[s]);
    std::printf(" %9s\n", "heap MiB");
    for (int p = 0; p < kPipelineCount; ++p) {
        std::printf("%-20s", kPipelineNames[p]);
        for (int s : kOrder) std::printf(" %15s", cell(spreads[p][s]).c_str());
        std::printf(" %9.1f\n", run.heap_high[p] / kMiB);
    }
    for (int p : {kDirect, kAmortized}) {
        std::printf("%-20s", (std::string(p == kDirect ? "direct" : "amortized") + " / FCL").c_str());
        for (int s : kOrder) {
            const double fcl = spreads[kFcl][s].median_ms;
            std::printf(" %15s", fcl > 0 ? paper_tables::three_significant(spreads[p][s].median_ms / fcl).c_str() : "-");
        }
        std::printf("\n");
    }
    print_batch(run);
    const Checks &c = run.checks;
    std::printf("checks: collided flag %s in %lld configuration-frames; distances: direct vs amortized max gap %.1e "
                "m over %d; FCL octree vs direct: %d of %d differ by more than %.0e m (max %.1e m)%s\n",
                c.collision_mismatches == 0 ? "agrees (direct, amortized, FCL)" : "MISMATCHES",
                c.collision_compared, c.engines_distance_gap, c.distance_compared, c.fcl_distance_off,
                c.fcl_distance_compared, kDistanceTolerance, c.fcl_distance_gap,
                c.fcl_distance_off > 0 ? " (known FCL octree distance errors, fcl#639/#640, and libccd's tolerance)"
                                       : "");
    std::fflush(stdout);
}

namespace {

void write_spread(std::ostream &out, const char *key, const Spread &s) {
    out << "\"" << key << "\": {\"median_ms\": " << s.median_ms << ", \"worst_ms\": " << s.worst_ms << "}";
}

void write_tree(std::ostream &out, const char *key, const TreeMemory &t) {
    out << "\"" << key << "\": {\"occupied\": " << t.occupied << ", \"known\": " << t.known
        << ", \"bytes\": " << t.bytes << ", \"bytes_per_occupied\": " << t.per_occupied()
        << ", \"bytes_per_known\": " << t.per_known() << "}";
}

void write_pipeline(std::ostream &out, const RunResult &run, const RunSpreads &spreads, int p) {
    out << "      {\"pipeline\": \"" << kPipelineNames[p] << "\", ";
    for (int s = 0; s < kSummaryCount; ++s) {
        write_spread(out, s < kStageCount ? kStageKeys[s] : kSummaryKeys[s - kStageCount], spreads[p][s]);
        out << ", ";
    }
    if (p != kFcl && !run.batch_ms.empty()) {
        write_spread(out, "batch_collisions", batch_spread(run, p, false));
        out << ", ";
        write_spread(out, "total_batch", batch_spread(run, p, true));
        out << ", ";
    }
    out << "\"distance_scaled\": " << (p == kFcl && fcl_distance_scaled(run) ? "true" : "false")
        << ", \"heap_high_water_bytes\": " << run.heap_high[p] << ", ";
    write_tree(out, "tree", tree_of(run, p));
    out << ", ";
    write_tree(out, "endpoints_tree", p == kFcl ? run.octomap_endpoints : run.opx_endpoints);
    out << ", \"endpoints_heap_high_water_bytes\": "
        << (p == kFcl ? run.octomap_endpoints_heap_high : run.opx_endpoints_heap_high) << ", \"frames_ms\": [";
    for (size_t f = 0; f < run.frames.size(); ++f) {
        out << (f ? ", " : "") << "[";
        for (int s = 0; s < kStageCount; ++s) out << (s ? ", " : "") << run.frames[f][p][s];
        out << "]";
    }
    out << "]}";
}

void write_run(std::ostream &out, const RunResult &run) {
    const RunSpreads spreads = summarize(run);
    const Checks &c = run.checks;
    out << "    {\"stream\": \"" << run.stream << "\", \"resolution\": " << run.plan.resolution
        << ", \"frames\": " << run.plan.frames << ", \"collision_queries\": " << run.configurations
        << ", \"distance_queries\": " << run.plan.distance_queries
        << ", \"fcl_distance_queries_measured\": " << std::min(run.plan.fcl_distance_queries, run.plan.distance_queries)
        << ", \"colliding_fraction\": " << double(c.collided) / std::max<long long>(1, c.collision_compared)
        << ", \"distance_collision_free\": " << c.distance_free
        << ", \"collision_mismatches\": " << c.collision_mismatches << ", \"batch_mismatches\": " << c.batch_mismatches
        << ", \"engines_distance_gap_m\": " << c.engines_distance_gap << ", \"fcl_distance_gap_m\": " << c.fcl_distance_gap
        << ",\n     \"pipelines\": [\n";
    for (int p = 0; p < kPipelineCount; ++p) {
        write_pipeline(out, run, spreads, p);
        out << (p + 1 < kPipelineCount ? ",\n" : "\n");
    }
    out << "     ]}";
}

}  // namespace

bool write_report_json(const std::string &path, const std::vector<RunResult> &runs, const ReportContext &context) {
    std::ofstream out(path);
    if (!out) return false;
    out.precision(6);
    out << "{\"program\": \"opx-frame-bench\", \"cpu\": \"" << context.cpu << "\", \"quick\": "
        << (context.quick ? "true" : "false") << ", \"load_average_start\": \"" << context.load_start
        << "\", \"load_average_end\": \"" << context.load_end << "\", \"seconds\": " << context.seconds
        << ", \"peak_rss_mib\": " << context.peak_rss_mib << ", \"robot_heap_bytes_octoprox\": " << context.robot_heap_opx
        << ", \"robot_heap_bytes_fcl\": " << context.robot_heap_fcl << ", \"stage_order\": [";
    for (int s = 0; s < kStageCount; ++s) out << (s ? ", " : "") << "\"" << kStageKeys[s] << "\"";
    out << "],\n \"runs\": [\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        write_run(out, runs[i]);
        out << (i + 1 < runs.size() ? ",\n" : "\n");
    }
    out << " ]}\n";
    return static_cast<bool>(out);
}

}  // namespace frame_bench
