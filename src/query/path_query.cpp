#include "query/path_query.hpp"

#include <algorithm>

namespace octoprox {

// A private copy of the link set takes each waypoint's poses, so the
// caller's set stays read-only; it is copied again only when the caller's
// set changed in more than its poses.
LinkSet &PathQuery::posable_copy(const LinkSet &links) {
    if (!copy_ || copy_source_ != links.identity() || copy_->generation() != links.generation()) {
        copy_ = std::make_unique<LinkSet>(links);
        copy_source_ = links.identity();
    }
    return *copy_;
}

void PathQuery::pose_waypoint(LinkSet &moving, const PathRequest &request, size_t w) {
    const size_t link_count = request.links.link_count();
    poses_.assign(request.poses.begin() + w * link_count, request.poses.begin() + (w + 1) * link_count);
    moving.set_poses(poses_);
}

bool PathQuery::collides(const PathRequest &request, Engine &engine, const LinkSet &moving,
                         const CollisionSettings &collision, PathOutcome &out) {
    bool hit = false;
    if (request.tree != nullptr) {
        const CollisionOutcome o = engine.collide(*request.tree, moving, collision, contacts_);
        out.narrow_tests += o.narrow_tests;
        hit = o.collided;
    }
    // A waypoint the octree settled needs no object.
    if (!hit && request.world != nullptr) hit = world_.collides(*request.world, moving, out.narrow_tests);
    return hit;
}

// The objects are searched below the least distance found so far: a
// waypoint no nearer than an earlier one changes nothing.
void PathQuery::measure(const PathRequest &request, Engine &engine, const LinkSet &moving, size_t w,
                        PathOutcome &out) {
    const DistanceSettings &settings = request.settings.distance_settings;
    double nearest = std::numeric_limits<double>::infinity();
    if (request.tree != nullptr) {
        const DistanceOutcome d = engine.distance(*request.tree, moving, settings, nullptr);
        out.narrow_tests += d.narrow_tests;
        if (d.found) nearest = d.distance;
    }
    if (request.world != nullptr) {
        const double bound = std::min({nearest, settings.cutoff, out.min_distance});
        const WorldDistance d = world_.distance(*request.world, moving, bound, false, nullptr);
        out.narrow_tests += d.narrow_tests;
        if (d.found) nearest = std::min(nearest, d.distance);
    }
    if (nearest < out.min_distance) out.min_distance = nearest, out.min_distance_waypoint = static_cast<int64_t>(w);
}

PathOutcome PathQuery::run(const PathRequest &request, Engine &engine, CostPipeline &cost,
                           std::vector<CostBox> &boxes) {
    LinkSet &moving = posable_copy(request.links);
    const PathSettings &settings = request.settings;
    CollisionSettings collision = settings.collision;
    collision.max_contacts = 0;  // yes/no per waypoint
    cost.start_path();
    PathOutcome out;
    for (size_t w = 0; w < request.waypoints; ++w) {
        pose_waypoint(moving, request, w);
        const bool hit = collides(request, engine, moving, collision, out);
        if (hit && out.first_collision < 0) out.first_collision = static_cast<int64_t>(w);
        if (collision.cost) cost.add_waypoint(moving, engine.cost());
        if (settings.distance) measure(request, engine, moving, w, out);
        if (out.first_collision >= 0 && !collision.cost && !settings.distance) break;
    }
    out.cost = cost.finish_path(collision.max_cost_boxes, boxes);
    return out;
}

}  // namespace octoprox
