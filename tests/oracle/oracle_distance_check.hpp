// One distance request checked against the brute-force distance oracle
// (oracle_nearest.hpp): the value, the found/collided flags, the cutoff and
// the allowed error, the reported link/shape/cell and witness points, and
// the per-link minima.
#pragma once

#include "oracle_nearest.hpp"

#include <string>

namespace oracle {

// Tolerances: polytope kernels are exact to rounding; cylinders to GJK's
// stopping rule (docs/geometry.md), checked at 1e-6 m, or at
// kCurvedAmbiguity when the oracle itself needed prism brackets.
constexpr double kExactTolerance = 1e-9;
constexpr double kCurvedTolerance = 1e-6;

// The state of the world one oracle answer is about.
struct DistanceCase {
    const RobotSpec *robot = nullptr;
    const std::vector<PlacedShape> *placed = nullptr;
    const CellIndex *cells = nullptr;
    const NearestAnswer *oracle = nullptr;
    const ObstacleRule *rule = nullptr;  // the request's obstacle rule
    double resolution = 0.0;
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
    double threshold = 0.0;  // the request's (0: the octree's)
    std::string label;
};

// What varies between requests on one state.
struct DistanceVariant {
    double abs_err = 0.0, rel_err = 0.0;
    double cutoff = 0.0;  // 0: none
    bool per_link = false;
};

class DistanceChecker {
public:
    explicit DistanceChecker(std::string test_name) : name_(std::move(test_name)) {}

    // Runs opx_query_distance and compares; false on a mismatch.
    bool check(opx_query *query, const opx_octree *tree, const opx_linkset *links, const DistanceCase &c,
               const DistanceVariant &v);
    void fail(const std::string &message);
    // Prints the summary line; returns the exit code.
    int finish(double seconds) const;
    uint64_t queries() const { return queries_; }

private:
    void check_found(const DistanceCase &c, const DistanceVariant &v, const opx_distance_result &r);
    void check_pair(const DistanceCase &c, const DistanceVariant &v, const opx_distance_result &r);
    void check_witness(const DistanceCase &c, const DistanceVariant &v, const PlacedShape &shape,
                       const MapCell &cell, const opx_distance_result &r, double tolerance);
    void check_per_link(opx_query *query, const DistanceCase &c, const DistanceVariant &v,
                        const opx_distance_result &r);
    void mismatch(const DistanceCase &c, const DistanceVariant &v, const opx_distance_result *r,
                  const std::string &what);
    void record_error(double error, bool curved);

    std::string name_;
    uint64_t queries_ = 0, mismatches_ = 0, found_ = 0, collided_ = 0, beyond_cutoff_ = 0, approximate_ = 0;
    uint64_t per_link_ = 0, ambiguous_cutoff_ = 0, doubtful_ = 0, unknown_cells_ = 0, ties_ = 0;
    double max_exact_error_ = 0.0, max_curved_error_ = 0.0;
    bool failed_ = false;
};

// The tolerance for a minimum `value` of the answer: cylinders within
// kCurvedTolerance of it loosen it.  link < 0: over all links.
double tolerance_near(const NearestAnswer &answer, double value, int link = -1);

std::string describe_robot(const RobotSpec &robot);

}  // namespace oracle
