// The direct engine's distance query: nearest-first branch and bound over
// the octree, shape by shape, each shape entering the octree at the cubes
// its reach overlaps (cube_entry.hpp), with lower bounds from box
// distances in the octree's (map) frame tightened by the shape's own
// geometry, and exact leaf distances.  With unknown space as obstacle the
// robot's shape tree walks the octree from the root instead.
#pragma once

#include "octree/cube_entry.hpp"
#include "octree/octree_cell.hpp"
#include "octree/sensor_octree.hpp"
#include "query/distance_types.hpp"
#include "robot/linkset.hpp"

#include <vector>

namespace octoprox {

class DirectDistance {
public:
    // Minimum distance between the enabled links and the obstacle cells.
    DistanceOutcome run(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings);
    // The same, and the minimum of every link in per_link (infinity for a
    // link with nothing within the cutoff, or disabled).
    DistanceOutcome run_per_link(const SensorOctree &tree, const LinkSet &links,
                                 const DistanceSettings &settings, std::vector<double> &per_link);

private:
    using Cell = OctreeCell;
    // Each round of search_shapes searches this many times farther.
    static constexpr double kRadiusGrowth = 4.0;
    // A child of the cell being descended, before its cube is rebuilt for
    // the recursion, with the bounds its lower bound was computed from
    // (bounding_box of the child cell).  No default member initializers,
    // so an array of eight costs nothing to set up (descend_octree is the
    // hottest function).
    struct Child {
        OctreeView::NodeRef node;
        double lower;
        int index;
        bool inner;  // the node has children
        Vec3 bounds_lo, bounds_hi;
    };

    void start(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings);
    void search(int32_t robot_node);
    void search_shapes();
    void search_round(CubeEntryFinder &entries);
    void search_shape_from_entries(CubeEntryFinder &entries, int32_t leaf);
    // `bounds`: where the cell's obstacles can lie (bounding_box(cell)), and
    // `inner`: its node has children; the caller, which bounded the pair
    // with them, computed both once.
    void recurse(const Cell &cell, const Aabb &bounds, bool inner, int32_t robot_node, double lower);
    void descend_octree(const Cell &cell, int32_t robot_node);
    // `box`: the cell's obstacle box (its bounds, a leaf's).
    void test_leaf_pair(const Cell &cell, const Aabb &box, const AabbTreeNode &robot);
    // Prune when the pair cannot bring the answer below the bound, or not
    // by more than the allowed error (slack_).  Inline, and from fields
    // set_bound keeps: the search asks it of every pair it bounds.
    bool can_prune(double lower) const {
        if (in_contact_) return lower > 0.0;  // signed, in contact: only overlapping pairs go deeper
        return lower >= bound_ || (slack_ > 0.0 && bound_ - lower <= slack_);
    }
    void set_bound(double bound);
    bool is_obstacle(const Cell &cell) const;
    double lower_bound(const AabbTreeNode &robot, const Aabb &cell) const;
    double box_lower_bound(const AabbTreeNode &robot, const Aabb &cell) const;
    Aabb bounding_box(const Cell &cell, bool inner) const { return obstacle_bounds(*view_, cell, model_, inner); }

    const OctreeView *view_ = nullptr;
    const LinkSet *links_ = nullptr;
    const AabbTreeNode *robot_ = nullptr;  // the link set's shape tree, read once per query
    const PlacedShape *placed_ = nullptr;
    DistanceSettings settings_;
    DistanceOutcome best_;
    double bound_ = 0.0;             // prune at or beyond this distance
    double slack_ = 0.0;             // abs_err / rel_err allowance, once a pair is found
    bool in_contact_ = false;        // signed, and the bound is at or below 0
    int32_t only_link_ = -1;         // per-link mode: the link searched
    ObstacleModel model_;            // inner boxes when they hold for this query; point extents
    // Scratch of search_shape_from_entries (never re-entered): as locals,
    // their cells and boxes were filled with empty boxes for every shape.
    CubeEntries entries_;
    Aabb entry_bounds_[8];
};

}  // namespace octoprox
