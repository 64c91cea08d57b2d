// real_batch_pr2: opx_query_check_configurations and _check_motions on the
// PR2 of the shared data (all 95 links, its meshes, the full SRDF) equal
// the single calls (FK on the link set, then opx_query_collide /
// opx_query_distance, and _self_collide / _self_distance) at
// random configurations within the URDF limits, for 1, 2 and 3 threads,
// against scattered occupied cells at 2 cm around the robot; certified
// motions against a dense walk.
#include "real_support.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

std::string g_urdf_path, g_srdf_path, g_package_entry;
constexpr size_t kRows = 150;

opx_linkset *load_pr2() {
    const char *dirs[1] = {g_package_entry.c_str()};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    options.srdf_path = g_srdf_path.c_str();
    opx_linkset *robot = nullptr;
    real::check_ok(opx_linkset_load_urdf_file(g_urdf_path.c_str(), &options, &robot), "opx_linkset_load_urdf_file");
    return robot;
}

size_t joint_count(const opx_linkset *robot) {
    uint32_t count = 0;
    real::check_ok(opx_linkset_get_joint_count(robot, &count), "opx_linkset_get_joint_count");
    return count;
}

// Rows of every joint uniform within its limits (continuous: +-pi).
std::vector<double> random_rows(const opx_linkset *robot, size_t rows, uint32_t seed) {
    const size_t joints = joint_count(robot);
    std::vector<double> lower(joints, 0.0), upper(joints, 0.0);
    for (uint32_t j = 0; j < joints; ++j) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        real::check_ok(opx_linkset_get_joint_info(robot, j, &info), "opx_linkset_get_joint_info");
        if (info.type == OPX_JOINT_CONTINUOUS) lower[j] = -M_PI, upper[j] = M_PI;
        else if (info.has_limits) lower[j] = info.lower, upper[j] = info.upper;
    }
    std::mt19937_64 rng(seed);
    std::vector<double> out(rows * joints);
    for (size_t r = 0; r < rows; ++r)
        for (size_t j = 0; j < joints; ++j)
            out[r * joints + j] = std::uniform_real_distribution<double>(lower[j], upper[j])(rng);
    return out;
}

// Occupied 2 cm cells scattered in front of the robot, where its arms
// reach (clear of the base, torso and head); the rest unknown.
opx_octree *scatter_map() {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = 0.02;
    opx_octree *tree = nullptr;
    real::check_ok(opx_octree_create(&options, &tree), "opx_octree_create");
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> x(0.45, 1.2), y(-1.0, 1.0), z(0.4, 1.4);
    std::vector<double> xyz;
    for (int i = 0; i < 150; ++i) xyz.insert(xyz.end(), {x(rng), y(rng), z(rng)});
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_ENDPOINTS;
    real::check_ok(opx_octree_insert_points(tree, xyz.data(), 150, 0, OPX_SCALAR_FLOAT64, &insert, nullptr),
                   "opx_octree_insert_points");
    return tree;
}

struct Single {
    opx_query *query;
    const opx_octree *tree;
    opx_linkset *robot;

    void move(const double *q) const {
        real::check_ok(opx_linkset_set_joint_positions(robot, q, joint_count(robot), nullptr),
                       "opx_linkset_set_joint_positions");
    }
    int collides(const double *q) const {
        move(q);
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        request.max_contacts = 0;
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        real::check_ok(opx_query_collide(query, tree, robot, &request, &result), "opx_query_collide");
        return result.collided;
    }
    double distance(const double *q) const {
        move(q);
        opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
        real::check_ok(opx_query_distance(query, tree, robot, nullptr, &result), "opx_query_distance");
        return result.distance;
    }
    // At the pose of the last move.
    int self_collides() const {
        opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
        request.max_contacts = 0;
        opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
        real::check_ok(opx_query_self_collide(query, robot, &request, &result), "opx_query_self_collide");
        return result.collided;
    }
    double self_distance() const {
        opx_self_distance_result result = OPX_SELF_DISTANCE_RESULT_INIT;
        real::check_ok(opx_query_self_distance(query, robot, nullptr, &result), "opx_query_self_distance");
        return result.distance;
    }
};

