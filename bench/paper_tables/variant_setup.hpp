// What Tables II and III share: the synthetic scene (maps, scene H and
// scene F), and per variant the maps of the two FCL pipelines with their
// build times T_{1,1}, T_{1,2}, and OctoProx's query context.
#pragma once

#include <memory>
#include <vector>

#include "fcl_pipelines.hpp"
#include "opx_pipelines.hpp"
#include "options.hpp"
#include "report.hpp"
#include "scene.hpp"

namespace paper_tables {

struct Scenes {
    SceneParameters parameters;
    OccupancyMaps maps;
    std::vector<SceneObject> hit;   // scene H
    std::vector<SceneObject> free;  // scene F
};

// What every row of one scene and variant shares.
struct RowContext {
    const char *scene;
    Variant variant;
    int queries;
    const std::string &cpu;
};

// A table row (`table` "II", "III") of one pipeline on that scene.
TableRow scene_row(const char *table, const RowContext &context, const char *pipeline, double t11_ms,
                   double t12_ms, double tq_ms);

// Builds the maps and both scenes, and prints one line about them.
Scenes make_scenes();

// The map side of the boxes pipeline.  The manager points into the boxes.
struct BoxesMap {
    double t11_ms = 0.0;
    double t12_ms = 0.0;
    std::vector<FclObjectPtr> boxes;
    std::unique_ptr<FclManager> manager;
};

// Rebuilt from scratch `repetitions` times; the medians are kept, and the
// last build serves the queries.
BoxesMap build_boxes_map(const octomap::OcTree &tree, Variant variant, int repetitions);

struct OctreeMap {
    double t12_ms = 0.0;
    FclObjectPtr octree;
};

// The OctoMap tree wrapped as an fcl::OcTree `repetitions` times (median).
OctreeMap build_octree_map(const std::shared_ptr<const octomap::OcTree> &tree, int repetitions);

// What the scenes of one variant share: the maps of the two FCL
// pipelines, and OctoProx's query context.
struct VariantSetup {
    Variant variant = Variant::kPrimitives;
    BoxesMap boxes;
    OctreeMap octree;
    OpxQueryPtr query;
};

VariantSetup make_variant_setup(const Scenes &scenes, Variant variant, const BenchOptions &options);

}  // namespace paper_tables
