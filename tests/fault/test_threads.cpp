// fault_threads: one map and a set of posed link sets shared read-only by
// N threads (2, 4, 8), each with its own query contexts, each running every
// query kind that takes const handles on both engines over many poses,
// every read of the map and the link sets, and frames self-filtered
// against the shared link sets into maps of each thread's own.  Every thread must answer bit
// for bit what one thread alone answers.  The link sets, and two copies of
// the map (for sphere queries, and for batches of an arm of spheres on two
// workers each), are made anew for each run and never queried before it,
// so their lazy work (the tree over shapes added by hand, a mesh placed
// when first reached, the maps' obstacle grids) happens while the threads
// race for it.  Built with -fsanitize=thread it is tsan_threads.
//
// Usage: fault_threads [--poses N] [--without-unplaced-links] [thread counts...]
//   --poses N: N posed arms (default 48)
//   --without-unplaced-links: leave out the link set whose tree the first
//     query builds (see run_tsan_threads.cmake)
//   thread counts: default 2 4 8
#include "fault_answers.hpp"
#include "fault_scene.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace fault;

constexpr size_t kWaypoints = 5;  // per path query
constexpr size_t kProbes = 200;   // classify calls

struct Settings {
    size_t poses = 48;  // posed arms shared by the threads
    bool unplaced_links = true;
    std::vector<size_t> thread_counts;
};

// What every thread reads: built before the threads start.
struct SharedScene {
    const opx_octree *tree = nullptr;
    std::vector<opx_linkset *> arms;  // arm i at configuration i
    opx_linkset *loose = nullptr;     // shapes added by hand, never posed (may be NULL)
    std::vector<std::vector<opx_pose>> paths;
    std::vector<double> boxes;
    opx_octree *sphere_map = nullptr;  // a copy of tree whose grid the first sphere query builds
    std::vector<double> spheres;       // x y z radius rows
    opx_octree *batch_map = nullptr;   // another copy, whose grid the first sphere-arm batch builds
    opx_linkset *sphere_arm = nullptr;
    std::vector<double> sphere_rows;   // its joint rows

    ~SharedScene() {
        for (opx_linkset *arm : arms) opx_linkset_destroy(arm);
        opx_linkset_destroy(loose);
        opx_octree_destroy(sphere_map);
        opx_octree_destroy(batch_map);
        opx_linkset_destroy(sphere_arm);
    }
};

// Links of every shape kind at the origin of the map, where the floor is:
// the link set's tree is left to the first query to build.
opx_linkset *loose_links() {
    opx_linkset *links = nullptr;
    require_ok(opx_linkset_create(&links), "opx_linkset_create");
    const opx_linkset *arm = arm_with_gripper();
    uint32_t count = 0;
    require_ok(opx_linkset_get_link_count(arm, &count), "opx_linkset_get_link_count");
    for (uint32_t link = 0; link < count; ++link) {
        uint32_t added = 0, shapes = 0;
        require_ok(opx_linkset_add_link(links, "copy", &added), "opx_linkset_add_link");
        require_ok(opx_linkset_get_shape_count(arm, link, &shapes), "opx_linkset_get_shape_count");
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            require_ok(opx_linkset_get_shape(arm, link, s, &shape), "opx_linkset_get_shape");
            shape.pose.position[0] += 0.5 + 0.1 * link;  // spread over the floor and the box
            shape.pose.position[2] += 0.02 * link;
            require_ok(opx_linkset_add_shape(links, added, &shape, nullptr), "opx_linkset_add_shape");
        }
    }
    opx_linkset_destroy(const_cast<opx_linkset *>(arm));
    return links;
}

std::unique_ptr<SharedScene> make_scene(const opx_octree *tree, const Settings &settings) {
    auto scene = std::make_unique<SharedScene>();
    scene->tree = tree;
    for (size_t i = 0; i < settings.poses; ++i) {
        scene->arms.push_back(arm_with_gripper());
        arm_pose(scene->arms.back(), i);
    }
    if (settings.unplaced_links) scene->loose = loose_links();
    for (size_t i = 0; i < settings.poses; ++i) scene->paths.push_back(arm_path(scene->arms[0], 3 * i, kWaypoints));
    scene->boxes = room_boxes(300, 21);
    const std::vector<unsigned char> image = map_image(tree, OPX_FORMAT_OT);
    for (opx_octree **copy : {&scene->sphere_map, &scene->batch_map})
        require_ok(opx_octree_load_memory(image.data(), image.size(), nullptr, copy), "opx_octree_load_memory");
    scene->sphere_arm = sphere_arm();
    scene->sphere_rows = sphere_arm_rows(64, 7);
    Lcg rng(5);
    for (size_t i = 0; i < 64; ++i)
        for (double value : {rng.uniform(-2.0, 2.0), rng.uniform(-2.0, 2.0), rng.uniform(0.0, 2.5), rng.uniform(0.0, 0.3)})
            scene->spheres.push_back(value);
    return scene;
}