// What the single calls answer for every row, without and with self.
struct Expected {
    std::vector<int> world, both;
    std::vector<double> world_distance, both_distance;
};

Expected single_answers(const Single &single, const std::vector<double> &rows, size_t joints) {
    Expected e;
    for (size_t i = 0; i < kRows; ++i) {
        const double *q = &rows[i * joints];
        e.world_distance.push_back(single.distance(q));
        e.both_distance.push_back(std::min(e.world_distance.back(), single.self_distance()));
        e.world.push_back(single.collides(q));
        e.both.push_back(e.world.back() || single.self_collides());
    }
    return e;
}

void test_configurations_equal_single_calls(void **) {
    opx_linkset *robot = load_pr2();
    opx_octree *tree = scatter_map();
    const size_t joints = joint_count(robot);
    const std::vector<double> rows = random_rows(robot, kRows, 5);
    opx_query *single_query = nullptr;
    real::check_ok(opx_query_create(nullptr, &single_query), "opx_query_create");
    const Single single{single_query, tree, robot};
    const Expected e = single_answers(single, rows, joints);
    size_t hits = 0, self_hits = 0;
    for (size_t i = 0; i < kRows; ++i) hits += size_t(e.world[i]), self_hits += size_t(e.both[i] && !e.world[i]);
    std::printf("PR2: %zu of %zu configurations collide with the map, %zu more with the robot itself\n", hits, kRows,
                self_hits);
    assert_true(hits > kRows / 20 && hits < kRows * 19 / 20);
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        for (int32_t kind = 0; kind < 4; ++kind) {
            const int32_t distance = kind & 1, self = kind >> 1;
            const std::vector<int> &expected = self ? e.both : e.world;
            const std::vector<double> &expected_distance = self ? e.both_distance : e.world_distance;
            opx_query *query = nullptr;
            real::check_ok(opx_query_create(nullptr, &query), "opx_query_create");
            opx_batch_request request = OPX_BATCH_REQUEST_INIT;
            request.max_threads = threads;
            request.compute_distance = distance;
            request.self_collision = self;
            std::vector<uint8_t> collided(kRows);
            std::vector<double> distances(kRows);
            real::check_ok(opx_query_check_configurations(query, tree, robot, rows.data(), kRows, joints, 0, nullptr,
                                                          0, 0, &request, collided.data(), distances.data(), kRows),
                           "opx_query_check_configurations");
            for (size_t i = 0; i < kRows; ++i) {
                assert_int_equal(collided[i], expected[i]);
                if (distance) assert_true(distances[i] == expected_distance[i]);
            }
            opx_query_destroy(query);
        }
    }
    opx_query_destroy(single_query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

// Motions from each configuration to a nearby one: the batch on 1-3
// threads equals opx_query_check_motion, motion by motion.
void test_motions_equal_single_motion_calls(void **) {
    opx_linkset *robot = load_pr2();
    opx_octree *tree = scatter_map();
    const size_t joints = joint_count(robot), motions = 40;
    std::vector<double> starts = random_rows(robot, motions, 9), goals = starts;
    std::mt19937_64 rng(3);
    for (double &v : goals) v += std::uniform_real_distribution<double>(-0.2, 0.2)(rng);
    opx_query *query = nullptr;
    real::check_ok(opx_query_create(nullptr, &query), "opx_query_create");
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = 0.02;
    request.self_collision = 1;
    std::vector<int32_t> expected(motions);
    std::vector<double> expected_fraction(motions);
    for (size_t m = 0; m < motions; ++m) {
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        real::check_ok(opx_query_check_motion(query, tree, robot, &starts[m * joints], &goals[m * joints], joints,
                                              nullptr, &request, &result),
                       "opx_query_check_motion");
        expected[m] = result.collided, expected_fraction[m] = result.first_collision_fraction;
    }
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        request.max_threads = threads;
        std::vector<uint8_t> collided(motions);
        std::vector<double> fractions(motions);
        real::check_ok(opx_query_check_motions(query, tree, robot, starts.data(), goals.data(), motions, joints, 0,
                                               nullptr, 0, 0, &request, collided.data(), fractions.data(), motions),
                       "opx_query_check_motions");
        for (size_t m = 0; m < motions; ++m) {
            assert_int_equal(collided[m], expected[m]);
            assert_true(fractions[m] == expected_fraction[m]);
        }
    }
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

// Certified motions of the PR2 with self-collision from free random
// configurations: a motion called free has no colliding configuration in
// a walk of 10,001 (1e-4 of it); one called colliding reports a
// configuration within the contact distance and none of the walk's before
// its fraction less the tolerance collides; 2 threads agree.
void test_certified_motions_against_a_walk(void **) {
    opx_linkset *robot = load_pr2();
    opx_octree *tree = scatter_map();
    const size_t joints = joint_count(robot), motions = 4;
    opx_query *query = nullptr, *single_query = nullptr;
    real::check_ok(opx_query_create(nullptr, &query), "opx_query_create");
    real::check_ok(opx_query_create(nullptr, &single_query), "opx_query_create");
    const Single single{single_query, tree, robot};
    auto collides = [&](const double *q) { return single.collides(q) || single.self_collides(); };
    std::vector<double> starts, goals;
    std::mt19937_64 rng(5);
    for (uint32_t seed = 100; starts.size() < motions * joints; ++seed) {
        const std::vector<double> q = random_rows(robot, 1, seed);
        if (collides(q.data())) continue;
        starts.insert(starts.end(), q.begin(), q.end());
        for (double v : q) goals.push_back(v + std::uniform_real_distribution<double>(-0.3, 0.3)(rng));
    }
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.check = OPX_MOTION_CERTIFIED;
    request.self_collision = 1;
    request.max_threads = 2;
    std::vector<uint8_t> collided(motions);
    std::vector<double> fractions(motions), q(joints);
    real::check_ok(opx_query_check_motions(query, tree, robot, starts.data(), goals.data(), motions, joints, 0,
                                           nullptr, 0, 0, &request, collided.data(), fractions.data(), motions),
                   "opx_query_check_motions");
    for (size_t m = 0; m < motions; ++m) {
        const double *a = &starts[m * joints], *b = &goals[m * joints];
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        real::check_ok(opx_query_check_motion(query, tree, robot, a, b, joints, nullptr, &request, &result),
                       "opx_query_check_motion");
        assert_true(result.first_collision_fraction == fractions[m]);
        assert_int_equal(result.collided, collided[m]);
        const double end = collided[m] ? fractions[m] - request.tolerance : 2.0;
        for (int i = 0; i <= 10000 && i / 1e4 < end; ++i) {
            for (size_t j = 0; j < joints; ++j) q[j] = a[j] + (i / 1e4) * (b[j] - a[j]);
            assert_false(collides(q.data()));
        }
        if (!collided[m]) continue;
        for (size_t j = 0; j < joints; ++j) q[j] = a[j] + fractions[m] * (b[j] - a[j]);
        assert_true(std::min(single.distance(q.data()), single.self_distance()) <= OPX_MOTION_CONTACT_DISTANCE);
    }
    opx_query_destroy(single_query);
    opx_query_destroy(query);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

}  // namespace

int main() {
    g_urdf_path = real::require_data_file("robots/pr2_description/urdf/robot.xml");
    g_srdf_path = real::require_data_file("robots/pr2_description/srdf/pr2.srdf");
    g_package_entry = "moveit_resources_pr2_description=" + real::data_dir() + "/robots/pr2_description";
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_configurations_equal_single_calls),
        cmocka_unit_test(test_motions_equal_single_motion_calls),
        cmocka_unit_test(test_certified_motions_against_a_walk),
    };
    return cmocka_run_group_tests_name("real_batch_pr2", tests, nullptr, nullptr);
}
