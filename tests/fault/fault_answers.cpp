#include "fault_answers.hpp"

#include "fault_scene.hpp"

namespace fault {

const char *query_kind_name(QueryKind kind) {
    switch (kind) {
    case QueryKind::kCollide: return "collide";
    case QueryKind::kDistance: return "distance";
    case QueryKind::kPath: return "path";
    case QueryKind::kCollideBoxes: return "collide_boxes";
    case QueryKind::kDistanceBoxes: return "distance_boxes";
    }
    return "?";
}

namespace {

opx_collision_request collision_request(const QueryInputs &in, bool cost) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.unknown_policy = in.unknown_policy;
    request.max_contacts = UINT32_MAX;
    request.compute_penetration = 1;
    request.compute_cost = cost ? 1 : 0;
    request.max_cost_boxes = 64;
    return request;
}

opx_distance_request distance_request(const QueryInputs &in) {
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.unknown_policy = in.unknown_policy;
    request.per_link = 1;
    request.signed_distance = 1;
    return request;
}

opx_path_request path_request(const QueryInputs &in) {
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.unknown_policy = in.unknown_policy;
    request.compute_distance = 1;
    request.compute_cost = 1;
    request.max_cost_boxes = 64;
    return request;
}

void record_contacts(Record &record, const opx_query *query, uint64_t count) {
    for (uint64_t i = 0; i < count; ++i) {
        opx_contact c = OPX_CONTACT_INIT;
        record.add("get_contact status", opx_query_get_contact(query, i, &c));
        record.add("contact link", c.link);
        record.add("contact shape", c.shape);
        record.add("contact class", c.cell_class);
        record.add("contact cell_center", c.cell_center, 3);
        record.add("contact cell_size", c.cell_size);
        record.add("contact probability", c.cell_probability);
        record.add("contact depth", c.depth);
        record.add("contact normal", c.normal, 3);
        record.add("contact position", c.position, 3);
    }
}

void record_cost_boxes(Record &record, const opx_query *query, uint64_t count) {
    for (uint64_t i = 0; i < count; ++i) {
        opx_cost_box b = OPX_COST_BOX_INIT;
        record.add("get_cost_box status", opx_query_get_cost_box(query, i, &b));
        record.add("cost box link", b.link);
        record.add("cost box class", b.cell_class);
        record.add("cost box min", b.min, 3);
        record.add("cost box max", b.max, 3);
        record.add("cost box probability", b.probability);
        record.add("cost box cost", b.cost);
        record.add("cost box cell_center", b.cell_center, 3);
        record.add("cost box cell_size", b.cell_size);
    }
}

void record_collision(Record &record, const opx_query *query, const opx_collision_result &r) {
    record.add("collided", r.collided);
    record.add("contact_count", r.contact_count);
    record.add("truncated", r.truncated);
    record.add("narrow_tests", r.narrow_tests);
    record.add("total_cost", r.total_cost);
    record.add("cost_box_count", r.cost_box_count);
    record.add("cost_boxes_found", r.cost_boxes_found);
    record_contacts(record, query, r.contact_count);
    record_cost_boxes(record, query, r.cost_box_count);
}

void record_distance(Record &record, const opx_query *query, const opx_distance_result &r) {
    record.add("found", r.found);
    record.add("collided", r.collided);
    record.add("cell_class", r.cell_class);
    record.add("link", r.link);
    record.add("shape", r.shape);
    record.add("distance", r.distance);
    record.add("point_on_link", r.point_on_link, 3);
    record.add("point_on_cell", r.point_on_cell, 3);
    record.add("cell_center", r.cell_center, 3);
    record.add("cell_size", r.cell_size);
    record.add("cell_probability", r.cell_probability);
    record.add("narrow_tests", r.narrow_tests);
    size_t count = 0;
    record.add("link distances status", opx_query_get_link_distances(query, nullptr, 0, &count));
    std::vector<double> distances(count);
    record.add("link distances status", opx_query_get_link_distances(query, distances.data(), count, &count));
    record.add("link distances", distances.data(), distances.size());
}

void record_path(Record &record, const opx_query *query, const opx_path_result &r) {
    record.add("collided", r.collided);
    record.add("first_colliding_waypoint", r.first_colliding_waypoint);
    record.add("min_distance", r.min_distance);
    record.add("min_distance_waypoint", r.min_distance_waypoint);
    record.add("total_cost", r.total_cost);
    record.add("cost_box_count", r.cost_box_count);
    record.add("cost_boxes_found", r.cost_boxes_found);
    record.add("narrow_tests", r.narrow_tests);
    record_cost_boxes(record, query, r.cost_box_count);
}

}  // namespace