void run_query(Record &record, QueryKind kind, opx_query *query, const QueryInputs &in) {
    QueryOutputs out;
    const opx_status status = call_query(kind, query, in, out);
    record.add(query_kind_name(kind), status);
    if (status == OPX_OK) record_query(kind, record, query, out);
}

// Octree queries: every link set, both unknown policies, on one context.
void octree_queries(Record &record, const SharedScene &scene, int32_t engine) {
    opx_query *query = new_query(engine);
    for (size_t i = 0; i <= scene.arms.size(); ++i) {
        QueryInputs in;
        in.tree = scene.tree;
        in.links = i < scene.arms.size() ? scene.arms[i] : scene.loose;
        if (in.links == nullptr) break;
        in.unknown_policy = i % 3 == 2 ? OPX_UNKNOWN_OCCUPIED : OPX_UNKNOWN_FREE;
        run_query(record, QueryKind::kCollide, query, in);
        run_query(record, QueryKind::kDistance, query, in);
        if (i < scene.paths.size()) {
            in.links = scene.arms[0];
            in.path = scene.paths[i].data();
            in.waypoints = kWaypoints;
            run_query(record, QueryKind::kPath, query, in);
        }
    }
    record_query_stats(record, query);
    opx_query_destroy(query);
}

void box_queries(Record &record, const SharedScene &scene) {
    opx_query *query = new_query(OPX_ENGINE_AMORTIZED);
    record.add("bind_boxes", opx_query_bind_boxes(query, scene.boxes.data(), scene.boxes.size() / 6, 0));
    for (const opx_linkset *arm : scene.arms) {
        QueryInputs in;
        in.links = arm;
        run_query(record, QueryKind::kCollideBoxes, query, in);
        run_query(record, QueryKind::kDistanceBoxes, query, in);
    }
    record_query_stats(record, query);
    opx_query_destroy(query);
}

// A clone of a shared link set (opx_linkset_clone takes a const handle),
// queried at once.
void clone_queries(Record &record, const SharedScene &scene) {
    opx_query *query = new_query(OPX_ENGINE_DIRECT);
    for (const opx_linkset *arm : {scene.arms[1], scene.loose}) {
        if (arm == nullptr) continue;
        opx_linkset *clone = nullptr;
        record.add("clone", opx_linkset_clone(arm, &clone));
        QueryInputs in;
        in.tree = scene.tree;
        in.links = clone;
        run_query(record, QueryKind::kDistance, query, in);
        record_linkset(record, clone);
        opx_linkset_destroy(clone);
    }
    opx_query_destroy(query);
}

// Spheres one call each, then all in one call, on the map copy.
void sphere_queries(Record &record, const SharedScene &scene) {
    opx_query *query = new_query(OPX_ENGINE_DIRECT);
    const size_t count = scene.spheres.size() / 4;
    std::vector<uint8_t> collided(count);
    for (size_t i = 0; i < count; ++i) {
        record.add("collide_spheres", opx_query_collide_spheres(query, scene.sphere_map, &scene.spheres[4 * i], 1, 0,
                                                                nullptr, &collided[i], 1));
        record.add("sphere collided", uint32_t(collided[i]));
    }
    record.add("collide_spheres", opx_query_collide_spheres(query, scene.sphere_map, scene.spheres.data(), count, 0,
                                                            nullptr, collided.data(), count));
    record.add_bytes("spheres collided", collided.data(), count);
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    request.max_threads = 2;
    std::vector<double> distance(count), gradient(3 * count);
    record.add("distance_spheres", opx_query_distance_spheres(query, scene.sphere_map, scene.spheres.data(), count, 0,
                                                              &request, distance.data(), gradient.data(), nullptr,
                                                              count));
    record.add_bytes("sphere distances", distance.data(), count * sizeof(double));
    record.add_bytes("sphere gradients", gradient.data(), 3 * count * sizeof(double));
    opx_query_destroy(query);
}

