// opx-bench-extents: how much free space near surfaces each obstacle model
// keeps.  Tabletop and shelf scenes of known boxes and cylinders, their
// surfaces sampled every 5 mm into clouds and inserted into maps at 1 cm
// and 2 cm; a 7-joint arm at configurations near the surfaces (exact
// distance to the objects at most 5 cm, touching ones included).  For each
// map: how many configurations the exact shapes (FCL on the true objects)
// call free, how many of those the whole cells and the point extents keep
// free, the misses (exactly colliding but called free: shapes reaching
// between the samples), and the time of a check of all of them per
// model (opx_query_check_configurations, one thread).  Exits 1 when whole
// cells miss a collision (they have none; the point extents may).
//
// usage: opx-bench-extents [--quick] [--json FILE]
#include "extent_scenes.hpp"

#include "arm_urdf.hpp"
#include "fcl_distance.hpp"
#include "pr2_fcl.hpp"
#include "report.hpp"

#include <octoprox/octoprox.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace extents_bench;

constexpr double kSpacing = 0.005;      // surface samples, metres
constexpr double kNearSurface = 0.05;   // configurations within this of an object
constexpr int kJoints = batch_bench::kArmJoints;

using paper_tables::check_opx;

struct Configurations {
    std::vector<double> rows;    // kJoints per configuration
    std::vector<uint8_t> exact;  // 1: the arm touches an object
};

// Random joint vectors kept when the arm comes within kNearSurface of the
// scene's objects (FCL, exact shapes).
Configurations near_surface(opx_linkset *arm, paper_tables::FclRobot &fcl, FclScene &objects, size_t count,
                            uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> joint(-2.9, 2.9);
    Configurations out;
    std::vector<double> q(kJoints);
    while (out.exact.size() < count) {
        for (double &v : q) v = joint(rng);
        check_opx(opx_linkset_set_joint_positions(arm, q.data(), q.size(), nullptr), "set_joint_positions");
        fcl.set_link_poses(paper_tables::link_poses(arm));
        const double d = paper_tables::fcl_managers_distance(fcl.manager(), *objects.manager, 1e-6);
        if (d > kNearSurface) continue;
        out.rows.insert(out.rows.end(), q.begin(), q.end());
        out.exact.push_back(d <= 0.0 ? 1 : 0);
    }
    return out;
}

struct ModelResult {
    size_t free = 0;    // called free
    size_t kept = 0;    // called free and free exactly
    size_t misses = 0;  // called free, colliding exactly
    double us_per_configuration = 0.0;
};

// One check of every configuration under `geometry`: the answers, and
// the microseconds per configuration.
double check_all(opx_query *query, const opx_octree *tree, const opx_linkset *arm, const Configurations &set,
                 int32_t geometry, std::vector<uint8_t> &collided) {
    const size_t n = set.exact.size();
    collided.assign(n, 0);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.obstacle_geometry = geometry;
    const auto start = std::chrono::steady_clock::now();
    check_opx(opx_query_check_configurations(query, tree, arm, set.rows.data(), n, kJoints, 0, nullptr, 0, 0,
                                             &request, collided.data(), nullptr, n),
              "check_configurations");
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / double(n);
}

ModelResult tally(const Configurations &set, const std::vector<uint8_t> &collided, double us) {
    ModelResult out;
    for (size_t i = 0; i < set.exact.size(); ++i) {
        out.free += collided[i] == 0;
        out.kept += collided[i] == 0 && !set.exact[i];
        out.misses += collided[i] == 0 && set.exact[i];
    }
    out.us_per_configuration = us;
    return out;
}

// Both models, their rounds interleaved (a change of the machine's load
// hits them alike), the fastest round of each.
void check_models(opx_query *query, const opx_octree *tree, const opx_linkset *arm, const Configurations &set,
                  int rounds, ModelResult &cells, ModelResult &extents) {
    std::vector<uint8_t> by_cells, by_extents;
    double cells_us = 1e300, extents_us = 1e300;
    for (int r = 0; r < rounds; ++r) {
        cells_us = std::min(cells_us, check_all(query, tree, arm, set, OPX_OBSTACLE_CELLS, by_cells));
        extents_us = std::min(extents_us, check_all(query, tree, arm, set, OPX_OBSTACLE_POINT_EXTENTS, by_extents));
    }
    cells = tally(set, by_cells, cells_us);
    extents = tally(set, by_extents, extents_us);
}

struct Row {
    std::string scene;
    double resolution = 0.0;
    size_t configurations = 0, exact_free = 0, occupied = 0, with_extent = 0;
    ModelResult cells, extents;
};

opx_octree *map_of(const std::vector<double> &points, double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_octree *tree = nullptr;
    check_opx(opx_octree_create(&options, &tree), "octree_create");
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_ENDPOINTS;  // surfaces only: the free space is not the question here
    check_opx(
        opx_octree_insert_points(tree, points.data(), points.size() / 3, 0, OPX_SCALAR_FLOAT64, &insert, nullptr),
        "insert_points");
    return tree;
}

void print_row(const Row &r) {
    std::printf("%-10s %4.0f cm %6zu %6zu %7zu (%5.1f%%) %4zu %7.2f %7zu (%5.1f%%) %4zu %7.2f %5.2fx\n",
                r.scene.c_str(), r.resolution * 100, r.configurations, r.exact_free, r.cells.kept,
                100.0 * r.cells.kept / std::max<size_t>(1, r.exact_free), r.cells.misses, r.cells.us_per_configuration,
                r.extents.kept, 100.0 * r.extents.kept / std::max<size_t>(1, r.exact_free), r.extents.misses,
                r.extents.us_per_configuration, r.extents.us_per_configuration / r.cells.us_per_configuration);
}

