// A robot as links with shapes, paddings, enabled flags and map-frame
// poses, objects attached to its links, the link pairs self-collision
// checks, and the BVH over all placed shapes that queries traverse.  Every
// change brings the shapes' boxes up to date at once; a change of the set
// of shapes (or of which are enabled) only marks the BVH's topology stale,
// and the first reader of tree() rebuilds it (thread-safe), so adding n
// shapes one by one costs O(n log n), not n tree builds.  A const LinkSet
// is thus always ready to query from any number of threads; a mesh's
// vertices and triangle tree follow when a query first reaches the mesh
// (PlacedShape::place_mesh, thread-safe).
#pragma once

#include "robot/link_pairs.hpp"
#include "robot/shape.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace octoprox {

// An object attached to a link (MoveIt's attached collision object): its
// shapes move with the link and are checked as the link's own against the
// map and the world; against the robot they follow their own rules
// (self-collision skips the link they are attached to and the touch
// links).  A shape's `local` is its pose in the LINK frame (the object's
// pose in the link times the shape's pose in the object).
struct AttachedObject {
    std::string name;
    uint32_t link = 0;
    Pose pose;                       // the object's frame in the link frame
    std::vector<Pose> shape_poses;   // each shape's pose in the object frame
    std::vector<std::unique_ptr<ShapeDef>> shapes;
    std::vector<uint32_t> touch_links;  // sorted, unique; never `link` itself

    bool touches(uint32_t other) const;  // `other` is a touch link
};

struct Link {
    std::string name;
    double padding = 0.0;
    bool enabled = true;
    Pose pose;
    // unique_ptr: PlacedShape keeps a pointer to its ShapeDef, which must
    // not move when the vector grows.
    std::vector<std::unique_ptr<ShapeDef>> shapes;
};

class LinkSet {
public:
    LinkSet() = default;
    LinkSet(const LinkSet &other);
    LinkSet &operator=(const LinkSet &) = delete;

    uint32_t add_link(const std::string &name);
    uint32_t add_shape(uint32_t link, ShapeDef def);
    void set_padding(double padding);
    void set_link_padding(uint32_t link, double padding);
    void set_link_enabled(uint32_t link, bool enabled);
    void set_poses(const std::vector<Pose> &poses);
    // The same when the caller knows which of the first `known` links may
    // have moved since the last set_poses (moved[i] != 0; forward
    // kinematics' flags): the others are not compared; links from `known`
    // on are.
    void set_poses(const std::vector<Pose> &poses, const uint8_t *moved, size_t known);
    // The box meshes get from the next placements on (shape.hpp): a batch's
    // own copy asks for kCheap.  Answers do not depend on it.
    void set_mesh_box(MeshBox mesh_box) { mesh_box_ = mesh_box; }
    // Whether self-collision queries check links a and b (a != b).
    void set_pair_enabled(uint32_t a, uint32_t b, bool enabled);
    const LinkPairs &pairs() const { return pairs_; }

    // Attached objects (linkset_attached.cpp); indices are positions, as
    // links': detaching moves every later object down by one.  Callers
    // check the link, touch links and shapes; `shapes` are in the object
    // frame (their `local` the pose in the object), `pose` the object in
    // the link frame.
    uint32_t attach(const std::string &name, uint32_t link, const Pose &pose, std::vector<ShapeDef> shapes,
                    std::vector<uint32_t> touch_links);
    void detach(uint32_t object);
    size_t attached_count() const { return attached_.size(); }
    const AttachedObject &attached(uint32_t index) const { return attached_[index]; }
    // The first attached object named `name`, or -1.
    int64_t find_attached(const std::string &name) const;
    // Self-collision's rule for an attached object and a link: not its own
    // link, not a touch link.
    bool attached_meets_link(uint32_t object, uint32_t link) const {
        const AttachedObject &a = attached_[object];
        return a.link != link && !a.touches(link);
    }

    size_t link_count() const { return links_.size(); }
    const Link &link(uint32_t index) const { return links_[index]; }
    double padding() const { return padding_; }
    // Whether set_poses was ever called (a robot's forward kinematics
    // calls it): self-filtering refuses a robot at no known pose.
    bool poses_set() const { return poses_set_; }
    // Grows with every change but poses: a copy with the same generation
    // differs from this set only in its poses.
    uint64_t generation() const { return generation_; }
    // Unique among all link sets ever made in this process (a copy gets a
    // new one): unlike an address, never reused.
    uint64_t identity() const { return identity_; }

    // What queries read: placed shapes and the tree over their boxes.
    const std::vector<PlacedShape> &placed() const { return placed_; }
    const AabbTree &tree() const {
        if (topology_stale_.load(std::memory_order_acquire)) rebuild_stale_topology();
        return tree_;
    }

private:
    void place_link(uint32_t link);
    void index_attached();  // attached_by_link_ from attached_
    size_t placed_count(uint32_t link) const;  // own and attached shapes
    static bool same_pose(const Pose &a, const Pose &b);
    void rebuild();  // place every shape, topology stale
    void mark_topology_stale();
    void rebuild_stale_topology() const;  // under topology_mutex_
    void build_topology() const;
    void refit_boxes() const;
    void refit() const;  // after boxes changed

    std::vector<Link> links_;
    std::vector<AttachedObject> attached_;
    // Per link, its attached objects in index order; their shapes follow
    // the link's own in placed_.
    std::vector<std::vector<uint32_t>> attached_by_link_;
    LinkPairs pairs_;
    double padding_ = 0.0;
    bool poses_set_ = false;
    MeshBox mesh_box_ = MeshBox::kTight;
    std::vector<PlacedShape> placed_;
    std::vector<uint32_t> first_placed_;  // per link: its first entry in placed_
    // Built by the first tree() after a change of the shapes: mutable,
    // guarded by the flag and the mutex.
    mutable AabbTree tree_;
    mutable std::vector<Aabb> box_scratch_;  // refit's input, capacity kept
    mutable std::atomic<bool> topology_stale_{false};
    mutable std::mutex topology_mutex_;
    bool topology_from_poses_ = false;
    uint64_t generation_ = 0;
    uint64_t identity_ = next_identity();
    static uint64_t next_identity();
};

}  // namespace octoprox
