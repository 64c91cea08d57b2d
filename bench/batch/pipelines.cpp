#include "pipelines.hpp"

#include <functional>

#include "timing.hpp"

namespace batch_bench {
namespace {

using paper_tables::check_opx;

// Runs `run` once untimed, then `rounds` timed; per configuration.
Timing time_rounds(const Workload &work, const std::function<void(std::vector<uint8_t> &)> &run) {
    Timing timing;
    timing.collided.assign(work.set.count, 0);
    run(timing.collided);
    std::vector<double> us;
    std::vector<uint8_t> scratch(work.set.count);
    for (int r = 0; r < work.rounds; ++r)
        us.push_back(1000.0 * paper_tables::time_once_ms([&] { run(scratch); }) / double(work.set.count));
    timing.us_per_configuration = paper_tables::median(us);
    timing.fastest_us = *std::min_element(us.begin(), us.end());
    return timing;
}

paper_tables::OpxQueryPtr make_query() { return paper_tables::make_direct_query(); }

}  // namespace

Timing time_single_calls(const Workload &work) {
    const paper_tables::OpxQueryPtr query = make_query();
    opx_linkset *links = work.robot.links.get();
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 0;
    opx_self_collision_request self_request = OPX_SELF_COLLISION_REQUEST_INIT;
    self_request.max_contacts = 0;
    return time_rounds(work, [&](std::vector<uint8_t> &collided) {
        for (size_t i = 0; i < work.set.count; ++i) {
            check_opx(opx_linkset_set_joint_positions(links, work.set.row(i), work.set.joints, &work.set.base),
                      "opx_linkset_set_joint_positions");
            opx_collision_result result = OPX_COLLISION_RESULT_INIT;
            check_opx(opx_query_collide(query.get(), work.scene.tree.get(), links, &request, &result),
                      "opx_query_collide");
            if (!result.collided && work.self_collision) {
                opx_self_collision_result self = OPX_SELF_COLLISION_RESULT_INIT;
                check_opx(opx_query_self_collide(query.get(), links, &self_request, &self), "opx_query_self_collide");
                result.collided = self.collided;
            }
            collided[i] = static_cast<uint8_t>(result.collided);
        }
    });
}

Timing time_batch(const Workload &work, uint32_t threads) {
    const paper_tables::OpxQueryPtr query = make_query();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = threads;
    request.self_collision = work.self_collision ? 1 : 0;
    return time_rounds(work, [&](std::vector<uint8_t> &collided) {
        check_opx(opx_query_check_configurations(query.get(), work.scene.tree.get(), work.robot.links.get(),
                                                 work.set.rows.data(), work.set.count, work.set.joints, 0,
                                                 &work.set.base, 1, 0, &request, collided.data(), nullptr,
                                                 work.set.count),
                  "opx_query_check_configurations");
    });
}

// Per configuration: place the objects (untimed), then time world and self.
Timing time_fcl(const Workload &work, FclCheck &fcl, bool self_collision) {
    Timing timing;
    timing.collided.assign(work.set.count, 0);
    std::vector<double> us;
    for (int r = 0; r < work.rounds; ++r) {
        double total_ms = 0.0;
        for (size_t i = 0; i < work.set.count; ++i) {
            fcl.place(work.set.poses[i]);
            bool hit = false;
            total_ms += paper_tables::time_once_ms([&] { hit = fcl.world_collides() || (self_collision && fcl.self_collides()); });
            timing.collided[i] = hit ? 1 : 0;
        }
        us.push_back(1000.0 * total_ms / double(work.set.count));
    }
    timing.us_per_configuration = paper_tables::median(us);
    timing.fastest_us = *std::min_element(us.begin(), us.end());
    return timing;
}

namespace {

// Configurations a motion batch checks, by single motion calls (untimed).
double configurations_per_motion(const Workload &work, const std::vector<double> &goals, size_t count,
                                 const opx_motion_request &request) {
    const paper_tables::OpxQueryPtr query = make_query();
    uint64_t checked = 0;
    for (size_t m = 0; m < count; ++m) {
        opx_motion_result result = OPX_MOTION_RESULT_INIT;
        check_opx(opx_query_check_motion(query.get(), work.scene.tree.get(), work.robot.links.get(), work.set.row(m),
                                         goals.data() + m * work.set.joints, work.set.joints, &work.set.base,
                                         &request, &result),
                  "opx_query_check_motion");
        checked += result.configurations_checked;
    }
    return double(checked) / double(count);
}

}  // namespace

MotionTiming time_motions(const Workload &work, const std::vector<double> &goals, size_t count, uint32_t threads) {
    const paper_tables::OpxQueryPtr query = make_query();
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = kMotionResolution;
    request.self_collision = work.self_collision ? 1 : 0;
    request.max_threads = threads;
    std::vector<uint8_t> collided(count);
    auto run = [&] {
        check_opx(opx_query_check_motions(query.get(), work.scene.tree.get(), work.robot.links.get(),
                                          work.set.rows.data(), goals.data(), count, work.set.joints, 0,
                                          &work.set.base, 1, 0, &request, collided.data(), nullptr, count),
                  "opx_query_check_motions");
    };
    run();
    std::vector<double> ms;
    for (int r = 0; r < work.rounds; ++r) ms.push_back(paper_tables::time_once_ms(run));
    MotionTiming timing;
    timing.motions = count;
    for (uint8_t c : collided) timing.collided += c;
    const double median_ms = paper_tables::median(ms);
    timing.motions_per_second = 1000.0 * double(count) / median_ms;
    timing.configurations_per_motion = configurations_per_motion(work, goals, count, request);
    timing.us_per_configuration = 1000.0 * median_ms / (double(count) * timing.configurations_per_motion);
    return timing;
}

}  // namespace batch_bench