void write_json(const char *path, const std::vector<Row> &rows, const std::string &cpu) {
    FILE *f = std::fopen(path, "w");
    if (f == nullptr) {
        std::fprintf(stderr, "opx-bench-extents: cannot write %s\n", path);
        std::exit(1);
    }
    std::fprintf(f, "{\n  \"cpu\": \"%s\",\n  \"spacing_m\": %g,\n  \"near_surface_m\": %g,\n  \"rows\": [\n", cpu.c_str(),
                 kSpacing, kNearSurface);
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        std::fprintf(f,
                     "    {\"scene\": \"%s\", \"resolution_m\": %g, \"configurations\": %zu, \"exact_free\": %zu, "
                     "\"occupied_leaves\": %zu, \"leaves_with_extent\": %zu,\n"
                     "     \"cells\": {\"free\": %zu, \"kept\": %zu, \"misses\": %zu, \"us_per_configuration\": %.3f},\n"
                     "     \"point_extents\": {\"free\": %zu, \"kept\": %zu, \"misses\": %zu, "
                     "\"us_per_configuration\": %.3f}}%s\n",
                     r.scene.c_str(), r.resolution, r.configurations, r.exact_free, r.occupied, r.with_extent,
                     r.cells.free, r.cells.kept, r.cells.misses, r.cells.us_per_configuration, r.extents.free,
                     r.extents.kept, r.extents.misses,
                     r.extents.us_per_configuration, i + 1 < rows.size() ? "," : "");
    }
    std::fprintf(f, "  ]\n}\n");
    std::fclose(f);
}

}  // namespace

static int run(int argc, char **argv) {
    bool quick = false;
    const char *json = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) quick = true;
        else if (std::strcmp(argv[i], "--json") == 0 && i + 1 < argc) json = argv[++i];
        else {
            std::fprintf(stderr, "usage: opx-bench-extents [--quick] [--json FILE]\n");
            return 2;
        }
    }
    const int variants = quick ? 1 : 5;
    const size_t per_scene = quick ? 100 : 1000;
    const int rounds = quick ? 1 : 5;
    const std::string cpu = paper_tables::cpu_name();
    opx_linkset *arm = nullptr;
    check_opx(opx_linkset_load_urdf_string(batch_bench::primitive_arm_urdf().c_str(), nullptr, &arm), "load arm");
    paper_tables::FclRobot fcl(arm);
    opx_query *query = nullptr;
    check_opx(opx_query_create(nullptr, &query), "query_create");
    std::printf("opx-bench-extents: %s; %d variants of each scene, %zu configurations each, surfaces every %g mm\n",
                cpu.c_str(), variants, per_scene, kSpacing * 1000);
    std::printf("%-10s %7s %6s %6s %17s %4s %7s %17s %4s %7s %6s\n", "scene", "res", "confs", "exact", "cells keep",
                "miss", "us/conf", "extents keep", "miss", "us/conf", "ratio");
    std::vector<Row> rows;
    for (const double resolution : {0.01, 0.02}) {
        for (int kind = 0; kind < 2; ++kind) {
            Row total;
            total.scene = kind == 0 ? "tabletop" : "shelf";
            total.resolution = resolution;
            for (int v = 0; v < variants; ++v) {
                const Scene scene = kind == 0 ? tabletop_scene(100 + v) : shelf_scene(200 + v);
                FclScene objects = fcl_scene(scene);
                const Configurations set = near_surface(arm, fcl, objects, per_scene, 300 + 17 * v + kind);
                opx_octree *tree = map_of(sample_surfaces(scene, kSpacing), resolution);
                opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
                check_opx(opx_octree_get_stats(tree, &stats), "get_stats");
                ModelResult cells, extents;
                check_models(query, tree, arm, set, rounds, cells, extents);
                total.configurations += set.exact.size();
                for (uint8_t e : set.exact) total.exact_free += e == 0;
                total.occupied += stats.leaves_occupied, total.with_extent += stats.leaves_with_extent;
                total.cells.free += cells.free, total.cells.kept += cells.kept, total.cells.misses += cells.misses;
                total.extents.free += extents.free, total.extents.kept += extents.kept;
                total.extents.misses += extents.misses;
                total.cells.us_per_configuration += cells.us_per_configuration / variants;
                total.extents.us_per_configuration += extents.us_per_configuration / variants;
                opx_octree_destroy(tree);
            }
            print_row(total);
            rows.push_back(total);
            // Whole cells hold every sample's cell, and a link between two
            // samples 5 mm apart meets the cells around them: a miss there
            // is a bug (the point extents may miss, as documented).
            if (total.cells.misses != 0)
                throw std::runtime_error(total.scene + " at " + std::to_string(resolution) + " m: whole cells call " +
                                         std::to_string(total.cells.misses) + " exactly colliding configurations free");
        }
    }
    if (json) write_json(json, rows, cpu);
    opx_query_destroy(query);
    opx_linkset_destroy(arm);
    return 0;
}

int main(int argc, char **argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception &error) {
        std::fprintf(stderr, "opx-bench-extents: %s\n", error.what());
        return 1;
    }
}