opx_status call_query(QueryKind kind, opx_query *query, const QueryInputs &in, QueryOutputs &out) {
    switch (kind) {
    case QueryKind::kCollide: {
        const opx_collision_request request = collision_request(in, true);
        return opx_query_collide(query, in.tree, in.links, &request, &out.collision);
    }
    case QueryKind::kDistance: {
        const opx_distance_request request = distance_request(in);
        return opx_query_distance(query, in.tree, in.links, &request, &out.distance);
    }
    case QueryKind::kPath: {
        const opx_path_request request = path_request(in);
        return opx_query_path(query, in.tree, in.links, in.path, in.waypoints, 0, 0, &request, &out.path);
    }
    case QueryKind::kCollideBoxes: {
        const opx_collision_request request = collision_request(in, false);
        return opx_query_collide_boxes(query, in.links, &request, &out.collision);
    }
    case QueryKind::kDistanceBoxes: {
        const opx_distance_request request = distance_request(in);
        return opx_query_distance_boxes(query, in.links, &request, &out.distance);
    }
    }
    return OPX_ERROR_INTERNAL;
}

void record_query(QueryKind kind, Record &record, const opx_query *query, const QueryOutputs &out) {
    switch (kind) {
    case QueryKind::kCollide:
    case QueryKind::kCollideBoxes: record_collision(record, query, out.collision); break;
    case QueryKind::kDistance:
    case QueryKind::kDistanceBoxes: record_distance(record, query, out.distance); break;
    case QueryKind::kPath: record_path(record, query, out.path); break;
    }
}

void record_query_stats(Record &record, opx_query *query) {
    opx_query_stats s = OPX_QUERY_STATS_INIT;
    record.add("query stats status", opx_query_get_stats(query, &s));
    record.add("engine", s.engine);
    record.add("boxes", s.boxes);
    record.add("builds", s.builds);
    record.add("refine_steps_done", s.refine_steps_done);
    record.add("sah_ratio", s.sah_ratio);
}

void record_map(Record &record, const opx_octree *tree) {
    opx_octree_stats s = OPX_OCTREE_STATS_INIT;
    record.add("map stats status", opx_octree_get_stats(tree, &s));
    record.add("has_occupied", s.has_occupied);
    record.add("resolution", s.resolution);
    record.add("leaves_occupied", s.leaves_occupied);
    record.add("leaves_uncertain", s.leaves_uncertain);
    record.add("leaves_free", s.leaves_free);
    record.add("inner_nodes", s.inner_nodes);
    record.add("memory_bytes", s.memory_bytes);
    record.add("occupied_min", s.occupied_min, 3);
    record.add("occupied_max", s.occupied_max, 3);
    record.add("known_min", s.known_min, 3);
    record.add("known_max", s.known_max, 3);
    const std::vector<unsigned char> image = map_image(tree, OPX_FORMAT_OT);
    record.add_bytes(".ot image", image.data(), image.size());
}

