// Obstacles as their point extents (OPX_OBSTACLE_POINT_EXTENTS) against a
// brute force over the sensed points.  Random clouds (sampled surfaces and
// scattered points) go into fresh maps, as endpoints over a few frames or
// as one ray-cast frame; the oracle reads the occupied leaves, gives each
// leaf the tight box of the points that fell in it, and measures random
// robots of all six shape kinds against those boxes exactly.  Checked:
//   - conservative: a configuration whose padded shapes overlap a leaf's
//     tight point box collides, and the reported distance never exceeds
//     the distance to the tight boxes (so to the points);
//   - tight: the reported distance is at least the distance to the tight
//     boxes grown by one slot of the leaf (edge / 32); a configuration
//     clear of those grown boxes does not collide;
//   - both engines give the same collision answer and the same distance.
#include "oracle_boxes.hpp"
#include "oracle_check.hpp"
#include "oracle_random.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace oracle;

namespace {

struct LeafBox {
    AlignedBox tight;  // the points' bounding box
    double size = 0.0; // the leaf's edge
};

struct Cloud {
    std::vector<double> xyz;  // packed points, map frame
    void add(const Vec3 &p) { xyz.insert(xyz.end(), {p.x(), p.y(), p.z()}); }
    size_t count() const { return xyz.size() / 3; }
    Vec3 at(size_t i) const { return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); }
};

// Points on a random box's faces every `spacing`, and a few scattered ones.
void sample_scene(Rng &rng, double spacing, Cloud &cloud) {
    const int boxes = rng.integer(1, 3);
    for (int b = 0; b < boxes; ++b) {
        const Vec3 lo = rng.point(Vec3(-0.6, -0.6, -0.6), Vec3(0.2, 0.2, 0.2));
        const Vec3 hi = lo + rng.point(Vec3(0.05, 0.05, 0.05), Vec3(0.5, 0.5, 0.5));
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                for (double a = lo[u]; a <= hi[u]; a += spacing)
                    for (double c = lo[v]; c <= hi[v]; c += spacing) {
                        Vec3 p;
                        p[axis] = side ? hi[axis] : lo[axis];
                        p[u] = a, p[v] = c;
                        cloud.add(p);
                    }
            }
    }
    const int scattered = rng.integer(0, 60);
    for (int i = 0; i < scattered; ++i) cloud.add(rng.point(Vec3(-0.7, -0.7, -0.7), Vec3(0.7, 0.7, 0.7)));
}

// Points [begin, end) of the cloud, given in the frame of a sensor at
// `sensor` (no rotation).
bool insert(opx_octree *tree, const Cloud &cloud, size_t begin, size_t end, int32_t mode, const Vec3 &sensor) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = mode;
    options.sensor_pose.position[0] = sensor.x();
    options.sensor_pose.position[1] = sensor.y();
    options.sensor_pose.position[2] = sensor.z();
    std::vector<double> in_sensor(cloud.xyz.begin() + 3 * begin, cloud.xyz.begin() + 3 * end);
    for (size_t i = 0; i < in_sensor.size(); ++i) in_sensor[i] -= sensor[int(i % 3)];
    if (opx_octree_insert_points(tree, in_sensor.data(), end - begin, 3 * sizeof(double), OPX_SCALAR_FLOAT64,
                                 &options, nullptr) == OPX_OK)
        return true;
    std::printf("FAIL: insert: %s\n", opx_last_error());
    return false;
}

// The occupied leaves holding points, each with its points' tight box.
std::vector<LeafBox> leaf_boxes(const opx_octree *tree, const Cloud &cloud) {
    std::map<std::tuple<long long, long long, long long, long long>, LeafBox> leaves;
    for (size_t i = 0; i < cloud.count(); ++i) {
        const Vec3 p = cloud.at(i);
        opx_cell_info info = OPX_CELL_INFO_INIT;
        if (opx_octree_classify(tree, p.data(), &info) != OPX_OK || info.cell_class != OPX_CELL_OCCUPIED) continue;
        const auto key = std::make_tuple(std::llround(info.center[0] / info.size * 2),
                                         std::llround(info.center[1] / info.size * 2),
                                         std::llround(info.center[2] / info.size * 2), (long long)info.depth);
        auto found = leaves.find(key);
        if (found == leaves.end()) {
            LeafBox leaf;
            leaf.tight.lo = leaf.tight.hi = p;
            leaf.size = info.size;
            leaves.emplace(key, leaf);
        } else {
            found->second.tight.lo = found->second.tight.lo.cwiseMin(p);
            found->second.tight.hi = found->second.tight.hi.cwiseMax(p);
        }
    }
    std::vector<LeafBox> out;
    for (const auto &entry : leaves) out.push_back(entry.second);
    return out;
}

