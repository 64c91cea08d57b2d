// The cost of uncertain and unknown space (opx_collision_request.compute_cost
// = 1) against the brute-force cost oracle (oracle_cost.hpp), and the
// contacts of the same requests against the collision oracle.  Maps are ray
// cast with free_threshold 0.4, so cells seen free once (one miss, p = 0.4
// exactly) or hit and missed are uncertain: random scattered frames, and
// enclosures (walls with holes: unknown space inside the observed bounds);
// also the empty map with an explicit region (the root cube clipped to it).
// Requests vary the threshold, unknown policy, unknown_probability,
// max_contacts, max_cost_boxes and the region (default: the observed bounds).
#include "oracle_engine.hpp"
#include "oracle_cost_check.hpp"
#include "oracle_enclosure.hpp"

#include <cmath>
#include <cstdio>

using namespace oracle;

namespace {

std::unique_ptr<Scene> raycast_scene(Rng &rng) {
    auto scene = std::make_unique<Scene>();
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = rng.uniform(0.1, 0.25);
    options.free_threshold = 0.4;
    if (opx_octree_create(&options, &scene->tree) != OPX_OK) std::exit(1);
    const Vec3 center = rng.point(Vec3::Constant(-3.0), Vec3::Constant(3.0));
    const Vec3 half = Vec3::Constant(rng.uniform(1.0, 1.5));
    scene->low = center - half, scene->high = center + half;
    std::vector<Vec3> points;
    for (int f = rng.integer(3, 7); f > 0; --f) {
        if (points.empty() || rng.chance(0.7)) {  // else repeat the last frame
            points.clear();
            for (int i = rng.integer(20, 150); i > 0; --i) points.push_back(rng.point(scene->low, scene->high));
        }
        const opx_pose sensor = random_pose(rng, scene->low - half * 0.5, scene->high + half * 0.5);
        insert_frame(scene->tree, points, sensor, rng.chance(0.8) ? OPX_INSERT_RAYCAST : OPX_INSERT_ENDPOINTS);
    }
    char label[96];
    std::snprintf(label, sizeof label, "ray-cast map res %.4f", options.resolution);
    scene->label = label;
    index_scene(*scene, true);
    return scene;
}

// The oracle's settings for a request.
CostSettings settings_of(const Scene &scene, const CostVariant &v) {
    CostSettings s;
    s.threshold_log_odds = float_logit(effective_threshold(v.threshold, scene.options));
    s.free_log_odds = float_logit(scene.options.free_threshold);
    s.unknown_occupied = v.unknown_policy == OPX_UNKNOWN_OCCUPIED;
    s.unknown_probability = v.unknown_probability;
    bool empty = false;
    const bool proper = v.region_set && (v.region.lo.array() < v.region.hi.array()).all();
    s.region = proper ? v.region : known_bounds(scene.leaves, empty);
    return s;
}

CostVariant random_variant(Rng &rng, const Scene &scene, bool first) {
    CostVariant v;
    v.threshold = random_threshold(rng, scene);
    v.unknown_probability = rng.chance(0.2) ? 0.5 : rng.uniform(0.0, 1.0);
    const uint32_t keeps[] = {0u, 1u, uint32_t(rng.integer(2, 20)), 100000u};
    v.max_cost_boxes = rng.chance(0.2) ? 16u : keeps[rng.integer(0, 3)];
    if (first) return v;  // default region, all contacts, unknown free
    v.unknown_policy = rng.chance(0.25) ? OPX_UNKNOWN_OCCUPIED : OPX_UNKNOWN_FREE;
    const uint32_t contacts[] = {0u, 1u, 3u};
    v.max_contacts = contacts[rng.integer(0, 2)];
    v.region_set = true;
    const Vec3 a = rng.point(scene.low - Vec3::Constant(0.5), scene.high + Vec3::Constant(0.5));
    const Vec3 b = rng.point(scene.low - Vec3::Constant(0.5), scene.high + Vec3::Constant(0.5));
    v.region = {a.cwiseMin(b), a.cwiseMax(b)};
    if (rng.chance(0.1)) v.region.hi.x() = v.region.lo.x();  // not a proper box: the default region
    return v;
}

// The oracle's own consistency: its box distances (oracle_boxes.hpp) on
// whole cells equal its cube distances (oracle_geometry.hpp).
void self_check(const std::vector<PlacedShape> &placed, const Scene &scene, CostChecker &checker) {
    std::vector<uint32_t> near;
    for (const PlacedShape &shape : placed) {
        scene.cells->candidates(shape.bounds_min, shape.bounds_max, near);
        for (size_t i = 0; i < near.size() && i < 4; ++i) {
            const Cell &cell = scene.cells->cells()[near[i]].cell;
            const double cube = std::max(0.0, shape_cell_distance(shape, cell, 1e300));
            const double box = shape_aligned_distance(shape, aligned_box_of(cell));
            if (std::abs(cube - box) > (shape.kind == OPX_SHAPE_CYLINDER ? 1e-7 : 1e-12) * (1.0 + cube))
                checker.fail("oracle self-check: " + std::string(kind_name(shape.kind)) + " box distance " +
                             std::to_string(box) + " vs cube distance " + std::to_string(cube));
        }
    }
}

void check_state(Rng &rng, const Scene &scene, const RobotSpec &robot, opx_linkset *links, opx_query *query,
                 CostChecker &checker, const std::string &label) {
    const std::vector<PlacedShape> placed = place_robot(robot);
    self_check(placed, scene, checker);
    for (bool first : {true, false}) {
        const CostVariant v = random_variant(rng, scene, first);
        const CostSettings settings = settings_of(scene, v);
        const CostAnswer cost = oracle_cost(robot, placed, *scene.cells, settings);
        const ObstacleRule rule(effective_threshold(v.threshold, scene.options), v.unknown_policy);
        const OracleAnswer contacts = oracle_collide(placed, *scene.cells, rule);
        CostCase c;
        c.robot = &robot, c.placed = &placed, c.cells = scene.cells.get(), c.oracle = &cost, c.contacts = &contacts;
        c.settings = &settings;
        c.resolution = scene.options.resolution, c.label = label;
        checker.check(query, scene.tree, links, c, v);
    }
}

void run_campaign(Rng &rng, const Scene &scene, const Campaign &campaign, opx_query *query, CostChecker &checker) {
    for (int r = 0; r < campaign.robots; ++r) {
        RobotSpec robot = random_robot(rng, campaign.robot);
        opx_linkset *links = build_linkset(robot);
        for (int s = 0; s < campaign.states; ++s) {
            randomize_state(rng, robot, campaign.robot, campaign.low, campaign.high);
            update_linkset(links, robot, unsigned(s));
            check_state(rng, scene, robot, links, query, checker,
                        scene.label + " robot " + std::to_string(r) + " state " + std::to_string(s));
        }
        opx_linkset_destroy(links);
    }
}

Campaign small_links(const Scene &scene, int states) {
    Campaign campaign;
    campaign.robot.max_links = 4, campaign.robot.max_scale = 0.6, campaign.robot.max_padding = 0.1;
    campaign.robots = 2, campaign.states = states;
    campaign.low = scene.low - Vec3::Constant(0.3), campaign.high = scene.high + Vec3::Constant(0.3);
    return campaign;
}

// The observed bounds from the leaves against the library's statistics.
void check_known_bounds(const Scene &scene, CostChecker &checker) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    bool empty = false;
    const AlignedBox bounds = known_bounds(scene.leaves, empty);
    if (opx_octree_get_stats(scene.tree, &stats) != OPX_OK) return checker.fail("opx_octree_get_stats failed");
    for (int k = 0; k < 3 && !empty; ++k)
        if (stats.known_min[k] != bounds.lo[k] || stats.known_max[k] != bounds.hi[k])
            return checker.fail(scene.label + ": known bounds differ from the leaves' bounds");
}

}  // namespace

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 4242);
    const int scenes = int(env_number("OPX_ORACLE_SCENES", 24));
    std::printf("oracle_cost: seed %llu, %d ray-cast maps, %d enclosures\n", (unsigned long long)seed, scenes,
                scenes / 2);
    Rng rng(seed);
    CostChecker checker("oracle_cost");
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    for (int i = 0; i < scenes; ++i) {
        std::unique_ptr<Scene> scene = raycast_scene(rng);
        scene->label = "map " + std::to_string(i) + " (" + scene->label + ")";
        check_known_bounds(*scene, checker);
        run_campaign(rng, *scene, small_links(*scene, 60), query, checker);
    }
    std::printf("ray-cast maps done: %llu queries, %.1f s\n", (unsigned long long)checker.queries(), elapsed_seconds());
    for (int i = 0; i < scenes / 2; ++i) {
        EnclosureOptions options;
        options.free_threshold = 0.4, options.min_holes = i % 3 ? 1 : 0, options.max_holes = i % 3 ? 4 : 0;
        std::unique_ptr<Scene> scene = enclosed_scene(rng, options);
        scene->label = "enclosure " + std::to_string(i) + " (" + scene->label + ")";
        check_known_bounds(*scene, checker);
        run_campaign(rng, *scene, small_links(*scene, 40), query, checker);
    }
    std::unique_ptr<Scene> empty = cells_scene(0.1, {}, true);
    empty->label = "empty map";
    empty->low = Vec3::Constant(-1.0), empty->high = Vec3::Constant(1.0);
    run_campaign(rng, *empty, small_links(*empty, 20), query, checker);
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}
