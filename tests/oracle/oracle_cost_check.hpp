// One cost request (opx_query_collide with compute_cost = 1) checked
// against the cost oracle (oracle_cost.hpp) and the collision oracle: the
// total cost, the number of (link, cell) boxes, the kept boxes (the K
// costliest, compared as a multiset of costs) and their fields; obstacles
// still reported as contacts and never as cost boxes; the same collided
// answer and contacts as the request without cost.
#pragma once

#include "oracle_check.hpp"
#include "oracle_cost.hpp"

#include <string>

namespace oracle {

struct CostCase {
    const RobotSpec *robot = nullptr;
    const std::vector<PlacedShape> *placed = nullptr;
    const CellIndex *cells = nullptr;
    const CostAnswer *oracle = nullptr;
    const CostSettings *settings = nullptr;  // the oracle's settings (diagnostics)
    const OracleAnswer *contacts = nullptr;  // the collision oracle, same threshold and policy
    double resolution = 0.0;
    std::string label;
};

struct CostVariant {
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
    double threshold = 0.0;  // 0: the octree's
    uint32_t max_contacts = UINT32_MAX;
    uint32_t max_cost_boxes = 16;
    double unknown_probability = 0.5;
    bool region_set = false;  // else the zeros: the known bounds
    AlignedBox region;
};

class CostChecker {
public:
    explicit CostChecker(std::string test_name) : name_(std::move(test_name)) {}
    bool check(opx_query *query, const opx_octree *tree, const opx_linkset *links, const CostCase &c,
               const CostVariant &v);
    void fail(const std::string &message);
    int finish(double seconds) const;
    uint64_t queries() const { return queries_; }

private:
    opx_collision_result ask(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                             const CostVariant &v, bool cost, std::vector<opx_contact> &contacts);
    void check_totals(const CostCase &c, const CostVariant &v, const opx_collision_result &r);
    void check_boxes(opx_query *query, const CostCase &c, const CostVariant &v, const opx_collision_result &r);
    void check_box_fields(const CostCase &c, const CostVariant &v, const opx_cost_box &box);
    void check_contacts(const CostCase &c, const CostVariant &v, const opx_collision_result &with_cost,
                        const std::vector<opx_contact> &contacts, const opx_collision_result &without_cost,
                        const std::vector<opx_contact> &plain_contacts);
    void mismatch(const CostCase &c, const CostVariant &v, const std::string &what);

    std::string name_;
    uint64_t queries_ = 0, mismatches_ = 0, pairs_ = 0, uncertain_ = 0, unknown_ = 0, flat_ = 0;
    uint64_t ambiguous_queries_ = 0, kept_ = 0, zero_boxes_ = 0, collided_ = 0, truncated_ = 0;
    double max_relative_error_ = 0.0;
    bool failed_ = false;
};

}  // namespace oracle
