#include "self_rows.hpp"

#include "timing.hpp"

#include <algorithm>

namespace batch_bench {
namespace {

using paper_tables::check_opx;

// Microseconds per configuration of `check(i)` over [0, count), each
// configuration posed first outside the timing; the median of the rounds.
template <class Pose, class Check>
double us_per_call(size_t count, int rounds, Pose &&pose, Check &&check) {
    std::vector<double> us;
    for (int round = 0; round < rounds; ++round) {
        double ms = 0.0;
        for (size_t i = 0; i < count; ++i) {
            pose(i);
            ms += paper_tables::time_once_ms([&] { check(i); });
        }
        us.push_back(1000.0 * ms / double(count));
    }
    return paper_tables::median(us);
}

}  // namespace

SelfTiming time_self_calls(Robot &robot, const ConfigurationSet &set, FclCheck &fcl, size_t distance_count,
                           int rounds) {
    opx_linkset *links = robot.links.get();
    const paper_tables::OpxQueryPtr query = paper_tables::make_direct_query();
    auto pose = [&](size_t i) {
        check_opx(opx_linkset_set_joint_positions(links, set.row(i), set.joints, &set.base),
                  "opx_linkset_set_joint_positions");
    };
    SelfTiming t;
    t.configurations = set.count;
    t.distance_configurations = std::min(distance_count, set.count);
    std::vector<uint8_t> collided(set.count), fcl_collided(set.count);
    opx_self_collision_request yes_no = OPX_SELF_COLLISION_REQUEST_INIT;
    yes_no.max_contacts = 0;
    t.collide_us = us_per_call(set.count, rounds, pose, [&](size_t i) {
        opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
        check_opx(opx_query_self_collide(query.get(), links, &yes_no, &result), "opx_query_self_collide");
        collided[i] = static_cast<uint8_t>(result.collided);
    });
    const opx_self_distance_request nearest = OPX_SELF_DISTANCE_REQUEST_INIT;
    t.distance_us = us_per_call(t.distance_configurations, rounds, pose, [&](size_t) {
        opx_self_distance_result result = OPX_SELF_DISTANCE_RESULT_INIT;
        check_opx(opx_query_self_distance(query.get(), links, &nearest, &result), "opx_query_self_distance");
    });
    t.fcl_collide_us = us_per_call(
        set.count, rounds, [&](size_t i) { fcl.place(set.poses[i]); },
        [&](size_t i) { fcl_collided[i] = fcl.self_collides() ? 1 : 0; });
    t.collided = size_t(std::count(collided.begin(), collided.end(), 1));
    t.fcl_collided = size_t(std::count(fcl_collided.begin(), fcl_collided.end(), 1));
    for (size_t i = 0; i < set.count; ++i) t.differ += collided[i] != fcl_collided[i];
    return t;
}

}  // namespace batch_bench
