// The oracle's own view of the map's cells: the known leaves (read through
// opx_octree_get_leaves), the obstacle rule, and the unknown cubes.
//
// Cell addressing (from the documented map geometry only: a cube of 2^16
// finest cells per axis centred on the origin): a node at depth d has edge
// size = resolution * 2^(16-d) and integer coordinates m in [0, 2^d) per
// axis; its centre is (m + 0.5 - 2^(d-1)) * size.  Its children are
// (d+1, 2m + bit).  Keys are recovered from reported centres by
// m = floor(centre / size + 2^(d-1)), robust to rounding (centres are at
// half-integers).
#pragma once

#include "oracle_geometry.hpp"

#include <octoprox/octoprox.h>

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace oracle {

struct CellKey {
    int depth = 0;
    int64_t x = 0, y = 0, z = 0;
    bool operator<(const CellKey &o) const {
        return std::tie(depth, x, y, z) < std::tie(o.depth, o.x, o.y, o.z);
    }
    bool operator==(const CellKey &o) const {
        return std::tie(depth, x, y, z) == std::tie(o.depth, o.x, o.y, o.z);
    }
};

// A known leaf, or an unknown cube (class OPX_CELL_UNKNOWN, probability 0.5).
struct MapCell {
    CellKey key;
    Cell cell;
    double size = 0.0;
    double probability = 0.5;
    float log_odds = 0.0f;  // float_logit(probability)
    int32_t cell_class = OPX_CELL_UNKNOWN;
    bool unknown() const { return cell_class == OPX_CELL_UNKNOWN; }
};

CellKey key_of(const double center[3], double size, double resolution);
MapCell cell_of_key(const CellKey &key, double resolution);  // an unknown cube
MapCell cell_of_leaf(const opx_leaf &leaf, double resolution);

// Every known leaf (OPX_MASK_ALL_KNOWN).
std::vector<opx_leaf> known_leaves(const opx_octree *tree);
opx_octree_options octree_options(const opx_octree *tree);

// Log-odds as the library keeps them: a float.  logit computed in double,
// then rounded.
float float_logit(double p);
// The probability the library reports for a float log-odds value.
double probability_of(float log_odds);

// Does every leaf's probability map back exactly to a float log-odds (so the
// obstacle rule below reproduces the library's float comparison), does its
// class follow from the octree's thresholds, and do its centre, size and
// depth match its key?  Prints the first failures.
bool check_leaves(const std::vector<opx_leaf> &leaves, const opx_octree_options &options);

// The request's threshold, or the octree's occupied_threshold when 0.
double effective_threshold(double request_threshold, const opx_octree_options &options);

// The obstacle rule of one request: a known cell is an obstacle when
// float_logit(p_leaf) >= float_logit(threshold) (the library compares float
// log-odds); an unknown cube when unknown space counts as occupied.
struct ObstacleRule {
    float threshold_log_odds = 0.0f;
    bool unknown_occupied = false;
    ObstacleRule(double threshold, int32_t unknown_policy)
        : threshold_log_odds(float_logit(threshold)), unknown_occupied(unknown_policy == OPX_UNKNOWN_OCCUPIED) {}
    bool operator()(const MapCell &cell) const {
        return cell.unknown() ? unknown_occupied : cell.log_odds >= threshold_log_odds;
    }
};

// The unknown cubes: the children of inner nodes (every ancestor of a known
// leaf) that are neither inner nodes nor known leaves.  The whole map cube
// (depth 0) when there is no leaf.
std::vector<MapCell> unknown_cubes(const std::vector<opx_leaf> &leaves, double resolution);

// Every cell of the map: the known leaves, then (with_unknown) the unknown cubes.
std::vector<MapCell> map_cells(const std::vector<opx_leaf> &leaves, double resolution, bool with_unknown);

}  // namespace oracle
