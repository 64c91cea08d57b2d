// opx-bench-map-edit: what the map edits cost beside a frame's ingest, on
// the map of the real frame (the generated room without the shared data):
// a later frame's insert, decay, a crop to a window, clearing a box and an
// object's shapes.  Each repetition times every operation in turn
// (interleaved), each on a fresh copy of the same map; medians reported.
//
//   opx-bench-map-edit [--reps N] [--res M] [--quick] [--data DIR] [--json FILE]
#include "bench_frame.hpp"
#include "machine_probe.hpp"

#include <octoprox/octoprox.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Args {
    int reps = 9;
    double resolution = 0.02;
    std::string data_dir;
    std::string json_path;
};

Args parse_args(int argc, char **argv) {
    Args args;
    const char *env = std::getenv("OPX_DATA_DIR");
    args.data_dir = env != nullptr && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--quick") args.reps = 1, args.resolution = 0.05;
        else if (a == "--reps" && has_value) args.reps = std::max(1, std::atoi(argv[++i]));
        else if (a == "--res" && has_value) args.resolution = std::atof(argv[++i]);
        else if (a == "--data" && has_value) args.data_dir = argv[++i];
        else if (a == "--json" && has_value) args.json_path = argv[++i];
        else {
            std::fprintf(stderr, "usage: %s [--reps N] [--res M] [--quick] [--data DIR] [--json FILE]\n", argv[0]);
            std::exit(a == "--help" ? 0 : 2);
        }
    }
    return args;
}

void require(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

std::string cpu_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find_first_not_of(" \t", line.find(':') + 1));
    return "unknown";
}

struct Operation {
    const char *name;
    std::function<void(opx_octree *)> run;
    std::vector<double> ms;
    double median() const {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        return sorted[sorted.size() / 2];
    }
};

}  // namespace

int main(int argc, char **argv) {
    const Args args = parse_args(argc, argv);
    try {
        const bench::Frame frame = bench::load_frame(args.data_dir, false);
        opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
        for (int axis = 0; axis < 3; ++axis) insert.sensor_pose.position[axis] = frame.position[axis];
        for (int axis = 0; axis < 4; ++axis) insert.sensor_pose.orientation[axis] = frame.quaternion_xyzw[axis];
        opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
        options.resolution = args.resolution;
        opx_octree *map = nullptr;
        require(opx_octree_create(&options, &map), "create");
        require(opx_octree_insert_points(map, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
                "insert");
        size_t size = 0;
        opx_octree_save_memory(map, OPX_FORMAT_OPX, nullptr, 0, &size);
        std::vector<unsigned char> image(size);
        require(opx_octree_save_memory(map, OPX_FORMAT_OPX, image.data(), size, &size), "save");
        opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
        require(opx_octree_get_stats(map, &stats), "stats");
        // A window of the map's middle half on x and y, and a 1 m box and a
        // 0.3 m sphere at the centre of the known space.
        double lo[3], hi[3], mid[3];
        for (int axis = 0; axis < 3; ++axis) {
            const double span = stats.known_max[axis] - stats.known_min[axis];
            mid[axis] = stats.known_min[axis] + 0.5 * span;
            lo[axis] = axis < 2 ? stats.known_min[axis] + 0.25 * span : -1e9;
            hi[axis] = axis < 2 ? stats.known_max[axis] - 0.25 * span : 1e9;
        }
        const double box_lo[3] = {mid[0] - 0.5, mid[1] - 0.5, mid[2] - 0.5};
        const double box_hi[3] = {mid[0] + 0.5, mid[1] + 0.5, mid[2] + 0.5};
        opx_shape sphere = OPX_SHAPE_INIT;
        sphere.kind = OPX_SHAPE_SPHERE;
        sphere.radius = 0.3;
        opx_pose at_mid = OPX_POSE_IDENTITY;
        for (int axis = 0; axis < 3; ++axis) at_mid.position[axis] = mid[axis];
        std::vector<Operation> ops = {
            {"insert a later frame", [&](opx_octree *t) {
                 require(opx_octree_insert_points(t, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert,
                                                  nullptr), "insert");
             }, {}},
            {"decay 0.1", [&](opx_octree *t) { require(opx_octree_decay(t, 0.1), "decay"); }, {}},
            {"crop to the middle half (x, y)", [&](opx_octree *t) { require(opx_octree_crop(t, lo, hi), "crop"); }, {}},
            {"clear_region 1 m box to unknown",
             [&](opx_octree *t) { require(opx_octree_clear_region(t, box_lo, box_hi, OPX_CELL_UNKNOWN), "clear"); }, {}},
            {"clear_region 1 m box to free",
             [&](opx_octree *t) { require(opx_octree_clear_region(t, box_lo, box_hi, OPX_CELL_FREE), "clear"); }, {}},
            {"clear_shapes 0.3 m sphere to unknown",
             [&](opx_octree *t) { require(opx_octree_clear_shapes(t, &sphere, 1, &at_mid, OPX_CELL_UNKNOWN), "shapes"); }, {}},
        };
        for (int rep = 0; rep < args.reps; ++rep)
            for (Operation &op : ops) {
                opx_octree *copy = nullptr;
                require(opx_octree_load_memory(image.data(), image.size(), &options, &copy), "load");
                const auto start = std::chrono::steady_clock::now();
                op.run(copy);
                op.ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
                opx_octree_destroy(copy);
            }
        const std::string cpu = cpu_name();
        std::printf("OctoProx %s map edits at %g m: %s\n  map: %llu leaves, %.1f MiB; %d repetitions, medians\n",
                    opx_version(), args.resolution, frame.source.c_str(),
                    (unsigned long long)(stats.leaves_free + stats.leaves_occupied + stats.leaves_uncertain),
                    stats.memory_bytes / 1048576.0, args.reps);
        const double insert_ms = ops[0].median();
        std::FILE *json = args.json_path.empty() ? nullptr : std::fopen(args.json_path.c_str(), "w");
        if (json) std::fprintf(json, "[\n");
        for (size_t i = 0; i < ops.size(); ++i) {
            std::printf("  %-40s %9.3f ms  %6.1f%% of the insert\n", ops[i].name, ops[i].median(),
                        100.0 * ops[i].median() / insert_ms);
            if (json)
                std::fprintf(json, "  {\"operation\": \"%s\", \"resolution\": %g, \"median_ms\": %.4f, "
                                   "\"fraction_of_insert\": %.4f, \"reps\": %d, \"map_bytes\": %llu, \"cpu\": \"%s\"}%s\n",
                             ops[i].name, args.resolution, ops[i].median(), ops[i].median() / insert_ms, args.reps,
                             (unsigned long long)stats.memory_bytes, cpu.c_str(), i + 1 < ops.size() ? "," : "");
        }
        if (json) std::fprintf(json, "]\n"), std::fclose(json);
        std::printf("cpu: %s\n", cpu.c_str());
        opx_octree_destroy(map);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "opx-bench-map-edit: %s\n", e.what());
        return 1;
    }
    return 0;
}
