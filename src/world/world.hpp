// World objects: known obstacles beside the sensed map (tables, shelves,
// walls), each a named set of shapes with a pose in the map frame and a
// pose per shape in the object's frame.  An object is held as a link of a
// robot is: its ShapeDefs placed at the object's pose (PlacedShape, no
// padding), so queries test them against robot shapes with the exact
// shape-pair kernels of self-collision (narrowphase/shape_pair.hpp).
//
// The broad phase is an AabbTree over the placed shapes of the enabled
// objects, built by the first reader after a change (thread-safe, as
// LinkSet::tree()): a const World is ready to query from any number of
// threads, and changing it needs exclusive access.  Batch queries make
// the tree and their meshes' placements on the calling thread before
// their workers start (BatchWorkers::prepare), so the workers only read.
#pragma once

#include "robot/shape.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace octoprox {

struct WorldObject {
    std::string name;
    Pose pose;  // the object's frame in the map frame
    bool enabled = true;
    // unique_ptr: a PlacedShape points at its ShapeDef, which must not move.
    std::vector<std::unique_ptr<ShapeDef>> shapes;
    // One per shape, at `pose`; PlacedShape::link is the object's index,
    // PlacedShape::shape the shape's index within the object.
    std::vector<PlacedShape> placed;
};

// What queries read: the enabled objects' placed shapes and the tree over
// their boxes (leaf item i is shapes[i]).
struct WorldIndex {
    std::vector<const PlacedShape *> shapes;
    AabbTree tree;
};

class World {
public:
    World() = default;
    World(const World &) = delete;
    World &operator=(const World &) = delete;

    // Indices are positions: removing an object moves every later one
    // down by one.  Callers check indices; these trust them.
    uint32_t add_object(const std::string &name, const Pose &pose);
    // Meshes get their triangle tree here, once.
    uint32_t add_shape(uint32_t object, ShapeDef def);
    void set_object_pose(uint32_t object, const Pose &pose);
    void set_shape_pose(uint32_t object, uint32_t shape, const Pose &local);
    void set_object_enabled(uint32_t object, bool enabled);
    void remove_object(uint32_t object);

    size_t object_count() const { return objects_.size(); }
    const WorldObject &object(uint32_t index) const { return objects_[index]; }
    // The first object named `name`, or -1.
    int64_t find_object(const std::string &name) const;
    // Grows with every change (objects, shapes, poses, enabled flags).
    uint64_t generation() const { return generation_; }
    // Shapes placed so far: adding a shape or setting its pose places that
    // shape alone, an object's pose or enabled flag each of its shapes.
    uint64_t placements() const { return placements_; }

    const WorldIndex &index() const {
        if (index_stale_.load(std::memory_order_acquire)) rebuild_index();
        return index_;
    }

private:
    void place_object(uint32_t object);
    void place_one(uint32_t object, uint32_t shape);
    void changed();
    void rebuild_index() const;  // under index_mutex_

    std::vector<WorldObject> objects_;
    uint64_t generation_ = 0;
    uint64_t placements_ = 0;
    mutable WorldIndex index_;
    mutable std::atomic<bool> index_stale_{false};
    mutable std::mutex index_mutex_;
};

}  // namespace octoprox