// The minimum padded distance from the shapes to the boxes, each grown by
// `grow_slots` slots of its leaf (edge / 32).
double min_distance(const std::vector<PlacedShape> &placed, const std::vector<LeafBox> &leaves, double grow_slots) {
    double best = std::numeric_limits<double>::infinity();
    for (const PlacedShape &shape : placed)
        for (const LeafBox &leaf : leaves) {
            AlignedBox box = leaf.tight;
            const double grow = grow_slots * leaf.size / 32.0;
            box.lo.array() -= grow, box.hi.array() += grow;
            const Vec3 gap = (box.lo - shape.bounds_max).cwiseMax(shape.bounds_min - box.hi).cwiseMax(0.0);
            if (gap.norm() >= best) continue;  // the shape's padded bounds are farther already
            best = std::min(best, std::max(0.0, shape_aligned_distance(shape, box) - shape.inflation));
        }
    return best;
}

void expect(Checker &checker, bool holds, const std::string &message) {
    if (!holds) checker.fail(message);
}

struct Answer {
    bool collided = false;
    double distance = 0.0;
};

// What the scenes exercised, printed at the end.
struct Tally {
    uint64_t states = 0, collided = 0, cells_only = 0, leaves = 0;
};

bool ask(opx_query *query, const opx_octree *tree, const opx_linkset *links, Answer &out,
         int32_t geometry = OPX_OBSTACLE_POINT_EXTENTS) {
    opx_collision_request collision = OPX_COLLISION_REQUEST_INIT;
    collision.max_contacts = 0;
    collision.obstacle_geometry = geometry;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.obstacle_geometry = geometry;
    opx_distance_result distance = OPX_DISTANCE_RESULT_INIT;
    if (opx_query_collide(query, tree, links, &collision, &hit) != OPX_OK ||
        opx_query_distance(query, tree, links, &request, &distance) != OPX_OK) {
        std::printf("FAIL: query: %s\n", opx_last_error());
        return false;
    }
    out.collided = hit.collided != 0;
    out.distance = distance.found ? distance.distance : std::numeric_limits<double>::infinity();
    return true;
}

// `tight_expected`: the map took its points in one frame, so no leaf was
// pruned and expanded again (an expanded leaf keeps the part of its
// parent's extent inside it, which may exceed its own points by more than
// a slot).
void check_state(const RobotSpec &robot, const std::vector<LeafBox> &leaves, const Answer &direct,
                 const Answer &amortized, bool tight_expected, const std::string &label, Checker &checker) {
    const std::vector<PlacedShape> placed = place_robot(robot);
    const double tight = min_distance(placed, leaves, 0.0);
    const double loose = min_distance(placed, leaves, 1.0);
    expect(checker, direct.collided == amortized.collided, label + ": the engines disagree on collision");
    expect(checker, direct.distance == amortized.distance ||
                      std::abs(direct.distance - amortized.distance) <= 1e-12,
                  label + ": the engines disagree on distance: " + std::to_string(direct.distance) + " vs " +
                      std::to_string(amortized.distance));
    if (tight < -kTouchTolerance || tight == 0.0)
        expect(checker, direct.collided, label + ": overlaps the points' box but is not reported colliding");
    if (tight_expected && loose > 1e-6)
        expect(checker, !direct.collided, label + ": clear of the grown boxes but reported colliding");
    expect(checker, direct.distance <= tight + 1e-9,
                  label + ": distance " + std::to_string(direct.distance) + " exceeds the points' " +
                      std::to_string(tight));
    if (tight_expected)
        expect(checker, direct.distance >= loose - 1e-9,
                  label + ": distance " + std::to_string(direct.distance) + " below the grown boxes' " +
                      std::to_string(loose));
}

