// The amortized engine (paper IV.A): the obstacle cells of one octree
// frame become boxes in a Morton-built tree (T_{1,1} + ~T_{1,2}), bound to
// the query context, refined a little by every query.  Collision and
// distance then run per robot shape over that tree, with the same exact
// kernels as the direct engine, so the answers are the same.  A caller's
// own boxes (a "collision map" from another source) can stand in for the
// octree's cells: bind_boxes, then collide_boxes / distance_boxes.
#pragma once

#include "broadphase/box_tree.hpp"
#include "broadphase/cell_boxes.hpp"
#include "octree/sensor_octree.hpp"
#include "query/collision_types.hpp"
#include "query/distance_types.hpp"
#include "robot/linkset.hpp"

#include <vector>

namespace octoprox {

struct AmortizedOptions {
    uint32_t refine_steps = 1;  // root-to-leaf refinement paths per query
    int morton_bits = 10;       // lattice bits per axis
};

struct AmortizedStats {
    uint64_t boxes = 0;
    uint64_t builds = 0;
    uint64_t refine_steps_done = 0;
    double extract_ms = 0.0;  // last bind: cells to boxes (T_{1,1})
    double build_ms = 0.0;    // last bind: boxes to tree (~T_{1,2})
};

class AmortizedEngine {
public:
    explicit AmortizedEngine(const AmortizedOptions &options = AmortizedOptions()) : options_(options) {}

    // Builds the tree unless it already holds this frame at this threshold.
    void bind(const SensorOctree &tree, float threshold_log_odds);
    CollisionOutcome collide(const SensorOctree &tree, const LinkSet &links, const CollisionSettings &settings,
                             std::vector<Contact> &contacts);
    DistanceOutcome distance(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings,
                             std::vector<double> *per_link);

    // The caller's boxes instead of an octree frame, until the next bind.
    void bind_boxes(std::vector<Aabb> boxes);
    bool holds_caller_boxes() const { return caller_boxes_; }
    const Aabb &caller_box(size_t index) const { return cells_.boxes[index]; }
    // Against the bound caller boxes: contacts give a box's center and
    // longest edge, class occupied, probability 1; the distance outcome
    // names the box in box_index.
    CollisionOutcome collide_boxes(const LinkSet &links, const CollisionSettings &settings,
                                   std::vector<Contact> &contacts);
    DistanceOutcome distance_boxes(const LinkSet &links, const DistanceSettings &settings,
                                   std::vector<double> *per_link);

    AmortizedStats stats() const;
    double sah_ratio() { return tree_.empty() ? 1.0 : tree_.sah_ratio(); }

private:
    void refine() { tree_.refine(options_.refine_steps); }
    void build_tree();
    // The loops shared by octree cells and caller boxes; `describe` fills
    // what an item is (cell or box) into a contact / the best outcome.
    template <class Describe>
    CollisionOutcome collide_bound(const LinkSet &links, const CollisionSettings &settings,
                                   std::vector<Contact> &contacts, Describe &&describe);
    template <class Describe>
    DistanceOutcome distance_bound(const LinkSet &links, const DistanceSettings &settings,
                                   std::vector<double> *per_link, Describe &&describe);

    AmortizedOptions options_;
    BoxTree tree_;
    CellBoxes cells_;
    uint64_t bound_identity_ = 0, bound_generation_ = 0;
    float bound_threshold_ = 0.0f;
    uint64_t builds_ = 0;
    bool caller_boxes_ = false;  // cells_.boxes are the caller's (keys, log-odds unused)
    double extract_ms_ = 0.0, build_ms_ = 0.0;
};

}  // namespace octoprox
