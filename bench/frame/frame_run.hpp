// One run of opx-frame-bench: one stream at one resolution, `frames`
// frames, every pipeline doing every stage of every frame:
//   octoprox direct     ingest (OpxMaps), no structure, per configuration
//                       opx_linkset_set_joint_positions (FK included) then
//                       opx_query_collide; distance: opx_query_distance
//   octoprox amortized  the same ingest (the same map: its time counts for
//                       both), structure = the query that binds the new map
//                       (cells to boxes to the Morton tree; it also answers
//                       one collision query), then as direct
//   FCL + OctoMap       ingest (OctomapMaps), structure = wrapping the tree
//                       as an fcl::OcTree object, per configuration the FK
//                       result set on the robot's objects (FCL has no FK:
//                       it is computed once, untimed) then FCL's octree
//                       collision / distance against the PR2 (pr2_fcl.hpp)
// Per configuration the three pipelines take turns (the order rotates), so
// a change of the machine's load hits them alike.  After the single calls,
// each octoprox engine checks the same 1,000 configurations again in one
// batch call on every core (opx_query_check_configurations), timed apart.
#pragma once

#include <string>
#include <vector>

#include "frame_maps.hpp"
#include "frame_stages.hpp"
#include "frame_stream.hpp"
#include "pr2_configurations.hpp"
#include "pr2_fcl.hpp"

namespace frame_bench {

struct RunPlan {
    double resolution = 0.05;      // m
    int frames = 1;
    int distance_queries = 10;     // per frame and pipeline
    int fcl_distance_queries = 10; // FCL measures only the first this many (its distance stage is scaled)
};

// The PR2 on both sides and the configurations, drawn once for a stream
// (same set for every pipeline, resolution and frame).
struct Robot {
    opx_linkset *links = nullptr;        // octoprox direct's PR2
    opx_linkset *links_amortized = nullptr;  // a clone: each engine moves its own robot, as each thread would
    paper_tables::FclRobot *fcl = nullptr;
    std::vector<paper_tables::Configuration> configurations;  // link poses at the stream's base
    opx_pose base = OPX_POSE_IDENTITY;
};

// Agreement of the pipelines' answers over all frames.
struct Checks {
    long long collision_compared = 0, collision_mismatches = 0, collided = 0;  // collided: per octoprox direct
    int distance_compared = 0, fcl_distance_compared = 0, fcl_distance_off = 0;
    int distance_free = 0;             // of the distance configurations, how many are collision-free (frame 0)
    double engines_distance_gap = 0.0; // max |direct - amortized|, m
    double fcl_distance_gap = 0.0;     // max |direct - FCL|, m
    long long batch_mismatches = 0;    // batch answers that differ from the single calls'
    bool ok() const;
};

struct RunResult {
    std::string stream;
    RunPlan plan;
    int configurations = 0;
    std::vector<std::array<StageTimes, kPipelineCount>> frames;  // [frame][pipeline], ms
    // [frame][pipeline]: the same configurations in one
    // opx_query_check_configurations call on every core (forward
    // kinematics included), ms; 0 for FCL, which has no such call.
    std::vector<std::array<double, kPipelineCount>> batch_ms;
    TreeMemory opx_raycast, opx_endpoints, octomap_raycast, octomap_endpoints;  // after the last frame
    size_t heap_high[kPipelineCount] = {0, 0, 0};  // the ray-cast map + the engine, bytes
    size_t opx_endpoints_heap_high = 0, octomap_endpoints_heap_high = 0;
    Checks checks;
};

RunResult run_frames(Stream &stream, Robot &robot, const RunPlan &plan);

// Distances that agree (m); FCL's octree distance has known errors
// (fcl#639, fcl#640) and libccd stops at 1e-6, so FCL is only counted.
constexpr double kDistanceTolerance = 1e-6;

}  // namespace frame_bench
