// Penetration depth (opx_contact with compute_penetration = 1) and signed
// distance (opx_query_distance with signed_distance = 1) on random small
// maps against the exact separating-axis oracle (oracle_depth.hpp):
//  - random robots of all six shape kinds at random states;
//  - single shapes placed with their origin inside a random obstacle cell
//    (deep overlaps, sphere centres inside cells, pruned and unknown cubes).
#include "oracle_engine.hpp"
#include "penetration_check.hpp"

#include "oracle_depth.hpp"

#include <cmath>
#include <cstdio>

using namespace oracle;

namespace {

struct Request {
    double threshold = 0.0;
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
};

Request random_request(Rng &rng, const Scene &scene) {
    Request r;
    r.threshold = random_threshold(rng, scene);
    r.unknown_policy = rng.chance(0.25) ? OPX_UNKNOWN_OCCUPIED : OPX_UNKNOWN_FREE;
    return r;
}

void check_state(opx_query *query, const opx_linkset *links, const Scene &scene, const RobotSpec &robot,
                 const Request &request, const std::string &label, DepthReport &report) {
    const std::vector<PlacedShape> placed = place_robot(robot);
    DepthCase c;
    c.scene = &scene, c.robot = &robot, c.placed = &placed;
    c.threshold = request.threshold, c.unknown_policy = request.unknown_policy;
    c.label = label;
    check_penetration(query, links, c, report);
}

void random_robots(Rng &rng, const Scene &scene, opx_query *query, int robots, int states, DepthReport &report) {
    RobotOptions options;
    options.max_links = 4;
    options.max_scale = rng.uniform(0.2, 1.0);
    for (int r = 0; r < robots; ++r) {
        RobotSpec robot = random_robot(rng, options);
        randomize_state(rng, robot, options, scene.low, scene.high);
        opx_linkset *links = build_linkset(robot);
        for (int s = 0; s < states; ++s) {
            randomize_state(rng, robot, options, scene.low, scene.high);
            update_linkset(links, robot, unsigned(s));
            check_state(query, links, scene, robot, random_request(rng, scene),
                        "robot " + std::to_string(r) + " state " + std::to_string(s), report);
        }
        opx_linkset_destroy(links);
    }
}

// A random point inside a random cell that is an obstacle for `request`.
bool point_in_obstacle(Rng &rng, const Scene &scene, const Request &request, Vec3 &point) {
    const ObstacleRule rule(effective_threshold(request.threshold, scene.options), request.unknown_policy);
    const std::vector<MapCell> &cells = scene.cells->cells();
    for (int attempt = 0; attempt < 50; ++attempt) {
        const MapCell &cell = cells[rng.integer(0, int(cells.size()) - 1)];
        if (!rule(cell) || cell.size > 8.0) continue;  // (not the huge unknown cubes far away)
        const Vec3 half = Vec3::Constant(cell.cell.half);
        point = rng.point(cell.cell.center - half, cell.cell.center + half);
        return true;
    }
    return false;
}

void shapes_in_cells(Rng &rng, const Scene &scene, opx_query *query, int count, DepthReport &report) {
    for (int i = 0; i < count; ++i) {
        const Request request = random_request(rng, scene);
        Vec3 point;
        if (!point_in_obstacle(rng, scene, request, point)) continue;
        RobotSpec robot;
        LinkSpec link;
        link.name = "single";
        const double scale = rng.uniform(0.02, 0.6);
        ShapeSpec shape = random_shape(rng, 1 + i % 6, scale);
        if (rng.chance(0.5)) shape.pose = opx_pose OPX_POSE_IDENTITY;  // the shape's centre at the point
        link.shapes.push_back(shape);
        link.padding = rng.chance(0.5) ? rng.uniform(0.0, 0.1) : 0.0;
        link.pose = random_pose(rng, point, point);
        robot.links.push_back(link);
        robot.global_padding = rng.chance(0.3) ? rng.uniform(0.0, 0.05) : 0.0;
        opx_linkset *links = build_linkset(robot);
        check_state(query, links, scene, robot, request, "single shape " + std::to_string(i), report);
        opx_linkset_destroy(links);
    }
}

// The oracle itself on hand-computed cases: the cell [0, 0.2]^3.
PlacedShape placed_of(int32_t kind, double inflation) {
    PlacedShape s;
    s.kind = kind;
    s.inflation = inflation;
    return s;
}

int check_oracle(DepthReport &report) {
    Cell cell;
    cell.center = Vec3::Constant(0.1), cell.half = 0.1;
    struct Expected {
        const char *name;
        PlacedShape shape;
        double depth;
    };
    std::vector<Expected> cases;
    PlacedShape s = placed_of(OPX_SHAPE_SPHERE, 0.1);
    s.point = Vec3(0.05, 0.1, 0.1);  // inside, 0.05 from the face x = 0
    cases.push_back({"sphere centre inside", s, 0.15});
    s.point = Vec3(0.3, 0.1, 0.1);  // 0.1 away, radius 0.15
    s.inflation = 0.15;
    cases.push_back({"sphere, ball only", s, 0.05});
    s = placed_of(OPX_SHAPE_BOX, 0.01);
    s.box.center = Vec3(0.25, 0.1, 0.1), s.box.half = Vec3::Constant(0.1);  // x overlap 0.05
    cases.push_back({"aligned box", s, 0.06});
    s = placed_of(OPX_SHAPE_CAPSULE, 0.02);
    s.segment = {Vec3(-1.0, 0.1, 0.1), Vec3(1.0, 0.1, 0.1)};  // through the centre: 0.1 to a face
    cases.push_back({"capsule through the centre", s, 0.12});
    s = placed_of(OPX_SHAPE_MESH, 0.0);
    s.triangles = {{Vec3(-1, -1, 0.15), Vec3(2, -1, 0.15), Vec3(-1, 2, 0.15)}};  // plane z = 0.15
    cases.push_back({"triangle across the cell", s, 0.05});
    int failures = 0;
    for (const Expected &e : cases) {
        const DepthAnswer d = padded_depth(e.shape, cell);
        if (std::abs(d.depth - e.depth) <= 1e-15) continue;
        ++failures;
        report.mismatch(std::string("the oracle itself: ") + e.name + ": depth " + std::to_string(d.depth) +
                        ", expected " + std::to_string(e.depth));
    }
    return failures;
}

}  // namespace

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 4242);
    const int scenes = int(env_number("OPX_ORACLE_SCENES", 25));
    std::printf("oracle_penetration: seed %llu, %d scenes\n", (unsigned long long)seed, scenes);
    Rng rng(seed);
    DepthReport report("oracle_penetration");
    if (check_oracle(report) > 0) return report.finish(elapsed_seconds());
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    for (int i = 0; i < scenes; ++i) {
        std::unique_ptr<Scene> scene = random_small_scene(rng, true);
        scene->label = "scene " + std::to_string(i) + " (" + scene->label + ", seed " + std::to_string(seed) + ")";
        random_robots(rng, *scene, query, 2, 30, report);
        shapes_in_cells(rng, *scene, query, 120, report);
    }
    opx_query_destroy(query);
    return report.finish(elapsed_seconds());
}
