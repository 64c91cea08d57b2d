// opx_query_path on random small maps (occupied, free, uncertain and
// unknown space) with random robots of all six shape kinds: random paths of
// 2..20 waypoints (each link interpolated between two random poses), in
// packed and strided pose arrays, with and without distance and cost, each
// checked against the oracle waypoint by waypoint (oracle_path_check.hpp).
// Then hand-made cases (path_cases.hpp).
#include "oracle_engine.hpp"
#include "oracle_path_check.hpp"
#include "path_cases.hpp"

#include <cstdio>

using namespace oracle;

namespace {

opx_pose interpolate(const opx_pose &a, const opx_pose &b, double t, double scale) {
    const Eigen::Quaterniond qa(isometry_of(a).linear()), qb(isometry_of(b).linear());
    const Eigen::Quaterniond q = qa.slerp(t, qb);
    opx_pose out;
    for (int k = 0; k < 3; ++k) out.position[k] = (1.0 - t) * a.position[k] + t * b.position[k];
    const double xyzw[4] = {q.x(), q.y(), q.z(), q.w()};
    for (int k = 0; k < 4; ++k) out.orientation[k] = scale * xyzw[k];  // not always unit
    return out;
}

// Each link from a random start to a random end: far (across the scene)
// or near (a short motion, so that waypoints sweep the same cells).
Waypoints random_path(Rng &rng, size_t links, const Vec3 &low, const Vec3 &high, int count, double far_chance) {
    Waypoints path(count, std::vector<opx_pose>(links));
    for (size_t l = 0; l < links; ++l) {
        const opx_pose start = random_pose(rng, low, high);
        const Vec3 from(start.position);
        const opx_pose end = rng.chance(far_chance) ? random_pose(rng, low, high)
                                             : random_pose(rng, from - Vec3::Constant(0.3), from + Vec3::Constant(0.3));
        for (int w = 0; w < count; ++w) {
            const double scale = rng.chance(0.2) ? rng.uniform(0.5, 2.0) : 1.0;
            path[w][l] = interpolate(start, end, count == 1 ? 0.0 : double(w) / (count - 1), scale);
        }
    }
    return path;
}

void random_strides(Rng &rng, size_t links, PathCase &c) {
    c.pose_stride = rng.chance(0.3) ? 0 : sizeof(opx_pose) + 8 * rng.integer(0, 3);
    const size_t step = c.pose_stride == 0 ? sizeof(opx_pose) : c.pose_stride;
    const double draw = rng.uniform(0.0, 1.0);
    c.waypoint_stride = draw < 0.3 ? 0 : draw < 0.45 ? (links - 1) * step + sizeof(opx_pose)
                                                     : links * step + 8 * rng.integer(0, 4);
}

opx_path_request random_request(Rng &rng, const Scene &scene) {
    opx_path_request r = OPX_PATH_REQUEST_INIT;
    r.unknown_policy = rng.chance(0.15) ? OPX_UNKNOWN_OCCUPIED : OPX_UNKNOWN_FREE;
    r.occupancy_threshold = random_threshold(rng, scene);
    const int mode = rng.integer(0, 3);
    r.compute_distance = mode & 1;
    r.compute_cost = (mode >> 1) & 1;
    r.max_cost_boxes = uint32_t(rng.integer(0, 24));
    r.unknown_probability = rng.chance(0.5) ? 0.5 : rng.uniform(0.05, 0.95);
    if (rng.chance(0.5)) {  // else the default: the observed cells' bounds
        const Vec3 a = rng.point(scene.low - Vec3::Constant(1.0), scene.high + Vec3::Constant(1.0));
        const Vec3 b = rng.point(scene.low - Vec3::Constant(1.0), scene.high + Vec3::Constant(1.0));
        for (int k = 0; k < 3; ++k) r.region_min[k] = std::min(a[k], b[k]), r.region_max[k] = std::max(a[k], b[k]);
    }
    return r;
}

void run_scene(Rng &rng, const Scene &scene, int robots, int paths, PathReport &report) {
    const Vec3 low = scene.low - Vec3::Constant(0.3), high = scene.high + Vec3::Constant(0.3);
    for (int r = 0; r < robots; ++r) {
        RobotOptions options;  // the first robot small: clear paths, positive distances
        options.max_links = r == 0 ? 2 : rng.integer(1, 4);
        options.max_scale = r == 0 ? rng.uniform(0.05, 0.15) : rng.uniform(0.05, 0.6);
        options.max_padding = r == 0 ? 0.05 : options.max_padding;
        RobotSpec robot = random_robot(rng, options);
        randomize_state(rng, robot, options, low, high);
        opx_linkset *links = build_linkset(robot);
        // A new query per link set: see path_cases.cpp, replaced_link_set.
        opx_query *query = nullptr;
        oracle_create_query(&query);
        for (int p = 0; p < paths; ++p) {
            randomize_state(rng, robot, options, low, high);
            update_linkset(links, robot, unsigned(p));
            PathCase c;
            c.scene = &scene, c.robot = &robot;
            c.waypoints = random_path(rng, robot.links.size(), low, high, rng.integer(2, 20), r == 0 ? 0.1 : 0.5);
            c.request = random_request(rng, scene);
            random_strides(rng, robot.links.size(), c);
            c.label = "robot " + std::to_string(r) + " path " + std::to_string(p);
            check_path(query, links, c, report);
        }
        opx_query_destroy(query);
        opx_linkset_destroy(links);
    }
}

}  // namespace

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 777);
    const int scenes = int(env_number("OPX_ORACLE_SCENES", 250));
    std::printf("oracle_path: seed %llu, %d scenes\n", (unsigned long long)seed, scenes);
    PathReport report("oracle_path");
    run_path_cases(report);
    Rng rng(seed);
    for (int i = 0; i < scenes; ++i) {
        std::unique_ptr<Scene> scene = random_small_scene(rng, true);
        scene->label = "scene " + std::to_string(i) + " (" + scene->label + ", seed " + std::to_string(seed) + ")";
        run_scene(rng, *scene, 3, 5, report);
    }
    return report.finish(elapsed_seconds());
}
