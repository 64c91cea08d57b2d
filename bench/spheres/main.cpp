// opx-bench-spheres: signed sphere distances for trajectory optimizers on
// the real RGB-D frame at 2 cm.  Rows, one thread, spheres of 2-8 cm
// uniform in the box of the occupied cells, a 10 cm activation distance:
//  - opx_query_distance_spheres: ns a sphere with gradient and witness
//    (one call of all spheres, median of rounds), and the first call of a
//    50-sphere arm after a new frame (the map's obstacle grid built);
//  - FCL's sphere-to-octree distance (fcl::distance of an fcl::Sphere and
//    the fcl::OcTree of the same cells; unsigned, no gradient);
//  - the grid pipeline: an exact EDT of the same cells over their box
//    (build ms) and trilinear lookups of distance and gradient (ns);
//  - opx_query_trajectory_cost of 32 waypoints of opx-bench-batch's
//    50-sphere 7-joint arm based in the middle of the occupied box (us).
// Rows and timings are interleaved round by round; --json FILE writes them.
//   opx-bench-spheres [--quick] [--json FILE] [--spheres N]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <octoprox/octoprox.h>

#include "arm_urdf.hpp"
#include "bench_frame.hpp"
#include "edt_reference.hpp"
#include "fcl_distance.hpp"
#include "fcl_pipelines.hpp"
#include "machine_probe.hpp"
#include "opx_pipelines.hpp"
#include "pr2_scene.hpp"
#include "report.hpp"
#include "rng.hpp"
#include "scene.hpp"
#include "timing.hpp"

using paper_tables::check_opx;

namespace {

constexpr double kResolution = 0.02, kActivation = 0.1;
constexpr double kMinRadius = 0.02, kMaxRadius = 0.08;

struct Row {
    std::string pipeline;
    double ns_per_sphere = NAN, ms = NAN;
    size_t spheres = 0;
};

paper_tables::OpxOctreePtr frame_map(const bench::Frame &frame) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = kResolution;
    opx_octree *raw = nullptr;
    check_opx(opx_octree_create(&options, &raw), "opx_octree_create");
    paper_tables::OpxOctreePtr tree(raw);
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_RAYCAST;
    insert.max_threads = 0;
    for (int i = 0; i < 3; ++i) insert.sensor_pose.position[i] = frame.position[i];
    for (int i = 0; i < 4; ++i) insert.sensor_pose.orientation[i] = frame.quaternion_xyzw[i];
    check_opx(opx_octree_insert_points(raw, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
              "opx_octree_insert_points");
    return tree;
}

std::vector<double> draw_spheres(const opx_octree_stats &stats, size_t count) {
    paper_tables::Rng rng(0x5D15u);
    std::vector<double> rows;
    for (size_t i = 0; i < count; ++i) {
        for (int a = 0; a < 3; ++a) rows.push_back(rng.uniform(stats.occupied_min[a], stats.occupied_max[a]));
        rows.push_back(rng.uniform(kMinRadius, kMaxRadius));
    }
    return rows;
}

// The occupied cells' centres, for the EDT.
std::vector<double> occupied_centres(const opx_octree *tree) {
    size_t count = 0;
    opx_octree_get_leaves(tree, OPX_MASK_OCCUPIED, nullptr, 0, &count);
    std::vector<opx_leaf> leaves(count);
    check_opx(opx_octree_get_leaves(tree, OPX_MASK_OCCUPIED, leaves.data(), count, &count), "opx_octree_get_leaves");
    std::vector<double> centres;
    for (const opx_leaf &leaf : leaves) {
        // A coarse leaf: each of its finest cells.
        const int n = int(std::lround(leaf.size / kResolution));
        for (int x = 0; x < n; ++x)
            for (int y = 0; y < n; ++y)
                for (int z = 0; z < n; ++z) {
                    const int at[3] = {x, y, z};
                    for (int a = 0; a < 3; ++a)
                        centres.push_back(leaf.center[a] - 0.5 * leaf.size + (at[a] + 0.5) * kResolution);
                }
    }
    return centres;
}

double opx_ns(opx_query *query, const opx_octree *tree, const std::vector<double> &rows, std::vector<double> &d,
              std::vector<double> &g, std::vector<double> &w) {
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    request.max_distance = kActivation;
    const size_t n = rows.size() / 4;
    const double ms = paper_tables::time_once_ms([&] {
        check_opx(opx_query_distance_spheres(query, tree, rows.data(), n, 0, &request, d.data(), g.data(), w.data(), n),
                  "opx_query_distance_spheres");
    });
    return 1e6 * ms / double(n);
}

double first_call_us(const opx_octree *tree, const std::vector<double> &rows) {
    const paper_tables::OpxOctreePtr copy = paper_tables::copy_octree(tree);
    const paper_tables::OpxQueryPtr query = paper_tables::make_direct_query();
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    request.max_distance = kActivation;
    double d[50], g[150];
    return 1e3 * paper_tables::time_once_ms([&] {
        check_opx(opx_query_distance_spheres(query.get(), copy.get(), rows.data(), 50, 0, &request, d, g, nullptr, 50),
                  "opx_query_distance_spheres");
    });
}

// 32 waypoints from one random configuration to another, in model order.
std::vector<double> trajectory(uint64_t seed) {
    paper_tables::Rng rng(seed);
    double from[batch_bench::kArmJoints], to[batch_bench::kArmJoints];
    for (int j = 0; j < batch_bench::kArmJoints; ++j) from[j] = rng.uniform(-2.0, 2.0), to[j] = rng.uniform(-2.0, 2.0);
    std::vector<double> rows;
    for (int w = 0; w < 32; ++w)
        for (int j = 0; j < batch_bench::kArmJoints; ++j) rows.push_back(from[j] + (to[j] - from[j]) * w / 31.0);
    return rows;
}

void write_json(const std::string &path, const std::vector<Row> &rows, const bench::ThreadSpeed &start,
                const bench::ThreadSpeed &end) {
    FILE *out = std::fopen(path.c_str(), "w");
    if (out == nullptr) return;
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < rows.size(); ++i)
        std::fprintf(out,
                     "  {\"pipeline\": \"%s\", \"map\": \"real frame 2 cm\", \"spheres\": %zu, \"ns_per_sphere\": %s, "
                     "\"ms\": %s, \"cpu\": \"%s\", \"load_average\": \"%s\", %s}%s\n",
                     rows[i].pipeline.c_str(), rows[i].spheres,
                     std::isfinite(rows[i].ns_per_sphere) ? std::to_string(rows[i].ns_per_sphere).c_str() : "null",
                     std::isfinite(rows[i].ms) ? std::to_string(rows[i].ms).c_str() : "null",
                     paper_tables::cpu_name().c_str(), paper_tables::load_average().c_str(),
                     bench::thread_speed_json_fields(start, end).c_str(), i + 1 < rows.size() ? "," : "");
    std::fprintf(out, "]\n");
    std::fclose(out);
}

}  // namespace

