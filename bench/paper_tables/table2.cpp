// Table II of the paper: collision queries, 300 objects against a
// 7,784-cell octree, in three pipelines:
//   FCL boxes + DynamicAABBTree  octree -> boxes (T_{1,1}) -> broad phase
//                                (T_{1,2}) -> manager vs manager (T_q)
//   FCL octree                   fcl::OcTree as one object (T_1 ~ 0)
//   octoprox direct              the octree as it is (T_1 = 0)
// Scenes: H (objects as drawn, some collide: a query stops at the first
// contact) and F (no object collides: a query traverses everything).
// Variants: (a) primitives, (b) triangle meshes.
#include <iostream>

#include "tables.hpp"
#include "timing.hpp"
#include "variant_setup.hpp"

namespace paper_tables {
namespace {

const char *const kBoxesPipeline = "FCL boxes + DynamicAABBTree";
const char *const kOctreePipeline = "FCL octree";
const char *const kOpxPipeline = "octoprox direct";

// Scene F was made collision-free with OctoProx; FCL should agree.
void warn_if_fcl_finds_collisions(const Scenes &scenes, const VariantSetup &setup) {
    const FclObjectSet objects = make_fcl_object_set(scenes.free, setup.variant);
    const size_t colliding = count_fcl_colliding_objects(objects, *setup.octree.octree);
    if (colliding == 0) return;
    std::cout << "WARNING: FCL finds " << colliding << " of " << objects.objects.size()
              << " objects of scene F colliding with the octree (variant " << variant_letter(setup.variant)
              << "); OctoProx finds none\n";
}

// The fields every row of one table shares.
struct Measurement {
    TableRow row;
    QueryTiming timing;
};

Measurement measurement(const RowContext &context, const char *pipeline, double t11_ms, double t12_ms,
                        const QueryTiming &timing) {
    Measurement m;
    m.row = scene_row("II", context, pipeline, t11_ms, t12_ms, timing.mean_ms);
    m.timing = timing;
    return m;
}

// The three pipelines on one scene.  The robot is built for the scene
// once, outside the timing, on both sides: FCL's objects manager, and
// OctoProx's link set (its first poses also build its tree's topology).
std::vector<Measurement> measure_scene(VariantSetup &setup, const Scenes &scenes,
                                       const std::vector<SceneObject> &objects, const RowContext &context) {
    const FclObjectSet robot = make_fcl_object_set(objects, setup.variant);
    const OpxLinksetPtr links = make_object_linkset(objects, setup.variant);
    const opx_octree *tree = scenes.maps.opx.get();
    const std::vector<QueryTiming> timings = time_queries_interleaved(
        context.queries, {[&] { return fcl_managers_collide(*robot.manager, *setup.boxes.manager); },
                          [&] { return fcl_octree_collides(*robot.manager, *setup.octree.octree); },
                          [&] { return opx_collides(setup.query.get(), tree, links.get()); }});
    return {measurement(context, kBoxesPipeline, setup.boxes.t11_ms, setup.boxes.t12_ms, timings[0]),
            measurement(context, kOctreePipeline, 0.0, setup.octree.t12_ms, timings[1]),
            measurement(context, kOpxPipeline, 0.0, 0.0, timings[2])};
}

const char *yes_no(bool value) { return value ? "yes" : "no"; }

// All pipelines must give one answer, every time; in scene F it is "no".
bool answers_agree(const std::vector<Measurement> &measurements, bool free_scene) {
    bool agree = true;
    for (const Measurement &m : measurements) {
        const bool wrong = m.timing.collided != measurements.front().timing.collided ||
                           (free_scene && m.timing.collided) || !m.timing.consistent;
        if (wrong) agree = false;
    }
    std::cout << (agree ? "collided:" : "MISMATCH: collided:");
    for (size_t i = 0; i < measurements.size(); ++i)
        std::cout << (i == 0 ? " " : "; ") << measurements[i].row.pipeline << ": "
                  << yes_no(measurements[i].timing.collided)
                  << (measurements[i].timing.consistent ? "" : " (answers varied between queries)");
    std::cout << (free_scene ? " (scene F: expected no)" : "") << "\n";
    return agree;
}

void print_ratios(const std::vector<Measurement> &measurements) {
    const double direct = measurements[2].row.tq_ms;
    for (size_t i = 0; i < 2; ++i) {
        const double fcl = measurements[i].row.tq_ms;
        std::cout << "octoprox T_q / " << measurements[i].row.pipeline << " T_q = "
                  << three_significant(fcl > 0.0 ? direct / fcl : 0.0) << "\n";
    }
}

std::string table_title(const RowContext &context, const BenchOptions &options) {
    const bool primitives = context.variant == Variant::kPrimitives;
    const bool free_scene = std::string(context.scene) == "F";
    return std::string("Table II(") + variant_letter(context.variant) + "), scene " + context.scene +
           (free_scene ? " (no object collides)" : " (objects as drawn)") + ": " +
           (primitives ? "objects and boxes as geometric primitives" : "objects and boxes as meshes") +
           "; ms; T_q mean of " + std::to_string(options.queries) +
           " queries (pipelines interleaved), T_{1,x} median of " +
           std::to_string(options.repetitions) + " builds";
}

int run_variant(const Scenes &scenes, Variant variant, const BenchOptions &options, const std::string &cpu,
                std::vector<TableRow> &rows) {
    VariantSetup setup = make_variant_setup(scenes, variant, options);
    warn_if_fcl_finds_collisions(scenes, setup);
    int status = 0;
    for (const char *scene : {"H", "F"}) {
        const RowContext context{scene, variant, options.queries, cpu};
        const bool free_scene = std::string(scene) == "F";
        const std::vector<Measurement> measurements =
            measure_scene(setup, scenes, free_scene ? scenes.free : scenes.hit, context);
        std::cout << "\n";
        std::vector<TableRow> table;
        for (const Measurement &m : measurements) table.push_back(m.row);
        print_table(std::cout, table_title(context, options), table);
        print_ratios(measurements);
        if (!answers_agree(measurements, free_scene)) status = 1;
        rows.insert(rows.end(), table.begin(), table.end());
    }
    return status;
}

}  // namespace

int run_table2(const BenchOptions &options, const std::string &cpu, std::vector<TableRow> &rows) {
    const Scenes scenes = make_scenes();
    int status = 0;
    for (Variant variant : {Variant::kPrimitives, Variant::kMeshes})
        status |= run_variant(scenes, variant, options, cpu, rows);
    return status;
}

}  // namespace paper_tables
