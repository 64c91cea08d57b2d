#include "geb079_sphere.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "fcl_distance.hpp"
#include "opx_distance.hpp"
#include "rng.hpp"
#include "timing.hpp"
#include "variant_setup.hpp"

namespace paper_tables {
namespace {

constexpr double kSphereRadius = 0.05;  // m
constexpr int kQueryCount = 1000;
constexpr uint64_t kCentreSeed = 0x6EB079u;
constexpr double kTolerance = 1e-6;  // m
constexpr size_t kShownDisagreements = 5;
const char *const kMapFile = "maps/geb079.bt";

using Point = std::array<double, 3>;

std::string map_path() {
    const char *env = std::getenv("OPX_DATA_DIR");
    const std::string root = env != nullptr && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
    return root + "/" + kMapFile;
}

struct Box {
    Point center;
    double half;
};

// The occupied leaves of the OctoMap tree, centres from the keys in double.
std::vector<Box> occupied_boxes(const octomap::OcTree &tree) {
    std::vector<Box> boxes;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
        if (!tree.isNodeOccupied(*it)) continue;
        const octomap::OcTreeKey key = it.getKey();
        const unsigned depth = it.getDepth();
        boxes.push_back({{tree.keyToCoord(key[0], depth), tree.keyToCoord(key[1], depth),
                          tree.keyToCoord(key[2], depth)},
                         0.5 * it.getSize()});
    }
    return boxes;
}

// Brute force: the sphere's distance to the nearest box, 0 when touching.
double reference_distance(const std::vector<Box> &boxes, const Point &centre) {
    double nearest_squared = INFINITY;
    for (const Box &box : boxes) {
        double squared = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double outside = std::max(0.0, std::fabs(centre[i] - box.center[i]) - box.half);
            squared += outside * outside;
        }
        nearest_squared = std::min(nearest_squared, squared);
    }
    return std::max(0.0, std::sqrt(nearest_squared) - kSphereRadius);
}

std::vector<Point> draw_centres(const opx_octree_stats &stats, int count) {
    Rng rng(kCentreSeed);
    std::vector<Point> centres(count);
    for (Point &centre : centres)
        for (int i = 0; i < 3; ++i) centre[i] = rng.uniform(stats.occupied_min[i], stats.occupied_max[i]);
    return centres;
}

struct QueryLog {
    std::vector<double> opx_ms, fcl_ms, opx_m, fcl_m, reference_m;
};

// Per centre: octoprox (pose update + query), then FCL (setTranslation +
// fcl::distance(octree, sphere)), each timed on its own.
QueryLog run_queries(const opx_octree *tree, const fcl::CollisionObjectd &octree, const std::vector<Point> &centres) {
    const OpxQueryPtr query = make_direct_query();
    const OpxLinksetPtr links = make_sphere_linkset(kSphereRadius);
    const FclObjectPtr sphere = make_fcl_sphere(kSphereRadius);
    auto opx_at = [&](const Point &c) {
        move_single_link(links.get(), c);
        return opx_min_distance(query.get(), tree, links.get());
    };
    auto fcl_at = [&](const Point &c) {
        sphere->setTranslation(fcl::Vector3d(c[0], c[1], c[2]));
        return fcl_pair_distance(octree, *sphere);
    };
    opx_at(centres.front());  // warm-up, untimed
    fcl_at(centres.front());
    QueryLog log;
    for (const Point &c : centres) {
        double d = 0.0;
        log.opx_ms.push_back(time_once_ms([&] { d = opx_at(c); }));
        log.opx_m.push_back(d);
        log.fcl_ms.push_back(time_once_ms([&] { d = fcl_at(c); }));
        log.fcl_m.push_back(d);
    }
    return log;
}

double mean(const std::vector<double> &values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    return values.empty() ? 0.0 : sum / values.size();
}

size_t count_disagreements(const std::vector<double> &a, const std::vector<double> &b) {
    size_t count = 0;
    for (size_t i = 0; i < a.size(); ++i) count += std::fabs(a[i] - b[i]) > kTolerance;
    return count;
}

void print_disagreements(const QueryLog &log, const std::vector<Point> &centres) {
    size_t shown = 0;
    for (size_t i = 0; i < centres.size() && shown < kShownDisagreements; ++i) {
        if (std::fabs(log.opx_m[i] - log.fcl_m[i]) <= kTolerance &&
            std::fabs(log.opx_m[i] - log.reference_m[i]) <= kTolerance)
            continue;
        ++shown;
        std::printf("  query %zu, centre (%.6f, %.6f, %.6f): octoprox %.9f m, FCL octree %.9f m, brute force %.9f m\n",
                    i, centres[i][0], centres[i][1], centres[i][2], log.opx_m[i], log.fcl_m[i], log.reference_m[i]);
    }
}

