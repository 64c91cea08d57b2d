// The configurations opx-bench-batch checks: for the PR2, Table IV's
// reaching configurations (both arms around a forward reach, +-0.5 rad per
// joint, within the URDF limits); for the arms, every joint uniform within
// its limits.  Each with its link poses after FK (for FCL, untimed), and
// motions from each configuration part of the way to the next one.
#pragma once

#include <cstdint>
#include <vector>

#include "bench_scene.hpp"

namespace batch_bench {

struct ConfigurationSet {
    size_t count = 0, joints = 0;
    std::vector<double> rows;                     // count x joints, model order
    std::vector<std::vector<opx_pose>> poses;     // per row, every link (map frame); with_poses only
    opx_pose base = OPX_POSE_IDENTITY;            // the root link, map frame
    const double *row(size_t i) const { return rows.data() + i * joints; }
};

ConfigurationSet draw_configurations(Robot &robot, const opx_pose &base, size_t count, uint64_t seed,
                                     bool with_poses);

// Motion i goes from row i to start + kMotionShare (row i+1 - row i): short
// joint-space edges as a sampling planner makes them.
constexpr double kMotionShare = 0.3;
std::vector<double> motion_goals(const ConfigurationSet &set);

}  // namespace batch_bench
