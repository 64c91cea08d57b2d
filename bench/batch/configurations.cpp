#include "configurations.hpp"

#include "pr2_configurations.hpp"
#include "rng.hpp"
#include "scene.hpp"

namespace batch_bench {
namespace {

using paper_tables::check_opx;

std::vector<opx_pose> poses_after_fk(opx_linkset *links, const double *q, size_t joints, const opx_pose &base) {
    check_opx(opx_linkset_set_joint_positions(links, q, joints, &base), "opx_linkset_set_joint_positions");
    return paper_tables::link_poses(links);
}

void draw_arm_rows(const Robot &robot, ConfigurationSet &set, uint64_t seed) {
    paper_tables::Rng rng(seed);
    for (size_t i = 0; i < set.count; ++i) {
        for (uint32_t j = 0; j < set.joints; ++j) {
            opx_joint_info info = OPX_JOINT_INFO_INIT;
            check_opx(opx_linkset_get_joint_info(robot.links.get(), j, &info), "opx_linkset_get_joint_info");
            set.rows.push_back(info.has_limits ? rng.uniform(info.lower, info.upper) : 0.0);
        }
    }
}

}  // namespace

ConfigurationSet draw_configurations(Robot &robot, const opx_pose &base, size_t count, uint64_t seed,
                                     bool with_poses) {
    ConfigurationSet set;
    set.count = count, set.joints = robot.joints, set.base = base;
    set.rows.reserve(count * set.joints);
    if (robot.name == "PR2") {
        for (const auto &c : paper_tables::draw_reaching_configurations(robot.links.get(), static_cast<int>(count),
                                                                        seed, base)) {
            set.rows.insert(set.rows.end(), c.joints.begin(), c.joints.end());
            if (with_poses) set.poses.push_back(c.poses);
        }
        return set;
    }
    draw_arm_rows(robot, set, seed);
    if (with_poses)
        for (size_t i = 0; i < count; ++i)
            set.poses.push_back(poses_after_fk(robot.links.get(), set.row(i), set.joints, base));
    return set;
}

std::vector<double> motion_goals(const ConfigurationSet &set) {
    std::vector<double> goals(set.rows.size());
    for (size_t i = 0; i < set.count; ++i) {
        const double *a = set.row(i), *b = set.row((i + 1) % set.count);
        for (size_t j = 0; j < set.joints; ++j) goals[i * set.joints + j] = a[j] + kMotionShare * (b[j] - a[j]);
    }
    return goals;
}

}  // namespace batch_bench