TableRow sphere_row(const char *pipeline, double t12_ms, const std::vector<double> &times_ms,
                    const std::string &cpu) {
    TableRow row;
    row.table = "III";
    row.pipeline = pipeline;
    row.scene = "geb079 sphere";
    row.variant = "a";
    row.t12_ms = t12_ms;
    row.tq_ms = mean(times_ms);
    row.tq_median_ms = median(times_ms);
    row.queries = static_cast<int>(times_ms.size());
    row.cpu = cpu;
    row.totals_of_queries = {1};
    return row;
}

void print_timing(const TableRow &row) {
    std::cout << "  " << row.pipeline << ": mean " << three_significant(row.tq_ms) << " ms, median "
              << three_significant(*row.tq_median_ms) << " ms per query\n";
}

void print_heading(const std::string &path, const opx_octree_stats &stats) {
    std::printf("\ngeb079 sphere: %d single-sphere distance queries in %s (%llu occupied leaves, %.3f m): radius "
                "%.2f m, centres uniform in the occupied bounds [%.2f, %.2f] x [%.2f, %.2f] x [%.2f, %.2f] m, "
                "the same for both; octoprox's time includes the pose update (opx_linkset_set_poses), FCL's "
                "the sphere's setTranslation\n",
                kQueryCount, path.c_str(), static_cast<unsigned long long>(stats.leaves_occupied), stats.resolution,
                kSphereRadius, stats.occupied_min[0], stats.occupied_max[0], stats.occupied_min[1],
                stats.occupied_max[1], stats.occupied_min[2], stats.occupied_max[2]);
}

// Prints the disagreements; returns how many octoprox answers the brute
// force contradicts.
size_t check_distances(const QueryLog &log, const std::vector<Point> &centres, size_t leaf_count) {
    const size_t touching = std::count(log.reference_m.begin(), log.reference_m.end(), 0.0);
    const size_t opx_wrong = count_disagreements(log.opx_m, log.reference_m);
    std::cout << "  distances disagreeing by more than " << kTolerance << " m: octoprox vs FCL octree "
              << count_disagreements(log.opx_m, log.fcl_m) << " of " << centres.size()
              << "; against a brute force over " << leaf_count << " occupied leaves: octoprox " << opx_wrong
              << ", FCL octree " << count_disagreements(log.fcl_m, log.reference_m) << " (" << touching
              << " spheres touch a cell)\n";
    print_disagreements(log, centres);
    if (opx_wrong != 0) std::cout << "FAIL: octoprox disagrees with the brute force in " << opx_wrong << " queries\n";
    return opx_wrong;
}

}  // namespace

int run_geb079_sphere(const BenchOptions &options, const std::string &cpu, std::vector<TableRow> &rows) {
    const std::string path = map_path();
    if (!std::ifstream(path)) {
        std::cout << "\ngeb079 sphere: skipped: " << path << " not found (set OPX_DATA_DIR to the shared data folder)\n";
        return 0;
    }
    const OpxOctreePtr tree = load_opx_octree(path);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(tree.get(), &stats), "opx_octree_get_stats");
    const std::shared_ptr<octomap::OcTree> octomap_tree = read_octomap_binary(path);
    const OctreeMap octree = build_octree_map(octomap_tree, options.repetitions);
    const std::vector<Point> centres = draw_centres(stats, kQueryCount);
    QueryLog log = run_queries(tree.get(), *octree.octree, centres);
    const std::vector<Box> boxes = occupied_boxes(*octomap_tree);
    for (const Point &c : centres) log.reference_m.push_back(reference_distance(boxes, c));

    const TableRow opx_row = sphere_row("octoprox direct", 0.0, log.opx_ms, cpu);
    const TableRow fcl_row = sphere_row("FCL octree", octree.t12_ms, log.fcl_ms, cpu);
    print_heading(path, stats);
    print_timing(opx_row);
    print_timing(fcl_row);
    std::cout << "  octoprox / FCL octree: mean " << three_significant(opx_row.tq_ms / fcl_row.tq_ms) << ", median "
              << three_significant(*opx_row.tq_median_ms / *fcl_row.tq_median_ms) << "\n";
    const size_t opx_wrong = check_distances(log, centres, boxes.size());
    rows.push_back(opx_row);
    rows.push_back(fcl_row);
    return opx_wrong != 0 ? 1 : 0;
}

}  // namespace paper_tables
