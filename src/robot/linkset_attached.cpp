// Objects attached to links (LinkSet::attach): held beside the links, their
// shapes placed after their link's own (LinkSet::place_link).  Attaching
// and detaching are rare next to poses: both place every shape again.
#include "robot/linkset.hpp"

#include <algorithm>

namespace octoprox {
namespace {

Pose compose(const Pose &outer, const Pose &inner) {
    Pose out;
    out.rotation = outer.rotation * inner.rotation;
    out.translation = outer.apply(inner.translation);
    return out;
}

}  // namespace

bool AttachedObject::touches(uint32_t other) const {
    return std::binary_search(touch_links.begin(), touch_links.end(), other);
}

uint32_t LinkSet::attach(const std::string &name, uint32_t link, const Pose &pose, std::vector<ShapeDef> shapes,
                         std::vector<uint32_t> touch_links) {
    AttachedObject object;
    object.name = name, object.link = link, object.pose = pose;
    for (ShapeDef &def : shapes) {
        if (def.kind == ShapeKind::kMesh) build_mesh_tree(def);
        object.shape_poses.push_back(def.local);
        def.local = compose(pose, def.local);
        object.shapes.push_back(std::make_unique<ShapeDef>(std::move(def)));
    }
    std::sort(touch_links.begin(), touch_links.end());
    touch_links.erase(std::unique(touch_links.begin(), touch_links.end()), touch_links.end());
    touch_links.erase(std::remove(touch_links.begin(), touch_links.end(), link), touch_links.end());
    object.touch_links = std::move(touch_links);
    attached_.push_back(std::move(object));
    ++generation_;
    index_attached();
    rebuild();
    return static_cast<uint32_t>(attached_.size() - 1);
}

void LinkSet::detach(uint32_t object) {
    attached_.erase(attached_.begin() + object);
    ++generation_;
    index_attached();
    rebuild();
}

int64_t LinkSet::find_attached(const std::string &name) const {
    for (size_t i = 0; i < attached_.size(); ++i)
        if (attached_[i].name == name) return static_cast<int64_t>(i);
    return -1;
}

void LinkSet::index_attached() {
    attached_by_link_.assign(links_.size(), {});
    for (uint32_t i = 0; i < attached_.size(); ++i) attached_by_link_[attached_[i].link].push_back(i);
}

}  // namespace octoprox