int main(int argc, char **argv) {
    bool quick = false;
    std::string json;
    size_t count = 20000;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) quick = true;
        else if (!std::strcmp(argv[i], "--json") && i + 1 < argc) json = argv[++i];
        else if (!std::strcmp(argv[i], "--spheres") && i + 1 < argc) count = std::strtoul(argv[++i], nullptr, 10);
        else {
            std::fprintf(stderr, "usage: opx-bench-spheres [--quick] [--json FILE] [--spheres N]\n");
            return 2;
        }
    }
    if (quick) count = 500;
    const int rounds = quick ? 1 : 7;
    const char *env = std::getenv("OPX_DATA_DIR");
    const bench::Frame frame = bench::load_frame(env != nullptr && env[0] ? env : OPX_DEFAULT_DATA_DIR, false);
    const bench::ThreadSpeed at_start = bench::measure_thread_speed();
    std::printf("frame: %s; cpu: %s\n", frame.source.c_str(), paper_tables::cpu_name().c_str());
    const paper_tables::OpxOctreePtr tree = frame_map(frame);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(tree.get(), &stats), "opx_octree_get_stats");
    const std::vector<double> rows = draw_spheres(stats, count);
    const size_t n = rows.size() / 4;

    // The EDT's box: the occupied cells' and the activation distance plus
    // the largest radius around it, so every lookup lies inside.
    const std::vector<double> centres = occupied_centres(tree.get());
    double lo[3];
    size_t size[3];
    for (int a = 0; a < 3; ++a) {
        const double margin = kActivation + kMaxRadius + kResolution;
        lo[a] = stats.occupied_min[a] - margin;
        size[a] = size_t(std::ceil((stats.occupied_max[a] + margin - lo[a]) / kResolution));
    }
    const std::shared_ptr<octomap::OcTree> octomap = paper_tables::mirror_through_bt(tree.get(), kResolution);
    const paper_tables::FclObjectPtr fcl_octree = paper_tables::wrap_octree(octomap);
    const paper_tables::FclObjectPtr fcl_sphere = paper_tables::make_fcl_sphere(kMinRadius);
    const size_t fcl_count = std::min<size_t>(n, quick ? 50 : 1000);

    const paper_tables::OpxQueryPtr query = paper_tables::make_direct_query();
    std::vector<double> d(n), g(3 * n), w(3 * n), edt_d(n);
    std::vector<double> opx, first, fcl, edt_build, edt_lookup, trajectory_us;
    opx_linkset *arm_raw = nullptr;
    check_opx(opx_linkset_load_urdf_string(batch_bench::sphere_arm_urdf().c_str(), nullptr, &arm_raw),
              "opx_linkset_load_urdf_string");
    const paper_tables::OpxLinksetPtr arm(arm_raw);
    opx_pose arm_base = OPX_POSE_IDENTITY;
    for (int a = 0; a < 3; ++a) arm_base.position[a] = 0.5 * (stats.occupied_min[a] + stats.occupied_max[a]);
    std::vector<std::vector<double>> trajectories;
    for (uint64_t t = 0; t < 20; ++t) trajectories.push_back(trajectory(0x7A0u + t));
    opx_trajectory_cost_request cost_request = OPX_TRAJECTORY_COST_REQUEST_INIT;
    cost_request.activation = kActivation;
    std::vector<double> cost_gradient(32 * batch_bench::kArmJoints);
    double cost_sum = 0.0;
    for (int r = 0; r < rounds; ++r) {
        opx.push_back(opx_ns(query.get(), tree.get(), rows, d, g, w));
        first.push_back(first_call_us(tree.get(), rows));
        fcl.push_back(1e6 * paper_tables::time_once_ms([&] {
            for (size_t i = 0; i < fcl_count; ++i) {
                auto sphere = paper_tables::make_fcl_sphere(rows[4 * i + 3]);
                sphere->setTranslation(fcl::Vector3d(rows[4 * i], rows[4 * i + 1], rows[4 * i + 2]));
                sphere->computeAABB();
                paper_tables::fcl_pair_distance(*sphere, *fcl_octree);
            }
        }) / double(fcl_count));
        std::unique_ptr<spheres_bench::DistanceGrid> grid;
        edt_build.push_back(paper_tables::time_once_ms(
            [&] { grid = std::make_unique<spheres_bench::DistanceGrid>(lo, size, kResolution, centres); }));
        edt_lookup.push_back(1e6 * paper_tables::time_once_ms([&] {
            for (size_t i = 0; i < n; ++i) {
                double gradient[3];
                edt_d[i] = std::min(grid->lookup(&rows[4 * i], gradient) - rows[4 * i + 3], kActivation);
            }
        }) / double(n));
        trajectory_us.push_back(1e3 * paper_tables::time_once_ms([&] {
            cost_sum = 0.0;
            for (const std::vector<double> &rows_q : trajectories) {
                double cost = 0.0;
                check_opx(opx_query_trajectory_cost(query.get(), tree.get(), arm.get(), rows_q.data(), 32,
                                                    batch_bench::kArmJoints, 0, &arm_base, &cost_request, &cost,
                                                    cost_gradient.data(), 32),
                          "opx_query_trajectory_cost");
                cost_sum += cost;
            }
        }) / double(trajectories.size()));
    }
    (void)fcl_sphere;
    size_t inside = 0, truncated = 0;
    double edt_error = 0.0;
    for (size_t i = 0; i < n; ++i) {
        inside += d[i] < 0.0, truncated += d[i] == kActivation;
        if (d[i] > 0.0) edt_error = std::max(edt_error, std::fabs(edt_d[i] - d[i]));
    }
    const bench::ThreadSpeed at_end = bench::measure_thread_speed();
    std::vector<Row> table = {
        {"opx_query_distance_spheres (distance, gradient, witness)", paper_tables::median(opx), NAN, n},
        {"opx first call of 50 spheres after a new frame", NAN, paper_tables::median(first) / 1e3, 50},
        {"FCL fcl::distance sphere vs fcl::OcTree (unsigned, no gradient)", paper_tables::median(fcl), NAN, fcl_count},
        {"EDT reference: exact EDT of the frame's box (build)", NAN, paper_tables::median(edt_build), 0},
        {"EDT reference: trilinear distance + gradient lookups", paper_tables::median(edt_lookup), NAN, n},
        {"opx_query_trajectory_cost: 32 waypoints x 50 spheres, cost + gradient", NAN,
         paper_tables::median(trajectory_us) / 1e3, 32 * 50},
    };
    std::printf("%zu spheres of %g-%g m, activation %g m: %zu inside an obstacle (distance < 0), %zu truncated; "
                "EDT grid %zux%zux%zu, its largest error outside: %.3g m\n",
                n, kMinRadius, kMaxRadius, kActivation, inside, truncated, size[0], size[1], size[2], edt_error);
    std::printf("trajectories: mean cost %.4g\n", cost_sum / 20.0);
    for (const Row &row : table)
        std::printf("%-66s %10.1f ns/sphere %10.3f ms\n", row.pipeline.c_str(), row.ns_per_sphere, row.ms);
    bench::print_thread_speeds(at_start, at_end);
    if (!json.empty()) write_json(json, table, at_start, at_end);
    return 0;
}
