#include "oracle_scenes.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <tuple>

namespace oracle {
namespace {

opx_octree *create_octree(double resolution, double free_threshold) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    options.free_threshold = free_threshold;
    opx_octree *tree = nullptr;
    require_ok(opx_octree_create(&options, &tree), "opx_octree_create");
    return tree;
}

std::vector<Vec3> random_points(Rng &rng, int count, const Vec3 &low, const Vec3 &high) {
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) points.push_back(rng.point(low, high));
    return points;
}

// Endpoints filling a solid block: its full octants are pruned into larger
// occupied leaves (depth < 16), larger contact cells.
void insert_solid_block(Rng &rng, Scene &scene, double resolution) {
    const Vec3 size(rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0));
    const Vec3 corner = rng.point(scene.low, scene.high - size);
    const double step = 0.5 * resolution;
    std::vector<Vec3> points;
    for (double x = 0; x <= size.x(); x += step)
        for (double y = 0; y <= size.y(); y += step)
            for (double z = 0; z <= size.z(); z += step) points.push_back(corner + Vec3(x, y, z));
    insert_frame(scene.tree, points, random_pose(rng, scene.low, scene.high), OPX_INSERT_ENDPOINTS);
}

}  // namespace

void index_scene(Scene &scene, bool with_unknown) {
    scene.options = octree_options(scene.tree);
    scene.leaves = known_leaves(scene.tree);
    if (!check_leaves(scene.leaves, scene.options)) {
        std::printf("FAIL: %s: the leaves' probabilities, classes or geometry do not follow from their "
                    "float log-odds and keys (see above)\n", scene.label.c_str());
        std::exit(1);
    }
    scene.cells = std::make_unique<CellIndex>(map_cells(scene.leaves, scene.options.resolution, with_unknown),
                                              4.0 * scene.options.resolution);
}

void insert_frame(opx_octree *tree, const std::vector<Vec3> &world_points, const opx_pose &sensor,
                  int32_t mode) {
    const Eigen::Isometry3d to_sensor = isometry_of(sensor).inverse();
    std::vector<Vec3> local;
    for (const Vec3 &p : world_points) local.push_back(to_sensor * p);
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = mode;
    options.sensor_pose = sensor;
    require_ok(opx_octree_insert_points(tree, local.data(), local.size(), 0, OPX_SCALAR_FLOAT64, &options, nullptr),
          "opx_octree_insert_points");
}

std::unique_ptr<Scene> random_small_scene(Rng &rng, bool with_unknown) {
    auto scene = std::make_unique<Scene>();
    const double resolution = rng.uniform(0.1, 0.25);
    scene->tree = create_octree(resolution, rng.chance(0.5) ? 0.4 : 0.5);
    const Vec3 center = rng.point(Vec3::Constant(-3.0), Vec3::Constant(3.0));
    const Vec3 half = Vec3::Constant(rng.uniform(1.0, 2.0));
    scene->low = center - half, scene->high = center + half;
    std::vector<std::vector<Vec3>> frames;
    const int frame_count = rng.integer(3, 8);
    for (int f = 0; f < frame_count; ++f) {
        // Repeat an earlier frame now and then: higher (and clamped) log-odds.
        const bool repeat = !frames.empty() && rng.chance(0.3);
        const std::vector<Vec3> points = repeat ? frames[rng.integer(0, int(frames.size()) - 1)]
                                                : random_points(rng, rng.integer(20, 200), scene->low, scene->high);
        frames.push_back(points);
        const int32_t mode = rng.chance(0.5) ? OPX_INSERT_RAYCAST : OPX_INSERT_ENDPOINTS;
        const opx_pose sensor = random_pose(rng, scene->low - half * 0.5, scene->high + half * 0.5);
        insert_frame(scene->tree, points, sensor, mode);
    }
    if (rng.chance(0.4)) insert_solid_block(rng, *scene, resolution);
    char label[128];
    std::snprintf(label, sizeof label, "small scene res %.4f", resolution);
    scene->label = label;
    index_scene(*scene, with_unknown);
    return scene;
}

std::unique_ptr<Scene> synthetic_scene(Rng &rng) {
    constexpr size_t kOccupiedLeaves = 7784;
    constexpr double kResolution = 0.2;
    auto scene = std::make_unique<Scene>();
    scene->tree = create_octree(kResolution, 0.5);
    scene->low = Vec3::Constant(-20.0), scene->high = Vec3::Constant(20.0);
    // One hit per new cell: draw points until 7,784 distinct cells (keys as
    // OctoMap computes them: floor(coordinate * (1 / resolution))).
    std::set<std::tuple<int64_t, int64_t, int64_t>> cells;
    std::vector<Vec3> points;
    while (cells.size() < kOccupiedLeaves) {
        const Vec3 p = rng.point(scene->low, scene->high);
        const double factor = 1.0 / kResolution;
        const auto key = std::make_tuple(int64_t(std::floor(p.x() * factor)), int64_t(std::floor(p.y() * factor)),
                                         int64_t(std::floor(p.z() * factor)));
        if (cells.insert(key).second) points.push_back(p);
    }
    insert_frame(scene->tree, points, opx_pose OPX_POSE_IDENTITY, OPX_INSERT_ENDPOINTS);
    scene->label = "synthetic scene";
    index_scene(*scene, false);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    require_ok(opx_octree_get_stats(scene->tree, &stats), "opx_octree_get_stats");
    if (stats.leaves_occupied != kOccupiedLeaves) {
        std::printf("FAIL: the synthetic scene has %llu occupied leaves, not %zu\n",
                    (unsigned long long)stats.leaves_occupied, kOccupiedLeaves);
        std::exit(1);
    }
    return scene;
}

double random_threshold(Rng &rng, const Scene &scene) {
    const double draw = rng.uniform(0.0, 1.0);
    if (draw < 0.3) return 0.0;
    if (draw < 0.45 && !scene.leaves.empty())
        return scene.leaves[rng.integer(0, int(scene.leaves.size()) - 1)].probability;
    return rng.uniform(0.3, 0.9);
}

void run_campaign(Rng &rng, const Scene &scene, const Campaign &campaign, opx_query *query, Checker &checker) {
    for (int r = 0; r < campaign.robots; ++r) {
        RobotSpec robot = random_robot(rng, campaign.robot);
        randomize_state(rng, robot, campaign.robot, campaign.low, campaign.high);
        opx_linkset *links = build_linkset(robot);
        for (int s = 0; s < campaign.states; ++s) {
            randomize_state(rng, robot, campaign.robot, campaign.low, campaign.high);
            update_linkset(links, robot, unsigned(s));
            const std::vector<PlacedShape> placed = place_robot(robot);
            QueryCase c;
            c.robot = &robot, c.placed = &placed, c.cells = scene.cells.get();
            c.resolution = scene.options.resolution;
            c.occupied_threshold = scene.options.occupied_threshold;
            c.unknown_policy = campaign.unknown_policy;
            c.threshold = campaign.fixed_threshold ? 0.0 : random_threshold(rng, scene);
            c.label = scene.label + " robot " + std::to_string(r) + " state " + std::to_string(s);
            checker.check(query, scene.tree, links, c);
        }
        opx_linkset_destroy(links);
    }
}

}  // namespace oracle
