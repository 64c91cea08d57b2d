#include "variant_setup.hpp"

#include <iostream>

#include "free_scene.hpp"
#include "timing.hpp"

namespace paper_tables {

Scenes make_scenes() {
    Scenes scenes;
    scenes.maps = build_occupancy_maps(scenes.parameters);
    Rng rng(scenes.parameters.object_seed);
    scenes.hit = draw_objects(scenes.parameters, rng);
    FreeSceneReport report;
    scenes.free = make_free_scene(scenes.hit, scenes.maps.opx.get(), scenes.parameters, report);
    std::cout << "Scene: " << scenes.parameters.occupied_cells << " occupied cells of "
              << scenes.parameters.resolution << " m in [-" << scenes.parameters.half_extent << ", "
              << scenes.parameters.half_extent << "]^3 m; " << scenes.hit.size() << " objects; "
              << report.redrawn_objects << " collide in scene H and were redrawn for scene F ("
              << report.redraws << " poses drawn)\n";
    return scenes;
}

BoxesMap build_boxes_map(const octomap::OcTree &tree, Variant variant, int repetitions) {
    std::vector<double> t11, t12;
    BoxesMap map;
    for (int i = 0; i < repetitions; ++i) {
        map.manager.reset();  // untimed teardown of the previous build
        map.boxes.clear();
        t11.push_back(time_once_ms([&] { map.boxes = boxes_from_octomap(tree, variant); }));
        t12.push_back(time_once_ms([&] { map.manager = manage_objects(map.boxes); }));
    }
    map.t11_ms = median(t11);
    map.t12_ms = median(t12);
    return map;
}

OctreeMap build_octree_map(const std::shared_ptr<const octomap::OcTree> &tree, int repetitions) {
    std::vector<double> t12;
    OctreeMap map;
    for (int i = 0; i < repetitions; ++i) {
        map.octree.reset();
        t12.push_back(time_once_ms([&] { map.octree = wrap_octree(tree); }));
    }
    map.t12_ms = median(t12);
    return map;
}

VariantSetup make_variant_setup(const Scenes &scenes, Variant variant, const BenchOptions &options) {
    VariantSetup setup;
    setup.variant = variant;
    setup.boxes = build_boxes_map(*scenes.maps.octomap, variant, options.repetitions);
    setup.octree = build_octree_map(scenes.maps.octomap, options.repetitions);
    setup.query = make_direct_query();
    return setup;
}

TableRow scene_row(const char *table, const RowContext &context, const char *pipeline, double t11_ms,
                   double t12_ms, double tq_ms) {
    TableRow row;
    row.table = table;
    row.pipeline = pipeline;
    row.scene = context.scene;
    row.variant = variant_letter(context.variant);
    row.t11_ms = t11_ms;
    row.t12_ms = t12_ms;
    row.tq_ms = tq_ms;
    row.queries = context.queries;
    row.cpu = context.cpu;
    return row;
}

}  // namespace paper_tables
