// What a query engine answers, whichever it is: the direct engine
// (query/direct/) walks the octree as it is; the amortized engine
// (query/amortized/) builds boxes of a frame's cells into a tree once and
// reuses it.  Both give the same answers; the query context
// (query/context.hpp) holds one, chosen when it is made.
#pragma once

#include "octree/sensor_octree.hpp"
#include "query/collision_types.hpp"
#include "query/cost_collector.hpp"
#include "query/distance_types.hpp"
#include "robot/linkset.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

// What an engine holds; zeros for the direct engine, which holds nothing
// between queries.
struct EngineStats {
    uint64_t boxes = 0;              // obstacle boxes (cells at or above the threshold, or caller boxes)
    uint64_t builds = 0;             // trees built: obstacle, uncertain and unknown
    uint64_t refine_steps_done = 0;  // on the obstacle tree
    double sah_ratio = 0.0;          // obstacle tree's surface-area cost over a median split's
    double extract_ms = 0.0;         // last obstacle bind: cells to boxes (T_{1,1})
    double build_ms = 0.0;           // last obstacle bind: boxes to tree (~T_{1,2})
};

class Engine {
public:
    virtual ~Engine() = default;

    // Clears and fills `contacts` (capacity kept: warm queries allocate
    // nothing); with settings.cost, the (link, cell) cost pairs go to cost().
    virtual CollisionOutcome collide(const SensorOctree &tree, const LinkSet &links,
                                     const CollisionSettings &settings, std::vector<Contact> &contacts) = 0;
    // The nearest pair; with per_link, also every link's minimum
    // (infinity for a link with nothing within the cutoff, or disabled).
    virtual DistanceOutcome distance(const SensorOctree &tree, const LinkSet &links,
                                     const DistanceSettings &settings, std::vector<double> *per_link) = 0;
    // The cost pairs of the last collision query with settings.cost.
    virtual CostCollector &cost() = 0;
    // May run concurrently with itself on one engine (no query running).
    virtual EngineStats stats() const = 0;
};

}  // namespace octoprox
