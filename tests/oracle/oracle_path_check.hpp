// opx_query_path against the oracle: per waypoint the collision oracle
// (oracle_check.hpp), the exact distance (oracle_min_distance.hpp) and the
// swept cost (oracle_swept_cost.hpp), then the path's answers compared:
// first colliding waypoint, minimum distance and its waypoint, total cost,
// number of swept cells and the costliest boxes kept.
#pragma once

#include "oracle_scenes.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

// One pose per link per waypoint: waypoints[w][link].
using Waypoints = std::vector<std::vector<opx_pose>>;

// The poses as the library reads them: `pose_stride` bytes from link to
// link, `waypoint_stride` from waypoint to waypoint (0: packed), the gaps
// filled with NaN (read by mistake, they would fail the call).
struct PoseBuffer {
    std::vector<double> storage;  // doubles: keeps every pose 8-byte aligned
    size_t pose_stride = 0, waypoint_stride = 0;
    const opx_pose *poses() const { return reinterpret_cast<const opx_pose *>(storage.data()); }
};
PoseBuffer pack_waypoints(const Waypoints &waypoints, size_t pose_stride, size_t waypoint_stride);

struct PathCase {
    const Scene *scene = nullptr;
    const RobotSpec *robot = nullptr;  // shapes, paddings, flags (link poses unused)
    Waypoints waypoints;
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    size_t pose_stride = 0, waypoint_stride = 0;
    std::string label;
};

// Counts and mismatches of one test; prints the first few in full.
class PathReport {
public:
    explicit PathReport(std::string name) : name_(std::move(name)) {}
    void mismatch(const std::string &message);
    int finish(double seconds) const;

    uint64_t paths = 0, waypoints = 0, collided = 0, stopped_early = 0;
    uint64_t distance_checks = 0, positive_distances = 0, curved_distance_checks = 0, cost_checks = 0, cost_cells = 0, sliver_cells = 0, kept_boxes = 0;
    uint64_t cost_paths_unused_vertices = 0, cost_paths_other = 0;
    uint64_t undecided_collisions = 0, undecided_costs = 0, special_checks = 0;
    uint64_t mismatches = 0;

private:
    std::string name_;
};

// Runs the path query and the oracle and compares; false on a mismatch.
bool check_path(opx_query *query, const opx_linkset *links, const PathCase &path_case, PathReport &report);

}  // namespace oracle
