// The query kinds of the fault tests as bare API calls, and records of what
// they answer and of the objects they must leave alone (maps, link sets).
#pragma once

#include "fault_record.hpp"

#include <octoprox/octoprox.h>

#include <vector>

namespace fault {

enum class QueryKind {
    kCollide,        // every contact, with penetration, and the cost
    kDistance,       // signed, per link
    kPath,           // with distance and cost
    kCollideBoxes,   // the caller boxes bound to the context
    kDistanceBoxes,
};
const char *query_kind_name(QueryKind kind);

struct QueryInputs {
    const opx_octree *tree = nullptr;
    const opx_linkset *links = nullptr;
    const opx_pose *path = nullptr;  // waypoint-major, one pose per link
    size_t waypoints = 0;
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
};

struct QueryOutputs {
    opx_collision_result collision = OPX_COLLISION_RESULT_INIT;
    opx_distance_result distance = OPX_DISTANCE_RESULT_INIT;
    opx_path_result path = OPX_PATH_RESULT_INIT;
};

// The API call alone (what a failing allocator is armed around).
opx_status call_query(QueryKind kind, opx_query *query, const QueryInputs &in, QueryOutputs &out);

// What the last call_query answered: its result struct and what the query
// holds (contacts, cost boxes, per-link distances).
void record_query(QueryKind kind, Record &record, const opx_query *query, const QueryOutputs &out);

// A context's stats without the timings (which differ run to run).
void record_query_stats(Record &record, opx_query *query);

// The map: its stats and its .ot image (every node's log-odds).
void record_map(Record &record, const opx_octree *tree);

// Every read a const map allows: options, stats, leaves of each class,
// classify at `probes` points, and both images.
void record_map_reads(Record &record, const opx_octree *tree, size_t probes);

// The link set: names, poses, shapes (with vertices and indices), joints.
void record_linkset(Record &record, const opx_linkset *links);

}  // namespace fault
