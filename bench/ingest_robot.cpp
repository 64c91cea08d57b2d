#include "ingest_robot.hpp"

#include "render_pr2.hpp"

#include <octoprox/octoprox.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace bench {
namespace {

constexpr double kRobotPadding = 0.02;  // metres beyond each link's own padding
constexpr int kArmPose = 2;             // both arms low over the table (render_pr2.hpp)

struct Insert {
    double ms = 0.0;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
};

// One insert of the composite frame into a fresh map.
Insert insert_once(const render::Pr2Scene &scene, double resolution, uint32_t threads, bool filtered) {
    opx_octree_options tree_options = OPX_OCTREE_OPTIONS_INIT;
    tree_options.resolution = resolution;
    opx_octree *tree = nullptr;
    if (opx_octree_create(&tree_options, &tree) != OPX_OK) throw std::runtime_error(opx_last_error());
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    image.scalar_type = OPX_SCALAR_FLOAT32;
    image.data = scene.composite.data();
    image.width = scene.camera.width;
    image.height = scene.camera.height;
    opx_camera_intrinsics k = OPX_CAMERA_INTRINSICS_INIT;
    k.fx = scene.camera.fx, k.fy = scene.camera.fy, k.cx = scene.camera.cx, k.cy = scene.camera.cy;
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.sensor_pose = scene.camera.pose;
    options.max_threads = threads;
    if (filtered) {
        options.robot = scene.robot;
        options.robot_padding = kRobotPadding;
    }
    Insert out;
    const auto start = std::chrono::steady_clock::now();
    const opx_status status = opx_octree_insert_depth_image(tree, &image, &k, &options, &out.report);
    out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    opx_octree_destroy(tree);
    if (status != OPX_OK) throw std::runtime_error(opx_last_error());
    return out;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

struct Row {
    double resolution;
    uint32_t threads;
    bool filtered;
    double median_ms;
    double filter_ms;  // filtered rows: their median minus the unfiltered one's
    opx_insert_report report;
};

// What the rows measure must be what the library promises: every pixel
// counted once, the robot seen in the frame, and the unfiltered insert
// using the points the filtered one takes away.  Throws otherwise.
void require_sound_reports(const opx_insert_report &plain, const opx_insert_report &filtered, size_t pixels) {
    const auto counted = [](const opx_insert_report &r) {
        return r.points_used + r.points_nonfinite + r.points_out_of_range + r.points_outside_map +
               r.points_on_robot + r.points_shadowed + r.pixels_no_return;
    };
    if (counted(plain) != pixels || counted(filtered) != pixels)
        throw std::runtime_error("an insert's report does not count every pixel once");
    if (filtered.points_on_robot == 0)
        throw std::runtime_error("the filtered insert found no robot point: the arms are not in the frame");
    if (plain.points_used != filtered.points_used + filtered.points_on_robot + filtered.points_shadowed)
        throw std::runtime_error("the filtered insert's robot and shadowed points are not the unfiltered one's extra points");
}

// The two pipelines of one resolution and thread count, alternating.
void run_pair(const render::Pr2Scene &scene, double resolution, uint32_t threads, int reps, std::vector<Row> &rows) {
    std::vector<double> plain_ms, filtered_ms;
    Insert plain, filtered;
    for (int rep = 0; rep < reps; ++rep)
        for (const bool filter : {rep % 2 == 0, rep % 2 != 0}) {
            const Insert run = insert_once(scene, resolution, threads, filter);
            (filter ? filtered_ms : plain_ms).push_back(run.ms);
            (filter ? filtered : plain) = run;
        }
    require_sound_reports(plain.report, filtered.report, scene.composite.size());
    const double plain_median = median(plain_ms), filtered_median = median(filtered_ms);
    rows.push_back(Row{resolution, threads, false, plain_median, 0.0, plain.report});
    rows.push_back(Row{resolution, threads, true, filtered_median, filtered_median - plain_median, filtered.report});
}

void print_rows(const std::vector<Row> &rows) {
    std::printf("\n%-6s %-7s %-24s %10s %10s %10s %10s %10s %9s\n", "res", "threads", "pipeline", "ms/frame",
                "filter ms", "used", "on robot", "shadowed", "ratio");
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        char ratio[32] = "";
        if (r.filtered) std::snprintf(ratio, sizeof ratio, "%.2fx", r.median_ms / rows[i - 1].median_ms);
        std::printf("%-6.2f %-7u %-24s %10.2f %10s %10llu %10llu %10llu %9s\n", r.resolution, r.threads,
                    r.filtered ? "octoprox self-filtered" : "octoprox", r.median_ms,
                    r.filtered ? std::to_string(r.filter_ms).substr(0, 7).c_str() : "",
                    (unsigned long long)r.report.points_used, (unsigned long long)r.report.points_on_robot,
                    (unsigned long long)r.report.points_shadowed, ratio);
    }
}

void write_json(const std::string &path, const std::vector<Row> &rows, const RobotRunOptions &options,
                const ThreadSpeed &at_start, const ThreadSpeed &at_end, size_t pixels) {
    std::FILE *out = std::fopen(path.c_str(), "w");
    if (out == nullptr) throw std::runtime_error("cannot write " + path);
    const std::string speeds = thread_speed_json_fields(at_start, at_end);
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        char filter_ms[32] = "null";
        if (r.filtered) std::snprintf(filter_ms, sizeof filter_ms, "%.3f", r.filter_ms);
        std::fprintf(out,
                     "  {\"resolution\": %g, \"mode\": \"depth image\", \"frame\": \"real + PR2 arms\", "
                     "\"pipeline\": \"%s\", \"threads\": %u, \"median_ms\": %.3f, \"filter_ms\": %s, "
                     "\"robot_padding\": %g, \"pixels\": %zu, \"points_used\": %llu, \"points_on_robot\": %llu, "
                     "\"points_shadowed\": %llu, \"reps\": %d, \"cpu\": \"%s\", %s}%s\n",
                     r.resolution, r.filtered ? "octoprox self-filtered" : "octoprox", r.threads, r.median_ms,
                     filter_ms, kRobotPadding, pixels, (unsigned long long)r.report.points_used,
                     (unsigned long long)r.report.points_on_robot, (unsigned long long)r.report.points_shadowed,
                     options.reps, options.cpu.c_str(), speeds.c_str(), i + 1 < rows.size() ? "," : "");
    }
    std::fprintf(out, "]\n");
    std::fclose(out);
}

}  // namespace