// The arm of spheres' rows in one batch on two workers, then on one, on
// the second map copy.
void sphere_batch_queries(Record &record, const SharedScene &scene) {
    opx_query *query = new_query(OPX_ENGINE_DIRECT);
    const size_t count = scene.sphere_rows.size() / kSphereArmJoints;
    std::vector<uint8_t> collided(count);
    for (uint32_t workers : {2u, 1u}) {
        opx_batch_request request = OPX_BATCH_REQUEST_INIT;
        request.max_threads = workers;
        record.add("check_configurations",
                   opx_query_check_configurations(query, scene.batch_map, scene.sphere_arm, scene.sphere_rows.data(),
                                                  count, kSphereArmJoints, 0, &kSphereArmBase, 1, 0, &request,
                                                  collided.data(), nullptr, count));
        record.add_bytes("configurations collided", collided.data(), count);
    }
    // The arm's rows as one trajectory: its cost and gradient.
    opx_trajectory_cost_request request = OPX_TRAJECTORY_COST_REQUEST_INIT;
    request.activation = 0.1;
    double cost = 0.0;
    std::vector<double> gradient(scene.sphere_rows.size());
    record.add("trajectory_cost", opx_query_trajectory_cost(query, scene.batch_map, scene.sphere_arm,
                                                            scene.sphere_rows.data(), count, kSphereArmJoints, 0,
                                                            &kSphereArmBase, &request, &cost, gradient.data(), count));
    record.add_bytes("trajectory cost", &cost, sizeof cost);
    record.add_bytes("trajectory gradient", gradient.data(), gradient.size() * sizeof(double));
    opx_query_destroy(query);
}

// Certified motions of the arm of spheres between its rows, on two
// workers, then on one: every thread reads the shared map and arm.
void certified_motion_queries(Record &record, const SharedScene &scene) {
    opx_query *query = new_query(OPX_ENGINE_DIRECT);
    const size_t count = std::min<size_t>(4, scene.sphere_rows.size() / kSphereArmJoints / 2);
    std::vector<uint8_t> collided(count);
    std::vector<double> fractions(count);
    for (uint32_t workers : {2u, 1u}) {
        opx_motion_request request = OPX_MOTION_REQUEST_INIT;
        request.check = OPX_MOTION_CERTIFIED;
        request.max_threads = workers;
        const double *rows = scene.sphere_rows.data();
        record.add("check_motions certified",
                   opx_query_check_motions(query, scene.tree, scene.sphere_arm, rows, rows + kSphereArmJoints, count,
                                           kSphereArmJoints, 2 * kSphereArmJoints * sizeof(double), &kSphereArmBase,
                                           1, 0, &request, collided.data(), fractions.data(), count));
        record.add_bytes("motions collided", collided.data(), count);
        record.add("first collision fractions", fractions.data(), count);
    }
    opx_query_destroy(query);
}

// Frames self-filtered against the shared arms (whose meshes the first
// filter places) into maps of this thread's own, on one and two threads.
void filtered_inserts(Record &record, const SharedScene &scene) {
    const std::vector<float> cloud = room_cloud(400, 9);
    const std::vector<unsigned char> image = map_image(scene.tree, OPX_FORMAT_OT);
    for (size_t i = 0; i < scene.arms.size() && i < 6; ++i) {
        opx_octree *map = nullptr;
        record.add("load_memory", opx_octree_load_memory(image.data(), image.size(), nullptr, &map));
        opx_insert_options options = sensor_insert_options(OPX_INSERT_RAYCAST);
        options.robot = scene.arms[i];
        options.robot_padding = 0.03;
        options.clear_robot_volume = 1;
        options.max_threads = 1 + static_cast<uint32_t>(i % 2);
        opx_insert_report report = OPX_INSERT_REPORT_INIT;
        record.add("insert_points filtered",
                   opx_octree_insert_points(map, cloud.data(), cloud.size() / 3, 0, OPX_SCALAR_FLOAT32, &options, &report));
        record.add("points_on_robot", report.points_on_robot);
        record.add("points_shadowed", report.points_shadowed);
        record.add("cells_cleared", report.cells_cleared);
        record_map(record, map);
        opx_octree_destroy(map);
    }
}

