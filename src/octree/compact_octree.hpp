// The octree laid out for queries: every node in one array, the children
// of a node next to each other (breadth first), 24 bytes a node.  OctoMap
// keeps one heap block per node and per child array, so a query walking
// it misses the cache at nearly every step.  This copy is rebuilt from the
// OctoMap tree, in one pass, by the first query (or stats) after the map
// changed (insert, load, clear): once per sensor frame, whatever the
// number of insert calls that made it.
//
// Each node also keeps the key bounds of the obstacle leaves below it
// (log-odds at or above the map's occupancy threshold): an octant that
// holds one occupied cell is then bounded by that cell, not by its cube,
// which lets distance queries prune whole subtrees early.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace octomap {
class OcTree;
}

namespace octoprox {

// Bits set in a byte (a table: the portable builtin is a library call
// on CPUs without POPCNT).
extern const uint8_t kBitsInByte[256];

struct CompactNode {
    float log_odds = 0.0f;     // a leaf's own; an inner node's: the maximum of its children
    uint8_t child_mask = 0;    // bit i: child i exists (observed space)
    uint8_t has_obstacle = 0;  // an obstacle leaf lies at or below this node
    uint16_t obstacle_lo[3] = {0, 0, 0};  // finest-depth keys of the obstacle leaves:
    uint16_t obstacle_hi[3] = {0, 0, 0};  // lowest and highest cell, both inclusive
    uint32_t first_child = 0;  // index of the lowest existing child
};

class CompactOctree {
public:
    // Lays out `tree`; obstacles are leaves with log-odds >= obstacle_log_odds.
    void rebuild(const octomap::OcTree &tree, float obstacle_log_odds);
    void clear() { nodes_.clear(); }

    const CompactNode *root() const { return nodes_.empty() ? nullptr : nodes_.data(); }
    const CompactNode *child(const CompactNode *node, int index) const {
        const unsigned mask = node->child_mask;
        if (((mask >> index) & 1u) == 0) return nullptr;
        const unsigned before = mask & ((1u << index) - 1u);
        return nodes_.data() + node->first_child + kBitsInByte[before];
    }
    float obstacle_log_odds() const { return obstacle_log_odds_; }
    size_t node_count() const { return nodes_.size(); }
    size_t memory_bytes() const { return nodes_.capacity() * sizeof(CompactNode); }

private:
    std::vector<CompactNode> nodes_;
    float obstacle_log_odds_ = 0.0f;
};

}  // namespace octoprox