int run_robot_rows(const RobotRunOptions &options) {
    const std::string missing = render::missing_pr2_data(options.data_dir);
    if (!missing.empty()) {
        std::printf("opx-bench-ingest --robot: skipped: %s not found (set OPX_DATA_DIR to the shared data folder)\n",
                    missing.c_str());
        return 77;
    }
    render::Pr2Scene scene = render::make_pr2_scene(options.data_dir, kArmPose);
    const int reps = options.quick ? 1 : options.reps;
    std::printf("OctoProx %s ingest with self-filtering: the real frame with the PR2's arms rendered in (arm pose %d), "
                "%zux%zu depth image, robot_padding %g m, %d repetition(s) a row, fresh map each\n",
                opx_version(), kArmPose, scene.camera.width, scene.camera.height, kRobotPadding, reps);
    const ThreadSpeed at_start = measure_thread_speed();
    std::vector<Row> rows;
    for (const double resolution : {0.05, 0.02}) {
        if (options.quick && resolution < 0.05) continue;
        for (const uint32_t threads : {1u, 2u}) run_pair(scene, resolution, threads, reps, rows);
    }
    const ThreadSpeed at_end = measure_thread_speed();
    print_rows(rows);
    if (!options.json_path.empty()) {
        write_json(options.json_path, rows, options, at_start, at_end, scene.composite.size());
        std::printf("\nrows written to %s\n", options.json_path.c_str());
    }
    std::printf("\ncpu: %s\n", options.cpu.c_str());
    print_thread_speeds(at_start, at_end);
    render::destroy(scene);
    return 0;
}

}  // namespace bench
