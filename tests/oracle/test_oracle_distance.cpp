// Distance queries (opx_query_distance) against the brute-force distance
// oracle: the minimum over every obstacle cell and enabled shape of the exact
// padded-shape-to-cell distance.  Single shapes of every kind near two cells
// (many, to catch rare kernel failures), random small maps with unknown space free,
// enclosed maps (fully or with holes) with unknown space occupied, the empty
// map, and hand-made cases: two identical obstacles at the same distance
// (either may be reported) and shapes touching a cell (distance 0).
// Each robot state is asked several requests: exact (per-link or not), with
// a cutoff, and with an allowed absolute or relative error.
#include "oracle_engine.hpp"
#include "oracle_distance_check.hpp"
#include "oracle_enclosure.hpp"

#include <cmath>
#include <cstdio>

using namespace oracle;

namespace {

struct World {
    const Scene *scene = nullptr;
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
    bool fixed_threshold = false;
};

// The requests asked on one state: exact, a cutoff around the answer, an
// allowed error (now and then with a cutoff too).
std::vector<DistanceVariant> variants(Rng &rng, double minimum) {
    std::vector<DistanceVariant> out(3);
    for (DistanceVariant &v : out) v.per_link = rng.chance(0.5);
    const double scale = std::isfinite(minimum) && minimum > 0.0 ? minimum : 0.5;
    out[1].cutoff = scale * rng.uniform(0.3, 1.7);
    if (rng.chance(0.5)) out[2].abs_err = rng.uniform(0.0, 0.2);
    else out[2].rel_err = rng.uniform(0.0, 0.5);
    if (rng.chance(0.3)) out[2].cutoff = scale * rng.uniform(0.5, 2.0);
    return out;
}

void check_state(Rng &rng, const World &w, const RobotSpec &robot, opx_linkset *links, opx_query *query,
                 DistanceChecker &checker, const std::string &label) {
    const Scene &scene = *w.scene;
    const std::vector<PlacedShape> placed = place_robot(robot);
    const double threshold = w.fixed_threshold ? 0.0 : random_threshold(rng, scene);
    const ObstacleRule rule(effective_threshold(threshold, scene.options), w.unknown_policy);
    const std::vector<const MapCell *> obstacles = obstacle_cells(*scene.cells, rule);
    const NearestAnswer answer = oracle_nearest(placed, robot.links.size(), obstacles);
    DistanceCase c;
    c.robot = &robot, c.placed = &placed, c.cells = scene.cells.get(), c.oracle = &answer, c.rule = &rule;
    c.resolution = scene.options.resolution;
    c.unknown_policy = w.unknown_policy;
    c.threshold = threshold;
    c.label = label;
    for (const DistanceVariant &v : variants(rng, answer.overall.distance)) checker.check(query, scene.tree, links, c, v);
}

void run_campaign(Rng &rng, const World &w, const Campaign &campaign, opx_query *query, DistanceChecker &checker) {
    for (int r = 0; r < campaign.robots; ++r) {
        RobotSpec robot = random_robot(rng, campaign.robot);
        randomize_state(rng, robot, campaign.robot, campaign.low, campaign.high);
        opx_linkset *links = build_linkset(robot);
        for (int s = 0; s < campaign.states; ++s) {
            randomize_state(rng, robot, campaign.robot, campaign.low, campaign.high);
            update_linkset(links, robot, unsigned(s));
            check_state(rng, w, robot, links, query, checker,
                        w.scene->label + " robot " + std::to_string(r) + " state " + std::to_string(s));
        }
        opx_linkset_destroy(links);
    }
}

void random_scenes(Rng &rng, int count, opx_query *query, DistanceChecker &checker) {
    for (int i = 0; i < count; ++i) {
        std::unique_ptr<Scene> scene = random_small_scene(rng, false);
        scene->label = "random " + std::to_string(i) + " (" + scene->label + ")";
        Campaign campaign;
        campaign.robot.max_links = rng.integer(1, 6);
        campaign.robot.max_scale = rng.uniform(0.2, 1.0);
        campaign.robots = 2, campaign.states = 80;
        campaign.low = scene->low - Vec3::Constant(1.0), campaign.high = scene->high + Vec3::Constant(1.0);
        run_campaign(rng, {scene.get(), OPX_UNKNOWN_FREE, false}, campaign, query, checker);
    }
}

// Many single shapes of every kind close to one or two cells: a rare kernel
// failure (e.g. a degenerate GJK simplex) shows up as a wrong distance.
void single_shapes(Rng &rng, int states, opx_query *query, DistanceChecker &checker) {
    const std::unique_ptr<Scene> scene = cells_scene(0.2, {Vec3(0.1, 0.1, 0.1), Vec3(0.5, 0.1, 0.3)}, false);
    scene->label = "two cells";
    Campaign campaign;
    campaign.robot.min_links = campaign.robot.max_links = 1;
    campaign.robot.max_shapes_per_link = 1;
    campaign.robot.disabled_fraction = 0.0;
    campaign.robots = states / 100, campaign.states = 100;
    campaign.low = Vec3::Constant(-0.8), campaign.high = Vec3::Constant(1.2);
    run_campaign(rng, {scene.get(), OPX_UNKNOWN_FREE, true}, campaign, query, checker);
}

// Unknown space occupied on random maps: links partly in unknown space.
void random_unknown_scenes(Rng &rng, int count, opx_query *query, DistanceChecker &checker) {
    for (int i = 0; i < count; ++i) {
        std::unique_ptr<Scene> scene = random_small_scene(rng, true);
        scene->label = "random, unknown occupied " + std::to_string(i) + " (" + scene->label + ")";
        Campaign campaign;
        campaign.robot.max_scale = 0.3, campaign.robot.max_padding = 0.05;
        campaign.robots = 2, campaign.states = 60;
        campaign.low = scene->low, campaign.high = scene->high;
        run_campaign(rng, {scene.get(), OPX_UNKNOWN_OCCUPIED, false}, campaign, query, checker);
    }
}

// Unknown space occupied: links inside enclosures, walls whole or with holes.
void enclosed_scenes(Rng &rng, int count, opx_query *query, DistanceChecker &checker) {
    for (int i = 0; i < count; ++i) {
        EnclosureOptions options;
        options.free_threshold = rng.chance(0.5) ? 0.4 : 0.5;
        options.max_holes = i % 2 ? 4 : 0;
        options.min_holes = i % 2 ? 1 : 0;
        std::unique_ptr<Scene> scene = enclosed_scene(rng, options);
        scene->label = "enclosure " + std::to_string(i) + " (" + scene->label + ")";
        Campaign campaign;
        campaign.robot.min_scale = 0.05, campaign.robot.max_scale = 0.5, campaign.robot.max_padding = 0.1;
        campaign.robots = 2, campaign.states = 150;
        campaign.low = scene->low, campaign.high = scene->high;
        run_campaign(rng, {scene.get(), OPX_UNKNOWN_OCCUPIED, false}, campaign, query, checker);
    }
}

// The empty map: nothing found with unknown space free (+inf, or the
// cutoff); the whole map cube touched with unknown space occupied.
void empty_map(Rng &rng, opx_query *query, DistanceChecker &checker) {
    std::unique_ptr<Scene> scene = cells_scene(rng.uniform(0.05, 0.25), {}, true);
    scene->label = "empty map";
    Campaign campaign;
    campaign.robots = 2, campaign.states = 30;
    campaign.low = Vec3::Constant(-3.0), campaign.high = Vec3::Constant(3.0);
    for (int32_t policy : {OPX_UNKNOWN_FREE, OPX_UNKNOWN_OCCUPIED})
        run_campaign(rng, {scene.get(), policy, true}, campaign, query, checker);
}

}  // namespace

void hand_made_cases(opx_query *query, DistanceChecker &checker);  // test_oracle_distance_cases.cpp

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 9001);
    const int scenes = int(env_number("OPX_ORACLE_SCENES", 40));
    std::printf("oracle_distance: seed %llu, %d random scenes, %d enclosures\n", (unsigned long long)seed, scenes,
                scenes / 4);
    Rng rng(seed);
    DistanceChecker checker("oracle_distance");
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    hand_made_cases(query, checker);
    std::printf("hand-made cases: %llu queries, %.1f s\n", (unsigned long long)checker.queries(), elapsed_seconds());
    empty_map(rng, query, checker);
    single_shapes(rng, int(env_number("OPX_ORACLE_SINGLE", 20000)), query, checker);
    std::printf("single shapes done: %llu queries, %.1f s\n", (unsigned long long)checker.queries(), elapsed_seconds());
    random_scenes(rng, scenes, query, checker);
    std::printf("random scenes done: %llu queries, %.1f s\n", (unsigned long long)checker.queries(), elapsed_seconds());
    random_unknown_scenes(rng, scenes / 10, query, checker);
    enclosed_scenes(rng, scenes / 4, query, checker);
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}
