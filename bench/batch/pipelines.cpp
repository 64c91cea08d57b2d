#include "pipelines.hpp"

#include <algorithm>
#include <functional>
#include <memory>

#include "timing.hpp"

namespace batch_bench {
namespace {

using paper_tables::check_opx;

paper_tables::OpxQueryPtr make_query() { return paper_tables::make_direct_query(); }

// `run` over the set, timed whole.
template <class Run>
double timed_ms(Run &&run) {
    return paper_tables::time_once_ms(run);
}

}  // namespace

std::vector<Timing> time_interleaved(const Workload &work, const std::vector<Pipeline> &pipelines) {
    const size_t n = pipelines.size(), count = work.set.count;
    std::vector<Timing> timings(n);
    std::vector<std::vector<double>> us(n);
    std::vector<uint8_t> scratch(count);
    for (size_t p = 0; p < n; ++p) {
        timings[p].collided.assign(count, 0);
        pipelines[p](timings[p].collided, 0, count);
    }
    for (int round = 0; round < work.rounds; ++round)
        for (size_t k = 0; k < n; ++k) {
            const size_t p = (k + size_t(round)) % n;
            us[p].push_back(1000.0 * pipelines[p](scratch, 0, count) / double(count));
        }
    for (size_t p = 0; p < n; ++p) {
        timings[p].us_per_configuration = paper_tables::median(us[p]);
        timings[p].fastest_us = *std::min_element(us[p].begin(), us[p].end());
    }
    return timings;
}

Pipeline single_calls(const Workload &work) {
    std::shared_ptr<opx_query> query = make_query();
    return [&work, query](std::vector<uint8_t> &collided, size_t begin, size_t end) {
        opx_linkset *links = work.robot.links.get();
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        request.max_contacts = 0;
        opx_self_collision_request self_request = OPX_SELF_COLLISION_REQUEST_INIT;
        self_request.max_contacts = 0;
        return timed_ms([&] {
            for (size_t i = begin; i < end; ++i) {
                check_opx(opx_linkset_set_joint_positions(links, work.set.row(i), work.set.joints, &work.set.base),
                          "opx_linkset_set_joint_positions");
                opx_collision_result result = OPX_COLLISION_RESULT_INIT;
                check_opx(opx_query_collide(query.get(), work.scene.tree.get(), links, &request, &result),
                          "opx_query_collide");
                if (!result.collided && work.self_collision) {
                    opx_self_collision_result self = OPX_SELF_COLLISION_RESULT_INIT;
                    check_opx(opx_query_self_collide(query.get(), links, &self_request, &self),
                              "opx_query_self_collide");
                    result.collided = self.collided;
                }
                collided[i] = static_cast<uint8_t>(result.collided);
            }
        });
    };
}

Pipeline batch_call(const Workload &work, uint32_t threads) {
    std::shared_ptr<opx_query> query = make_query();
    return [&work, query, threads](std::vector<uint8_t> &collided, size_t begin, size_t end) {
        opx_batch_request request = OPX_BATCH_REQUEST_INIT;
        request.max_threads = threads;
        request.self_collision = work.self_collision ? 1 : 0;
        return timed_ms([&] {
            check_opx(opx_query_check_configurations(query.get(), work.scene.tree.get(), work.robot.links.get(),
                                                     work.set.row(begin), end - begin, work.set.joints, 0,
                                                     &work.set.base, 1, 0, &request, collided.data() + begin,
                                                     nullptr, end - begin),
                      "opx_query_check_configurations");
        });
    };
}

// Per configuration: place the objects (untimed), then time world and self.
Pipeline fcl_calls(const Workload &work, FclCheck &fcl) {
    return [&work, &fcl](std::vector<uint8_t> &collided, size_t begin, size_t end) {
        double total_ms = 0.0;
        for (size_t i = begin; i < end; ++i) {
            fcl.place(work.set.poses[i]);
            bool hit = false;
            total_ms += paper_tables::time_once_ms([&] { hit = fcl.world_collides() || fcl.self_collides(); });
            collided[i] = hit ? 1 : 0;
        }
        return total_ms;
    };
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
