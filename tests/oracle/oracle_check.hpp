// One query checked against the oracle: the brute-force answer (every
// placed shape vs every obstacle cell), the library's answers through the
// C ABI (yes/no, all contacts, truncated lists) and their comparison.
#pragma once

#include "oracle_cells.hpp"
#include "oracle_index.hpp"
#include "oracle_robot.hpp"

#include <octoprox/octoprox.h>

#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace oracle {

// A contact as the library reports it: one per (link, shape, cell).
struct Triple {
    uint32_t link = 0, shape = 0;
    CellKey cell;
    bool operator<(const Triple &o) const {
        return std::tie(link, shape, cell) < std::tie(o.link, o.shape, o.cell);
    }
};

struct PairRecord {
    const PlacedShape *shape = nullptr;
    const MapCell *cell = nullptr;
    double distance = 0.0;  // core to cell; compare with shape->inflation
};

struct OracleAnswer {
    std::map<Triple, PairRecord> touching;   // distance <= inflation (+ tolerance)
    std::map<Triple, PairRecord> ambiguous;  // too close to the threshold to call
};

// Brute force: every placed shape against every obstacle cell near it (a
// mesh: every triangle against every obstacle cell near the triangle).
OracleAnswer oracle_collide(const std::vector<PlacedShape> &placed, const CellIndex &cells,
                            const ObstacleRule &rule);

// Everything one comparison needs to know and to print.
struct QueryCase {
    const RobotSpec *robot = nullptr;
    const std::vector<PlacedShape> *placed = nullptr;
    const CellIndex *cells = nullptr;  // the map's cells (unknown cubes too, when needed)
    double resolution = 0.0;
    double occupied_threshold = 0.5;  // the octree's
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
    double threshold = 0.0;  // the request's (0: the octree's)
    std::string label;       // e.g. "scene 3 query 17 (seed 42)"
};

class Checker {
public:
    explicit Checker(std::string test_name) : name_(std::move(test_name)) {}

    // Runs the library queries for `query_case`, the oracle, and compares.
    // Returns false on a mismatch (the first few are printed in full).
    bool check(opx_query *query, const opx_octree *tree, const opx_linkset *links, const QueryCase &query_case);

    // A mismatch found elsewhere (e.g. by a test's own expectation).
    void fail(const std::string &message);

    // Prints the summary line; returns the exit code (0, or 1 on mismatches).
    int finish(double seconds) const;

    uint64_t queries() const { return queries_; }
    uint64_t mismatches() const { return mismatches_; }
    uint64_t collided_queries() const { return collided_; }

private:
    struct LibraryAnswer;
    LibraryAnswer ask(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                      const QueryCase &query_case, uint32_t max_contacts);
    void compare_collided(const QueryCase &c, const OracleAnswer &oracle, const LibraryAnswer &lib,
                          const char *call);
    void compare_contacts(const QueryCase &c, const OracleAnswer &oracle, const LibraryAnswer &lib);
    void check_contact_fields(const QueryCase &c, const opx_contact &contact);
    void check_truncation(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                          const QueryCase &c, const OracleAnswer &oracle, uint64_t total);
    void report_pair(const QueryCase &c, const Triple &t, const char *what, const char *library_says);
    void mismatch(const std::string &message);

    std::string name_;
    uint64_t queries_ = 0, mismatches_ = 0, collided_ = 0, contacts_ = 0, coarse_contacts_ = 0, unknown_contacts_ = 0;
    uint64_t ambiguous_by_kind_[7] = {}, ambiguous_pairs_ = 0, ambiguous_queries_ = 0, truncation_checks_ = 0;
    uint64_t max1_truncated_ = 0, max0_truncated_ = 0;
    bool query_failed_ = false;
};

// The path of a shared data file ($OPX_DATA_DIR, else OPX_DEFAULT_DATA_DIR);
// "" after printing "SKIP: ..." when it is absent (the test then exits 77);
// with OPX_REQUIRE_DATA=1 (CI sets it) absent data fails the test (exit 1).
std::string data_path(const char *relative);

// An unsigned integer from the environment (e.g. OPX_ORACLE_SEED), else `fallback`.
uint64_t env_number(const char *name, uint64_t fallback);

// Seconds since the first call (a test's wall clock).
double elapsed_seconds();

}  // namespace oracle
