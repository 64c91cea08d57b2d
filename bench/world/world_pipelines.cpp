#include "world_pipelines.hpp"

#include <algorithm>
#include <memory>

#include "timing.hpp"

namespace world_bench {
namespace {

using paper_tables::check_opx;
using paper_tables::Clock;
using paper_tables::milliseconds_between;

void forward_kinematics(Robot &robot, size_t i) {
    static const opx_pose kBase = OPX_POSE_IDENTITY;
    const std::vector<double> &q = robot.configurations[i].joints;
    check_opx(opx_linkset_set_joint_positions(robot.links.get(), q.data(), q.size(), &kBase),
              "opx_linkset_set_joint_positions");
}

// A direct context with `world` set (NULL: none), kept while the pipeline is.
std::shared_ptr<opx_query> query_with_world(const opx_world *world) {
    std::shared_ptr<opx_query> query(paper_tables::make_direct_query().release(), [](opx_query *q) {
        opx_query_set_world(q, nullptr);
        opx_query_destroy(q);
    });
    check_opx(opx_query_set_world(query.get(), world), "opx_query_set_world");
    return query;
}

}  // namespace

Pipeline opx_pipeline(Robot &robot, const opx_octree *tree, const opx_world *world) {
    std::shared_ptr<opx_query> query = query_with_world(world);
    return [&robot, tree, query](std::vector<uint8_t> &collided) {
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        request.max_contacts = 0;  // yes or no: stop at the first contact
        Split split;
        for (size_t i = 0; i < robot.configurations.size(); ++i) {
            const Clock::time_point start = Clock::now();
            forward_kinematics(robot, i);
            const Clock::time_point posed = Clock::now();
            opx_collision_result result = OPX_COLLISION_RESULT_INIT;
            check_opx(opx_query_collide(query.get(), tree, robot.links.get(), &request, &result), "opx_query_collide");
            const Clock::time_point done = Clock::now();
            split.pose_ms += milliseconds_between(start, posed);
            split.query_ms += milliseconds_between(posed, done);
            collided[i] = static_cast<uint8_t>(result.collided);
        }
        return split;
    };
}

Pipeline opx_batch_pipeline(Robot &robot, const opx_octree *tree, const opx_world *world, uint32_t threads) {
    std::shared_ptr<opx_query> query = query_with_world(world);
    auto rows = std::make_shared<std::vector<double>>();
    for (const paper_tables::Configuration &c : robot.configurations) rows->insert(rows->end(), c.joints.begin(), c.joints.end());
    return [&robot, tree, query, rows, threads](std::vector<uint8_t> &collided) {
        opx_batch_request request = OPX_BATCH_REQUEST_INIT;
        request.max_threads = threads;
        const size_t count = robot.configurations.size(), joints = robot.configurations.front().joints.size();
        Split split;
        split.query_ms = paper_tables::time_once_ms([&] {
            check_opx(opx_query_check_configurations(query.get(), tree, robot.links.get(), rows->data(), count, joints,
                                                     0, nullptr, 0, 0, &request, collided.data(), nullptr, count),
                      "opx_query_check_configurations");
        });
        return split;
    };
}

Pipeline fcl_pipeline(Robot &robot, paper_tables::FclManager &objects) {
    return [&robot, &objects](std::vector<uint8_t> &collided) {
        Split split;
        for (size_t i = 0; i < robot.configurations.size(); ++i) {
            const Clock::time_point start = Clock::now();
            robot.fcl->set_link_poses(robot.configurations[i].poses);
            const Clock::time_point posed = Clock::now();
            const bool hit = paper_tables::fcl_managers_collide(robot.fcl->manager(), objects);
            const Clock::time_point done = Clock::now();
            split.pose_ms += milliseconds_between(start, posed);
            split.query_ms += milliseconds_between(posed, done);
            collided[i] = hit ? 1 : 0;
        }
        return split;
    };
}

std::vector<Timing> time_interleaved(size_t configurations, int rounds, const std::vector<Pipeline> &pipelines) {
    const size_t n = pipelines.size();
    std::vector<Timing> timings(n);
    std::vector<std::vector<double>> pose_us(n), query_us(n);
    std::vector<uint8_t> scratch(configurations);
    for (size_t p = 0; p < n; ++p) {
        timings[p].collided.assign(configurations, 0);
        pipelines[p](timings[p].collided);
    }
    const double per = 1000.0 / double(configurations);
    for (int round = 0; round < rounds; ++round)
        for (size_t k = 0; k < n; ++k) {
            const size_t p = (k + size_t(round)) % n;
            const Split split = pipelines[p](scratch);
            pose_us[p].push_back(per * split.pose_ms);
            query_us[p].push_back(per * split.query_ms);
        }
    for (size_t p = 0; p < n; ++p) {
        timings[p].pose_us = paper_tables::median(pose_us[p]);
        timings[p].query_us = paper_tables::median(query_us[p]);
        timings[p].fastest_query_us = *std::min_element(query_us[p].begin(), query_us[p].end());
    }
    return timings;
}

double object_distance(Robot &robot, size_t i, const opx_world *world) {
    const std::shared_ptr<opx_query> query = query_with_world(world);
    forward_kinematics(robot, i);
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.signed_distance = 1;
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    check_opx(opx_query_distance(query.get(), nullptr, robot.links.get(), &request, &result), "opx_query_distance");
    return result.distance;
}

}  // namespace world_bench
