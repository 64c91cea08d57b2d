// The amortized engine (paper IV.A): the obstacle cells of one octree
// frame become boxes in a Morton-built tree (T_{1,1} + ~T_{1,2}), bound to
// the query context, refined a little by every query.  Collision, distance,
// cost and paths then run per robot shape over that tree, with the same
// exact kernels as the direct engine, so the answers are the same.
//
// Two more trees are built on the same frame only when a query first needs
// them, so plain collision and distance binds cost what they always did:
// the unknown cubes (missing children of inner nodes, at their own size),
// obstacles under OPX_UNKNOWN_OCCUPIED and cost inside the region; and the
// uncertain cells (free <= log-odds < threshold), cost only.
//
// A caller's own boxes (a "collision map" from another source) can stand in
// for the octree's cells: bind_boxes, then collide_boxes / distance_boxes.
#pragma once

#include "broadphase/box_tree.hpp"
#include "octree/cell_boxes.hpp"
#include "query/engine.hpp"

#include <vector>

namespace octoprox {

class ContactSink;

struct AmortizedOptions {
    uint32_t refine_steps = 1;  // root-to-leaf refinement paths per query and tree used
    int morton_bits = 10;       // lattice bits per axis
};

class AmortizedEngine final : public Engine {
public:
    explicit AmortizedEngine(const AmortizedOptions &options = AmortizedOptions()) : options_(options) {}

    // Builds the obstacle tree unless it already holds this frame at this
    // threshold and obstacle model (cubes or point extents).
    void bind(const SensorOctree &tree, float threshold_log_odds, bool point_extents);
    // Engine's queries (engine.hpp), over the trees bound to the frame.
    CollisionOutcome collide(const SensorOctree &tree, const LinkSet &links, const CollisionSettings &settings,
                             std::vector<Contact> &contacts) override;
    DistanceOutcome distance(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings,
                             std::vector<double> *per_link) override;
    CostCollector &cost() override { return cost_; }
    // sah_ratio computes the median split's cost once per build (a diagnostic).
    EngineStats stats() const override;

    // The caller's boxes instead of an octree frame, until the next bind.
    void bind_boxes(std::vector<Aabb> boxes);
    bool holds_caller_boxes() const { return caller_boxes_; }
    const Aabb &caller_box(size_t index) const { return obstacles_.cells.boxes[index]; }
    // Against the bound caller boxes: contacts give a box's center and
    // longest edge, class occupied, probability 1; the distance outcome
    // names the box in box_index.
    CollisionOutcome collide_boxes(const LinkSet &links, const CollisionSettings &settings,
                                   std::vector<Contact> &contacts);
    DistanceOutcome distance_boxes(const LinkSet &links, const DistanceSettings &settings,
                                   std::vector<double> *per_link);


private:
    // What a band's boxes were read from: rebuilt only when it changes.
    struct BandKey {
        uint64_t identity = 0, generation = 0;  // identity 0: nothing bound
        float threshold = 0.0f, free = 0.0f;
        bool point_extents = false;
        bool operator==(const BandKey &o) const {
            return identity == o.identity && generation == o.generation && threshold == o.threshold &&
                   free == o.free && point_extents == o.point_extents;
        }
    };
    // One band of a frame's cells (or the caller's boxes) and its tree.
    struct Band {
        CellBoxes cells;
        BoxTree tree;
        BandKey key;
        bool unknown = false;  // the unknown cubes (class unknown, probability 0.5)
    };
    // Returns the milliseconds the tree took (~T_{1,2}).
    double build_tree(Band &band);
    void bind_unknown(const SensorOctree &tree);
    void bind_uncertain(const SensorOctree &tree, float threshold_log_odds, float free_log_odds);
    void refine(Band &band) { band.tree.refine(options_.refine_steps); }
    void collect_cost(const LinkSet &links, const CollisionSettings &settings, uint64_t &narrow_tests);

    // The loops shared by octree cells and caller boxes, over the obstacle
    // band and, with_unknown, the unknown cubes; `describe` tells what an
    // item of a band is (cell or box): a CellSummary for a contact, the
    // best outcome's cell for distance.
    template <class Describe>
    CollisionOutcome collide_bound(const LinkSet &links, const CollisionSettings &settings, bool with_unknown,
                                   std::vector<Contact> &contacts, Describe &&describe);
    template <class Describe>
    void collide_band(const Band &band, const PlacedShape &shape, ContactSink &sink, Describe &&describe);
    template <class Describe>
    DistanceOutcome distance_bound(const LinkSet &links, const DistanceSettings &settings, bool with_unknown,
                                   std::vector<double> *per_link, Describe &&describe);
    template <class Describe>
    void distance_band(const Band &band, const PlacedShape &shape, const DistanceSettings &settings,
                       std::vector<double> *per_link, double &bound, DistanceOutcome &best, Describe &&describe);

    AmortizedOptions options_;
    Band obstacles_;  // cells at or above the threshold, or the caller's boxes
    Band unknown_;    // built on first need (unknown occupied, or cost)
    Band uncertain_;  // built on first need (cost)
    CostCollector cost_;
    uint64_t builds_ = 0;
    bool caller_boxes_ = false;  // obstacles_.cells.boxes are the caller's (keys, log-odds unused)
    double extract_ms_ = 0.0, build_ms_ = 0.0;
};

}  // namespace octoprox
