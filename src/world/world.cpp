#include "world/world.hpp"

namespace octoprox {

uint32_t World::add_object(const std::string &name, const Pose &pose) {
    WorldObject object;
    object.name = name;
    object.pose = pose;
    objects_.push_back(std::move(object));
    changed();
    return static_cast<uint32_t>(objects_.size() - 1);
}

uint32_t World::add_shape(uint32_t object, ShapeDef def) {
    if (def.kind == ShapeKind::kMesh) build_mesh_tree(def);
    WorldObject &o = objects_[object];
    o.shapes.push_back(std::make_unique<ShapeDef>(std::move(def)));
    o.placed.emplace_back();
    place_one(object, static_cast<uint32_t>(o.shapes.size() - 1));
    changed();
    return static_cast<uint32_t>(o.shapes.size() - 1);
}

void World::set_object_pose(uint32_t object, const Pose &pose) {
    objects_[object].pose = pose;
    place_object(object);
    changed();
}

void World::set_shape_pose(uint32_t object, uint32_t shape, const Pose &local) {
    objects_[object].shapes[shape]->local = local;
    place_one(object, shape);
    changed();
}

void World::set_object_enabled(uint32_t object, bool enabled) {
    objects_[object].enabled = enabled;
    place_object(object);
    changed();
}

// The later objects move down by one: their placed shapes take their new
// index (their ShapeDefs, held by pointer, do not move).
void World::remove_object(uint32_t object) {
    objects_.erase(objects_.begin() + object);
    for (uint32_t i = object; i < objects_.size(); ++i)
        for (PlacedShape &p : objects_[i].placed) p.link = i;
    changed();
}

int64_t World::find_object(const std::string &name) const {
    for (size_t i = 0; i < objects_.size(); ++i)
        if (objects_[i].name == name) return static_cast<int64_t>(i);
    return -1;
}

void World::place_object(uint32_t object) {
    for (uint32_t s = 0; s < objects_[object].shapes.size(); ++s) place_one(object, s);
}

void World::place_one(uint32_t object, uint32_t shape) {
    WorldObject &o = objects_[object];
    PlacedShape &placed = o.placed[shape];
    placed.link = object, placed.shape = shape;
    place_shape(*o.shapes[shape], o.pose, 0.0, o.enabled, placed);
    ++placements_;
}

void World::changed() {
    ++generation_;
    index_stale_.store(true, std::memory_order_release);
}

// Every change marks the tree stale, poses included: objects are few next
// to a map's cells, and a tree refit after large moves would cull poorly.
void World::rebuild_index() const {
    std::lock_guard<std::mutex> lock(index_mutex_);
    if (!index_stale_.load(std::memory_order_relaxed)) return;  // another reader built it
    index_.shapes.clear();
    std::vector<Aabb> boxes;
    for (const WorldObject &o : objects_) {
        if (!o.enabled) continue;
        for (const PlacedShape &p : o.placed) {
            index_.shapes.push_back(&p);
            boxes.push_back(p.box);
        }
    }
    index_.tree.build(boxes);
    index_stale_.store(false, std::memory_order_release);
}

}  // namespace octoprox