void record_map_reads(Record &record, const opx_octree *tree, size_t probes) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    record.add("get_options status", opx_octree_get_options(tree, &options));
    record.add("options resolution", options.resolution);
    record.add("options free_threshold", options.free_threshold);
    record_map(record, tree);
    const std::vector<unsigned char> binary = map_image(tree, OPX_FORMAT_BT);
    record.add_bytes(".bt image", binary.data(), binary.size());
    for (uint32_t mask : {OPX_MASK_FREE, OPX_MASK_UNCERTAIN, OPX_MASK_OCCUPIED, OPX_MASK_ALL_KNOWN}) {
        size_t count = 0;
        record.add("get_leaves status", opx_octree_get_leaves(tree, mask, nullptr, 0, &count));
        std::vector<opx_leaf> leaves(count);
        record.add("get_leaves status", opx_octree_get_leaves(tree, mask, leaves.data(), count, &count));
        for (const opx_leaf &leaf : leaves) {
            record.add("leaf center", leaf.center, 3);
            record.add("leaf size", leaf.size);
            record.add("leaf probability", leaf.probability);
            record.add("leaf class", leaf.cell_class);
            record.add("leaf depth", leaf.depth);
        }
    }
    Lcg random(probes);
    for (size_t i = 0; i < probes; ++i) {
        const double point[3] = {random.uniform(-0.5, 2.5), random.uniform(-1.5, 1.5), random.uniform(-0.2, 1.6)};
        opx_cell_info info = OPX_CELL_INFO_INIT;
        record.add("classify status", opx_octree_classify(tree, point, &info));
        record.add("classify class", info.cell_class);
        record.add("classify probability", info.probability);
        record.add("classify center", info.center, 3);
        record.add("classify size", info.size);
        record.add("classify depth", info.depth);
    }
}

namespace {

void record_shape(Record &record, const opx_shape &s) {
    record.add("shape kind", s.kind);
    record.add("shape position", s.pose.position, 3);
    record.add("shape orientation", s.pose.orientation, 4);
    record.add("shape radius", s.radius);
    record.add("shape length", s.length);
    record.add("shape size", s.size, 3);
    record.add("shape vertices", s.vertices, 3 * s.vertex_count);
    record.add_bytes("shape indices", s.indices, 3 * sizeof(uint32_t) * s.triangle_count);
}

void record_joints(Record &record, const opx_linkset *links) {
    uint32_t joints = 0;
    record.add("joint_count status", opx_linkset_get_joint_count(links, &joints));
    for (uint32_t j = 0; j < joints; ++j) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        record.add("joint_info status", opx_linkset_get_joint_info(links, j, &info));
        record.add_text("joint name", info.name);
        record.add("joint type", info.type);
        record.add("joint origin", info.origin.position, 3);
        record.add("joint axis", info.axis, 3);
    }
    std::vector<double> positions(joints);
    size_t count = 0;
    record.add("joint positions status",
               opx_linkset_get_joint_positions(links, positions.data(), positions.size(), &count));
    record.add("joint positions", positions.data(), positions.size());
}

}  // namespace

void record_linkset(Record &record, const opx_linkset *links) {
    uint32_t count = 0;
    record.add("link_count status", opx_linkset_get_link_count(links, &count));
    record.add("link count", count);
    for (uint32_t link = 0; link < count; ++link) {
        const char *name = nullptr;
        record.add("link_name status", opx_linkset_get_link_name(links, link, &name));
        record.add_text("link name", name);
        opx_pose pose = OPX_POSE_IDENTITY;
        record.add("get_pose status", opx_linkset_get_pose(links, link, &pose));
        record.add("link position", pose.position, 3);
        record.add("link orientation", pose.orientation, 4);
        uint32_t shapes = 0;
        record.add("shape_count status", opx_linkset_get_shape_count(links, link, &shapes));
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            record.add("get_shape status", opx_linkset_get_shape(links, link, s, &shape));
            record_shape(record, shape);
        }
    }
    record_joints(record, links);
}

}  // namespace fault