bool run_scene(Rng &rng, int index, opx_query *direct, opx_query *amortized, Checker &checker, Tally &tally) {
    const double resolutions[3] = {0.02, 0.05, 0.1};
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolutions[rng.integer(0, 2)];
    opx_octree *tree = nullptr;
    if (opx_octree_create(&options, &tree) != OPX_OK) return false;
    Cloud cloud;
    sample_scene(rng, rng.uniform(0.004, 0.02), cloud);
    const bool raycast = rng.chance(0.4);
    size_t frames = 1;
    const Vec3 sensor = rng.point(Vec3(-1.5, -1.5, 1.0), Vec3(1.5, 1.5, 1.5));
    if (raycast) {
        if (!insert(tree, cloud, 0, cloud.count(), OPX_INSERT_RAYCAST, sensor)) return false;
    } else {
        // Several endpoint frames: no cell is freed, every point stays in its leaf's extent.
        frames = size_t(rng.integer(1, 3));
        for (size_t f = 0; f < frames; ++f)
            if (!insert(tree, cloud, cloud.count() * f / frames, cloud.count() * (f + 1) / frames, OPX_INSERT_ENDPOINTS,
                        sensor))
                return false;
    }
    const std::vector<LeafBox> leaves = leaf_boxes(tree, cloud);
    tally.leaves += leaves.size();
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    opx_octree_get_stats(tree, &stats);
    const std::string scene = "scene " + std::to_string(index) + " (" + std::to_string(cloud.count()) + " points, " +
                              (raycast ? "ray-cast" : "endpoints") + ", resolution " +
                              std::to_string(options.resolution) + ")";
    if (!raycast)
        expect(checker, stats.leaves_with_extent == stats.leaves_occupied,
                      scene + ": every occupied leaf of an endpoints-only map keeps an extent");
    RobotOptions robot_options;
    robot_options.max_links = rng.integer(1, 4);
    robot_options.min_scale = 0.01;
    robot_options.max_scale = rng.uniform(0.03, 0.2);
    robot_options.max_padding = 0.05;
    RobotSpec robot = random_robot(rng, robot_options);
    opx_linkset *links = build_linkset(robot);
    // Links placed among the points, where whole cells and extents differ.
    Vec3 low = cloud.at(0), high = cloud.at(0);
    for (size_t i = 1; i < cloud.count(); ++i) low = low.cwiseMin(cloud.at(i)), high = high.cwiseMax(cloud.at(i));
    for (int state = 0; state < 16; ++state) {
        randomize_state(rng, robot, robot_options, low, high);
        update_linkset(links, robot);
        Answer a, b, cells;
        if (!ask(direct, tree, links, a) || !ask(amortized, tree, links, b) ||
            !ask(direct, tree, links, cells, OPX_OBSTACLE_CELLS))
            return false;
        expect(checker, a.distance >= cells.distance, scene + ": point extents nearer than whole cells");
        ++tally.states;
        tally.collided += a.collided;
        tally.cells_only += cells.collided && !a.collided;
        check_state(robot, leaves, a, b, frames == 1, scene + ", state " + std::to_string(state), checker);
    }
    opx_linkset_destroy(links);
    opx_octree_destroy(tree);
    return true;
}

}  // namespace

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 20261124);
    const int scenes = int(env_number("OPX_ORACLE_SCENES", 40));
    std::printf("oracle_point_extents: seed %llu, %d scenes\n", (unsigned long long)seed, scenes);
    Rng rng(seed);
    Checker checker("oracle_point_extents");
    opx_query *direct = nullptr, *amortized = nullptr;
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    if (opx_query_create(&options, &direct) != OPX_OK) return 1;
    options.engine = OPX_ENGINE_AMORTIZED;
    if (opx_query_create(&options, &amortized) != OPX_OK) return 1;
    Tally tally;
    for (int i = 0; i < scenes; ++i)
        if (!run_scene(rng, i, direct, amortized, checker, tally)) return 1;
    std::printf("occupied leaves with points %llu; robot states %llu, colliding %llu, colliding only as whole "
                "cells %llu\n",
                (unsigned long long)tally.leaves, (unsigned long long)tally.states,
                (unsigned long long)tally.collided, (unsigned long long)tally.cells_only);
    opx_query_destroy(direct);
    opx_query_destroy(amortized);
    // The scenes must exercise what the oracle compares: leaves with
    // points, robots colliding with the extents, and robots that only the
    // whole cells would call colliding (the extents' free space), beside
    // free ones.
    const bool exercised = tally.leaves > 0 && tally.collided > 0 && tally.cells_only > 0 &&
                           tally.collided + tally.cells_only < tally.states;
    if (!exercised) std::printf("FAIL: the scenes miss a case: leaves with points, colliding, only-cells or free states\n");
    return checker.finish(elapsed_seconds()) != 0 || !exercised ? 1 : 0;
}
