#include "robot/linkset.hpp"

#include <atomic>

namespace octoprox {

uint64_t LinkSet::next_identity() {
    static std::atomic<uint64_t> counter{0};
    return ++counter;
}

LinkSet::LinkSet(const LinkSet &other)
    : pairs_(other.pairs_), padding_(other.padding_), poses_set_(other.poses_set_), generation_(other.generation_) {
    for (const Link &l : other.links_) {
        Link copy;
        copy.name = l.name, copy.padding = l.padding, copy.enabled = l.enabled, copy.pose = l.pose;
        for (const auto &def : l.shapes) copy.shapes.push_back(std::make_unique<ShapeDef>(*def));
        links_.push_back(std::move(copy));
    }
    for (const AttachedObject &a : other.attached_) {
        AttachedObject copy;
        copy.name = a.name, copy.link = a.link, copy.pose = a.pose, copy.shape_poses = a.shape_poses;
        copy.touch_links = a.touch_links;
        for (const auto &def : a.shapes) copy.shapes.push_back(std::make_unique<ShapeDef>(*def));
        attached_.push_back(std::move(copy));
    }
    index_attached();
    rebuild();
}

// A new link has no shapes yet: nothing to place.
uint32_t LinkSet::add_link(const std::string &name) {
    ++generation_;
    Link link;
    link.name = name;
    links_.push_back(std::move(link));
    pairs_.resize(links_.size());
    attached_by_link_.emplace_back();
    first_placed_.push_back(static_cast<uint32_t>(placed_.size()));
    mark_topology_stale();
    return static_cast<uint32_t>(links_.size() - 1);
}

// Places only the new shape, after the link's others in placed_ (and
// before its attached objects' shapes, which keep their fields).
uint32_t LinkSet::add_shape(uint32_t link, ShapeDef def) {
    ++generation_;
    if (def.kind == ShapeKind::kMesh) build_mesh_tree(def);
    Link &l = links_[link];
    l.shapes.push_back(std::make_unique<ShapeDef>(std::move(def)));
    const uint32_t shape = static_cast<uint32_t>(l.shapes.size() - 1);
    const size_t at = first_placed_[link] + shape;
    placed_.insert(placed_.begin() + static_cast<std::ptrdiff_t>(at), PlacedShape());
    for (uint32_t later = link + 1; later < links_.size(); ++later) ++first_placed_[later];
    PlacedShape &placed = placed_[at];
    placed.link = link, placed.shape = shape;
    place_shape(*l.shapes[shape], l.pose, padding_ + l.padding, l.enabled, placed, mesh_box_);
    mark_topology_stale();
    return shape;
}

void LinkSet::set_padding(double padding) {
    ++generation_;
    padding_ = padding;
    for (uint32_t i = 0; i < links_.size(); ++i) place_link(i);
    refit();
}

void LinkSet::set_link_padding(uint32_t link, double padding) {
    ++generation_;
    links_[link].padding = padding;
    place_link(link);
    refit();
}

void LinkSet::set_link_enabled(uint32_t link, bool enabled) {
    ++generation_;
    links_[link].enabled = enabled;
    place_link(link);
    refit();
}

void LinkSet::set_pair_enabled(uint32_t a, uint32_t b, bool enabled) {
    ++generation_;
    pairs_.set_enabled(a, b, enabled);
}

// The first poses after the shapes changed also rebuild the topology: a
// tree built with every link at the origin would cull nothing.  Later
// poses only refit it, and skip the links whose pose is bit for bit the
// one they are placed at: a planner moving one arm leaves the base, torso
// and head where they are, and placing a mesh (every vertex, then its
// triangle tree) is most of the cost of a new configuration.
void LinkSet::set_poses(const std::vector<Pose> &poses) { set_poses(poses, nullptr, 0); }

void LinkSet::set_poses(const std::vector<Pose> &poses, const uint8_t *moved, size_t known) {
    poses_set_ = true;
    if (!topology_from_poses_) known = 0;  // every link is placed below
    for (uint32_t i = 0; i < links_.size(); ++i) {
        if (i < known ? moved[i] == 0 : topology_from_poses_ && same_pose(links_[i].pose, poses[i])) continue;
        links_[i].pose = poses[i];
        place_link(i);
    }
    if (topology_from_poses_) {
        refit();
    } else {
        build_topology();
        topology_from_poses_ = true;
    }
}

bool LinkSet::same_pose(const Pose &a, const Pose &b) {
    return a.rotation == b.rotation && a.translation == b.translation;
}

// The link's own shapes, then its attached objects' (each shape's `local`
// is already in the link frame), with the link's padding and flag.
void LinkSet::place_link(uint32_t index) {
    const Link &l = links_[index];
    const double padding = padding_ + l.padding;
    uint32_t at = first_placed_[index];
    for (uint32_t s = 0; s < l.shapes.size(); ++s, ++at) {
        PlacedShape &placed = placed_[at];
        placed.link = index, placed.shape = s, placed.attached = -1;
        place_shape(*l.shapes[s], l.pose, padding, l.enabled, placed, mesh_box_);
    }
    for (uint32_t object : attached_by_link_[index]) {
        const AttachedObject &a = attached_[object];
        for (uint32_t s = 0; s < a.shapes.size(); ++s, ++at) {
            PlacedShape &placed = placed_[at];
            placed.link = index, placed.shape = s, placed.attached = static_cast<int32_t>(object);
            place_shape(*a.shapes[s], l.pose, padding, l.enabled, placed, mesh_box_);
        }
    }
}

size_t LinkSet::placed_count(uint32_t link) const {
    size_t count = links_[link].shapes.size();
    for (uint32_t object : attached_by_link_[link]) count += attached_[object].shapes.size();
    return count;
}

void LinkSet::rebuild() {
    first_placed_.clear();
    size_t total = 0;
    for (uint32_t link = 0; link < links_.size(); ++link) {
        first_placed_.push_back(static_cast<uint32_t>(total));
        total += placed_count(link);
    }
    placed_.assign(total, PlacedShape());
    for (uint32_t i = 0; i < links_.size(); ++i) place_link(i);
    mark_topology_stale();
}

// The next poses rebuild the topology anyway (set_poses); a query before
// them does it in tree().
void LinkSet::mark_topology_stale() {
    topology_from_poses_ = false;
    topology_stale_.store(true, std::memory_order_release);
}

void LinkSet::rebuild_stale_topology() const {
    std::lock_guard<std::mutex> lock(topology_mutex_);
    if (!topology_stale_.load(std::memory_order_relaxed)) return;  // another reader built it
    build_topology();
}

// Disabled shapes have empty boxes; the split uses their centres instead.
void LinkSet::build_topology() const {
    std::vector<Aabb> boxes;
    boxes.reserve(placed_.size());
    for (const PlacedShape &p : placed_)
        boxes.push_back(p.box.empty() ? Aabb::from_center(p.core.center, Vec3::Zero()) : p.box);
    tree_.build(boxes);
    // The boxes are written before the flag is cleared: a reader on another
    // thread that sees the topology fresh must see the whole tree.
    refit_boxes();
    topology_stale_.store(false, std::memory_order_release);
}

// A stale topology is rebuilt from the current boxes later: nothing to do.
void LinkSet::refit() const {
    if (!topology_stale_.load(std::memory_order_relaxed)) refit_boxes();
}

// Reuses box_scratch_, so new poses allocate nothing once the set is built.
void LinkSet::refit_boxes() const {
    box_scratch_.clear();
    for (const PlacedShape &p : placed_) box_scratch_.push_back(p.box);
    tree_.refit(box_scratch_);
}

}  // namespace octoprox
