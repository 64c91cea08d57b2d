// The stages of a frame and the pipelines opx-frame-bench times.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "heap_meter.hpp"

namespace frame_bench {

using bench::HeapDelta;
using bench::measure_heap;

// ingest_raycast feeds the map every query runs on; ingest_endpoints is
// timed on a second map of the same stream (the cheaper mode, reported
// beside it).  pose_update: moving the robot to each queried
// configuration (collision and distance); collision: the 1,000 collision
// queries; distance: the distance queries.
enum Stage { kIngestRaycast, kIngestEndpoints, kStructure, kPoseUpdate, kCollision, kDistance, kStageCount };
constexpr const char *kStageKeys[kStageCount] = {"ingest_raycast", "ingest_endpoints", "structure",
                                                 "pose_update",    "collision_queries", "distance_queries"};

enum Pipeline { kDirect, kAmortized, kFcl, kPipelineCount };
constexpr const char *kPipelineNames[kPipelineCount] = {"octoprox direct", "octoprox amortized", "FCL + OctoMap"};

// Milliseconds per stage of one frame.
using StageTimes = std::array<double, kStageCount>;

// Heap attributed to one part of a pipeline (a map, an engine): what it
// holds now and the most it ever held, counting the transient peak of
// each piece of work on top of what it held before.
struct HeapBook {
    long long held = 0;
    size_t high = 0;
    void add(const HeapDelta &delta) {
        const size_t before = held > 0 ? static_cast<size_t>(held) : 0;
        high = std::max(high, before + delta.peak_above_start);
        held += delta.retained;
    }
};

}  // namespace frame_bench