// Clearing, decay, cropping and bounded inserts on maps of this thread's
// own, while the other threads query the shared one.
void map_edits(Record &record, const SharedScene &scene) {
    const std::vector<unsigned char> image = map_image(scene.tree, OPX_FORMAT_OT);
    const std::vector<float> cloud = room_cloud(300, 5);
    opx_octree *map = nullptr;
    record.add("load_memory", opx_octree_load_memory(image.data(), image.size(), nullptr, &map));
    const double lo[3] = {-0.83, -0.52, 0.11}, hi[3] = {0.71, 0.94, 1.27};
    record.add("clear_region free", opx_octree_clear_region(map, lo, hi, OPX_CELL_FREE));
    opx_shape sphere = OPX_SHAPE_INIT;
    sphere.kind = OPX_SHAPE_SPHERE;
    sphere.radius = 0.4;
    opx_pose pose = OPX_POSE_IDENTITY;
    pose.position[2] = 0.6;
    record.add("clear_shapes unknown", opx_octree_clear_shapes(map, &sphere, 1, &pose, OPX_CELL_UNKNOWN));
    opx_insert_options options = sensor_insert_options(OPX_INSERT_RAYCAST);
    options.use_bounds = 1;
    for (int axis = 0; axis < 3; ++axis) options.bounds_min[axis] = -1.5, options.bounds_max[axis] = 1.5;
    record.add("insert_points bounded",
               opx_octree_insert_points(map, cloud.data(), cloud.size() / 3, 0, OPX_SCALAR_FLOAT32, &options, nullptr));
    record.add("decay", opx_octree_decay(map, 0.3));
    record.add("crop", opx_octree_crop(map, lo, hi));
    record_map(record, map);
    opx_octree_destroy(map);
}

Record every_answer(const SharedScene &scene) {
    Record record;
    map_edits(record, scene);
    filtered_inserts(record, scene);
    sphere_queries(record, scene);
    sphere_batch_queries(record, scene);
    certified_motion_queries(record, scene);
    octree_queries(record, scene, OPX_ENGINE_DIRECT);
    octree_queries(record, scene, OPX_ENGINE_AMORTIZED);
    box_queries(record, scene);
    clone_queries(record, scene);
    record_map_reads(record, scene.tree, kProbes);
    for (const opx_linkset *arm : scene.arms) record_linkset(record, arm);
    if (scene.loose != nullptr) record_linkset(record, scene.loose);
    return record;
}

// Runs every_answer on `threads` threads at once over a fresh scene; the
// number of threads whose answers differ from `reference`.
int run_threads(const opx_octree *tree, const Settings &settings, size_t threads, const Record &reference) {
    const std::unique_ptr<SharedScene> scene = make_scene(tree, settings);
    std::vector<Record> records(threads);
    std::atomic<size_t> ready{0};
    std::vector<std::thread> workers;
    for (size_t t = 0; t < threads; ++t) {
        workers.emplace_back([&, t] {
            ready.fetch_add(1);
            while (ready.load() < threads) std::this_thread::yield();  // start together
            records[t] = every_answer(*scene);
        });
    }
    for (std::thread &worker : workers) worker.join();
    int differing = 0;
    for (size_t t = 0; t < threads; ++t) {
        if (records[t] == reference) continue;
        ++differing;
        std::printf("FAIL %zu threads: thread %zu answers otherwise than one thread alone: %s\n", threads, t,
                    records[t].first_difference(reference).c_str());
    }
    return differing;
}

Settings read_settings(int argc, char **argv) {
    Settings settings;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--poses" && i + 1 < argc) settings.poses = std::strtoul(argv[++i], nullptr, 10);
        else if (arg == "--without-unplaced-links") settings.unplaced_links = false;
        else settings.thread_counts.push_back(std::strtoul(argv[i], nullptr, 10));
    }
    if (settings.poses < 2) settings.poses = 2;  // clone_queries uses arm 1
    if (settings.thread_counts.empty()) settings.thread_counts = {2, 4, 8};
    return settings;
}

}  // namespace

int main(int argc, char **argv) {
    setvbuf(stdout, nullptr, _IOLBF, 0);
    const Settings settings = read_settings(argc, argv);
    opx_octree *tree = room_map(0.05, 3000, 11);
    const auto start = std::chrono::steady_clock::now();
    const Record reference = every_answer(*make_scene(tree, settings));
    const double alone = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("one thread: %zu poses, %zu words of answers in %.2f s%s\n", settings.poses, reference.size(), alone,
                settings.unplaced_links ? "" : " (without the unplaced link set)");

    int passed = 0, failed = 0;
    for (size_t threads : settings.thread_counts) {
        const auto run_start = std::chrono::steady_clock::now();
        const int differing = run_threads(tree, settings, threads, reference);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
        std::printf("%zu threads: %d of them differ, %.2f s\n", threads, differing, seconds);
        (differing == 0 ? passed : failed) += 1;
    }
    opx_octree_destroy(tree);
    std::printf("fault_threads: %d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
