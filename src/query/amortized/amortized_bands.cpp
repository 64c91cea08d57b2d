// The amortized engine's bands: which cells of a frame it holds as boxes,
// when each tree is (re)built, and the cost pass over the uncertain cells
// and unknown cubes (paper IV.C).
#include "query/amortized/amortized_engine.hpp"

#include "narrowphase/narrow_phase.hpp"

#include <chrono>
#include <type_traits>
#include <utility>

namespace octoprox {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

void AmortizedEngine::bind(const SensorOctree &tree, float threshold_log_odds, bool point_extents) {
    const BandKey key{tree.identity(), tree.generation(), threshold_log_odds, threshold_log_odds, point_extents};
    if (!caller_boxes_ && obstacles_.key == key) return;
    // Nothing is bound until the new tree stands: a build that throws must
    // not leave a band that a later query on the old frame takes as bound.
    obstacles_.key = BandKey();
    caller_boxes_ = false;
    const auto start = Clock::now();
    CellBands bands;
    bands.threshold_log_odds = threshold_log_odds;
    bands.free_log_odds = threshold_log_odds;
    bands.point_extents = point_extents;
    extract_cell_boxes(tree, bands, obstacles_.cells, nullptr);
    extract_ms_ = ms_since(start);
    build_ms_ = build_tree(obstacles_);
    obstacles_.key = key;
}

// T_{1,1} is the copy of the caller's boxes here.
// Built aside and swapped in, so a bind that fails (out of memory) leaves
// the context with what it held before.
void AmortizedEngine::bind_boxes(std::vector<Aabb> boxes) {
    static_assert(std::is_nothrow_swappable_v<Band>, "the swap below must not fail half way");
    const auto start = Clock::now();
    Band band;
    band.cells.boxes = std::move(boxes);
    const double extract_ms = ms_since(start);
    const double build_ms = build_tree(band);
    std::swap(obstacles_, band);  // band.key: no octree has identity 0, the next octree query binds
    caller_boxes_ = true;
    extract_ms_ = extract_ms;
    build_ms_ = build_ms;
}

// Unknown cubes depend on the frame only, not on any threshold.
void AmortizedEngine::bind_unknown(const SensorOctree &tree) {
    const BandKey key{tree.identity(), tree.generation(), 0.0f, 0.0f};
    if (unknown_.key == key) return;
    unknown_.key = BandKey();  // unbound until built, as in bind
    extract_unknown_boxes(tree.view(), unknown_.cells);
    unknown_.unknown = true;
    build_tree(unknown_);
    unknown_.key = key;
}

void AmortizedEngine::bind_uncertain(const SensorOctree &tree, float threshold_log_odds, float free_log_odds) {
    const BandKey key{tree.identity(), tree.generation(), threshold_log_odds, free_log_odds};
    if (uncertain_.key == key) return;
    uncertain_.key = BandKey();  // unbound until built, as in bind
    CellBands bands;
    bands.threshold_log_odds = threshold_log_odds;
    bands.free_log_odds = free_log_odds;
    extract_uncertain_boxes(tree.view(), bands, uncertain_.cells);
    build_tree(uncertain_);
    uncertain_.key = key;
}

double AmortizedEngine::build_tree(Band &band) {
    const auto start = Clock::now();
    BoxTreeOptions options;
    options.morton_bits = options_.morton_bits;
    band.tree.build(band.cells.boxes, options);
    ++builds_;
    return ms_since(start);
}

EngineStats AmortizedEngine::stats() const {
    EngineStats stats;
    stats.boxes = obstacles_.cells.boxes.size();
    stats.builds = builds_;
    stats.refine_steps_done = obstacles_.tree.refine_steps_done();
    stats.sah_ratio = obstacles_.tree.empty() ? 1.0 : obstacles_.tree.sah_ratio();
    stats.extract_ms = extract_ms_, stats.build_ms = build_ms_;
    return stats;
}

// Over the uncertain cells and, unless unknown space is an obstacle
// (OPX_UNKNOWN_OCCUPIED: then no cost), the unknown cubes inside the
// region, with the cost rule of both engines (CostCollector::offer).
void AmortizedEngine::collect_cost(const LinkSet &links, const CollisionSettings &settings, uint64_t &narrow_tests) {
    cost_.clear();
    const bool unknown_cost = !settings.unknown_occupied;
    const Aabb &region = settings.region;
    for (const PlacedShape &shape : links.placed()) {
        if (shape.box.empty()) continue;
        uncertain_.tree.for_each_leaf_if(
            [&](const Aabb &box) { return box.overlaps(shape.box) && shape_may_touch(shape, box); },
            [&](int32_t item) {
                cost_.offer(shape, uncertain_.cells.keys[item], false, uncertain_.cells.log_odds[item],
                            uncertain_.cells.boxes[item], settings, narrow_tests);
            });
        if (!unknown_cost) continue;
        unknown_.tree.for_each_leaf_if(
            [&](const Aabb &box) {
                return box.overlaps(shape.box) && box.overlaps(region) && shape_may_touch(shape, box);
            },
            [&](int32_t item) {
                cost_.offer(shape, unknown_.cells.keys[item], true, 0.0f, unknown_.cells.boxes[item], settings,
                            narrow_tests);
            });
    }
    refine(uncertain_);
    if (unknown_cost) refine(unknown_);
}

}  // namespace octoprox
