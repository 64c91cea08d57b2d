#include "query/path_query.hpp"

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
        const CollisionOutcome hit = engine.collide(request.tree, moving, collision, contacts_);
        out.narrow_tests += hit.narrow_tests;
        if (hit.collided && out.first_collision < 0) out.first_collision = static_cast<int64_t>(w);
        if (collision.cost) cost.add_waypoint(moving, engine.cost());
        if (settings.distance) {
            const DistanceOutcome d = engine.distance(request.tree, moving, settings.distance_settings, nullptr);
            out.narrow_tests += d.narrow_tests;
            if (d.found && d.distance < out.min_distance)
                out.min_distance = d.distance, out.min_distance_waypoint = static_cast<int64_t>(w);
        }
        if (out.first_collision >= 0 && !collision.cost && !settings.distance) break;
    }
    out.cost = cost.finish_path(collision.max_cost_boxes, boxes);
    return out;
}

}  // namespace octoprox
