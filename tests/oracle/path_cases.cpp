#include "oracle_engine.hpp"
#include "path_cases.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Fixture {
    opx_octree *tree = nullptr;
    opx_query *query = nullptr;
    Fixture() {
        opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
        options.resolution = 0.5;  // every coordinate below is exact in binary
        opx_octree_create(&options, &tree);
        insert_frame(tree, {Vec3(0.25, 0.25, 0.25)}, opx_pose OPX_POSE_IDENTITY, OPX_INSERT_ENDPOINTS);
        oracle_create_query(&query);
    }
    ~Fixture() {
        opx_query_destroy(query);
        opx_octree_destroy(tree);
    }
};

opx_pose at(double x, double y, double z) {
    opx_pose pose = OPX_POSE_IDENTITY;
    pose.position[0] = x, pose.position[1] = y, pose.position[2] = z;
    return pose;
}

opx_linkset *box_links(size_t count, double sx, double sy, double sz) {
    opx_linkset *links = nullptr;
    opx_linkset_create(&links);
    for (size_t i = 0; i < count; ++i) {
        uint32_t link = 0;
        opx_linkset_add_link(links, ("link" + std::to_string(i)).c_str(), &link);
        opx_shape shape = OPX_SHAPE_INIT;
        shape.kind = OPX_SHAPE_BOX;
        shape.size[0] = sx, shape.size[1] = sy, shape.size[2] = sz;
        opx_linkset_add_shape(links, link, &shape, nullptr);
    }
    return links;
}

opx_linkset *sphere_link(double radius) {
    opx_linkset *links = nullptr;
    uint32_t link = 0;
    opx_linkset_create(&links);
    opx_linkset_add_link(links, "ball", &link);
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_SPHERE;
    shape.radius = radius;
    opx_linkset_add_shape(links, link, &shape, nullptr);
    return links;
}

void expect(PathReport &report, bool ok, const std::string &what) {
    ++report.special_checks;
    if (!ok) report.mismatch("special case: " + what);
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); }

// The map: one occupied cell [0, 0.5]^3; its 7 siblings are unknown cubes
// of 0.5 m.  The region [0.5, 1] x [0, 0.5] x [0, 1] holds two of them,
// c1 (z in [0, 0.5]) and c2 (z in [0.5, 1]).  A 0.2 x 0.2 x 0.4 box at
// (0.75, 0.25, 0.5), then 1 cm further along x, overlaps both at both
// waypoints: per cell the union is 0.21 x 0.2 x 0.2 m, cost 0.5 x 0.0084,
// so 0.0084 in all; the sum of the four boxes would be 0.016.
void swept_once(PathReport &report) {
    Fixture f;
    opx_linkset *links = box_links(1, 0.2, 0.2, 0.4);
    const opx_pose poses[2] = {at(0.75, 0.25, 0.5), at(0.76, 0.25, 0.5)};
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_cost = 1, request.compute_distance = 1;
    const double region_min[3] = {0.5, 0.0, 0.0}, region_max[3] = {1.0, 0.5, 1.0};
    std::memcpy(request.region_min, region_min, sizeof region_min);
    std::memcpy(request.region_max, region_max, sizeof region_max);
    opx_path_result r = OPX_PATH_RESULT_INIT;
    const opx_status status = opx_query_path(f.query, f.tree, links, poses, 2, 0, 0, &request, &r);
    const double expected = 2 * 0.5 * (0.21 * 0.2 * 0.2);
    char text[320];
    std::snprintf(text, sizeof text, "swept once: status %d total_cost %.17g (expected the union %.17g, not the sum "
                  "0.016) cells %llu (2) collided %d min_distance %.17g (0.15) at %lld (0)", status, r.total_cost,
                  expected, (unsigned long long)r.cost_boxes_found, r.collided, r.min_distance,
                  (long long)r.min_distance_waypoint);
    expect(report, status == OPX_OK && near(r.total_cost, expected) && r.cost_boxes_found == 2 &&
                       r.cost_box_count == 2 && r.collided == 0 && r.first_colliding_waypoint == -1 &&
                       std::abs(r.min_distance - 0.15) <= 1e-9 && r.min_distance_waypoint == 0, text);
    for (size_t i = 0; i < r.cost_box_count; ++i) {
        opx_cost_box b = OPX_COST_BOX_INIT;
        opx_query_get_cost_box(f.query, i, &b);
        const double z_low = b.cell_center[2] < 0.5 ? 0.3 : 0.5;
        const bool ok = b.cell_class == OPX_CELL_UNKNOWN && b.cell_size == 0.5 && near(b.cost, 0.0042) &&
                        std::abs(b.min[0] - 0.65) < 1e-12 && std::abs(b.max[0] - 0.86) < 1e-12 &&
                        std::abs(b.min[1] - 0.15) < 1e-12 && std::abs(b.max[1] - 0.35) < 1e-12 &&
                        std::abs(b.min[2] - z_low) < 1e-12 && std::abs(b.max[2] - (z_low + 0.2)) < 1e-12;
        std::snprintf(text, sizeof text, "swept once: box %zu [%.17g %.17g %.17g]-[%.17g %.17g %.17g] cost %.17g", i,
                      b.min[0], b.min[1], b.min[2], b.max[0], b.max[1], b.max[2], b.cost);
        expect(report, ok, text);
    }
    opx_linkset_destroy(links);
}

// A flat shape (a horizontal triangle) moving up 1 cm over the unknown cube
// c1 = [0.5, 1] x [0, 0.5] x [0, 0.5]: each waypoint's box is flat, but the
// union of the two is 0.1 x 0.1 x 0.01 m, cost 0.5 x 1e-4 (query.h: the
// bounding box of the boxes of every waypoint that touches the cell).
void flat_sweep(PathReport &report) {
    Fixture f;
    const double v[9] = {0.6, 0.1, 0.0, 0.7, 0.1, 0.0, 0.6, 0.2, 0.0};
    const uint32_t triangle[3] = {0, 1, 2};
    opx_linkset *links = nullptr;
    uint32_t link = 0;
    opx_linkset_create(&links);
    opx_linkset_add_link(links, "plate", &link);
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_MESH;
    shape.vertices = v, shape.vertex_count = 3, shape.indices = triangle, shape.triangle_count = 1;
    opx_linkset_add_shape(links, link, &shape, nullptr);
    const opx_pose poses[2] = {at(0.0, 0.0, 0.2), at(0.0, 0.0, 0.21)};
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_cost = 1;
    const double region_min[3] = {0.5, 0.0, 0.0}, region_max[3] = {1.0, 0.5, 0.5};
    std::memcpy(request.region_min, region_min, sizeof region_min);
    std::memcpy(request.region_max, region_max, sizeof region_max);
    opx_path_result r = OPX_PATH_RESULT_INIT;
    opx_query_path(f.query, f.tree, links, poses, 2, 0, 0, &request, &r);
    char text[200];
    std::snprintf(text, sizeof text, "a flat triangle swept 1 cm up: %llu cells, total_cost %.17g; expected 1 cell, "
                  "5e-05 (the union of the two flat boxes)", (unsigned long long)r.cost_boxes_found, r.total_cost);
    expect(report, r.cost_boxes_found == 1 && std::abs(r.total_cost - 5e-5) <= 1e-15, text);
    opx_linkset_destroy(links);
}

opx_status path_call(const Fixture &f, const opx_linkset *links, const opx_pose *poses, size_t count,
                     size_t pose_stride, size_t waypoint_stride, opx_path_result &r) {
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    request.compute_distance = 1, request.compute_cost = 1;
    r = OPX_PATH_RESULT_INIT;
    return opx_query_path(f.query, f.tree, links, poses, count, pose_stride, waypoint_stride, &request, &r);
}

bool invalid_naming(opx_status status, const char *a, const char *b = nullptr) {
    const std::string message = opx_last_error();
    return status == OPX_ERROR_INVALID_ARGUMENT && message.find(a) != std::string::npos &&
           (b == nullptr || message.find(b) != std::string::npos);
}

void bad_arguments(PathReport &report) {
    Fixture f;
    opx_linkset *links = box_links(3, 0.1, 0.1, 0.1);
    std::vector<opx_pose> poses(12, at(3.0, 3.0, 3.0));  // 4 waypoints x 3 links, clear
    opx_path_result r;
    const size_t pose = sizeof(opx_pose);
    expect(report, invalid_naming(path_call(f, links, nullptr, 2, 0, 0, r), "poses"),
           std::string("NULL poses, 2 waypoints: ") + opx_last_error());
    expect(report, invalid_naming(path_call(f, links, poses.data(), 2, pose - 8, 0, r), "pose_stride"),
           std::string("pose_stride 48: ") + opx_last_error());
    expect(report, invalid_naming(path_call(f, links, poses.data(), 2, 0, 3 * pose - 1, r), "waypoint_stride"),
           std::string("waypoint_stride 167 for 3 links: ") + opx_last_error());
    expect(report, path_call(f, links, poses.data(), 2, 0, 3 * pose, r) == OPX_OK && r.collided == 0,
           std::string("waypoint_stride 168 for 3 links (exactly one waypoint): ") + opx_last_error());
    std::vector<opx_pose> nan_poses = poses;
    nan_poses[2 * 3 + 1].position[1] = std::nan("");
    expect(report, invalid_naming(path_call(f, links, nan_poses.data(), 4, 0, 0, r), "waypoint 2", "link 1"),
           std::string("NaN at waypoint 2, link 1: ") + opx_last_error());
    nan_poses = poses;
    nan_poses[1 * 3 + 2].orientation[3] = 0.0;  // a zero quaternion
    expect(report, invalid_naming(path_call(f, links, nan_poses.data(), 4, 0, 0, r), "waypoint 1", "link 2"),
           std::string("zero quaternion at waypoint 1, link 2: ") + opx_last_error());
    for (const opx_pose *p : {static_cast<const opx_pose *>(nullptr), static_cast<const opx_pose *>(poses.data())}) {
        const opx_status status = path_call(f, links, p, 0, 0, 0, r);
        expect(report, status == OPX_OK && r.collided == 0 && r.first_colliding_waypoint == -1 &&
                           r.min_distance == kInfinity && r.min_distance_waypoint == -1 && r.total_cost == 0.0 &&
                           r.cost_boxes_found == 0,
               std::string("zero waypoints (poses ") + (p ? "set" : "NULL") + "): " + opx_last_error());
    }
    opx_linkset_destroy(links);
    // One link: a waypoint is one opx_pose, so a smaller waypoint_stride
    // overlaps the waypoints (as "stride smaller than one point" elsewhere).
    opx_linkset *one = box_links(1, 0.1, 0.1, 0.1);
    expect(report, invalid_naming(path_call(f, one, poses.data(), 3, 0, 8, r), "waypoint_stride"),
           std::string("waypoint_stride 8 with one link (waypoints overlap) was accepted, status ") +
               opx_status_name(path_call(f, one, poses.data(), 3, 0, 8, r)));
    opx_linkset_destroy(one);
}

// The path's poses never move the caller's link set.
void link_set_unmoved(PathReport &report) {
    Fixture f;
    opx_linkset *links = box_links(2, 0.1, 0.2, 0.3);
    const opx_pose home[2] = {at(5.0, 0.0, 0.0), at(0.0, 5.0, 0.0)};
    opx_linkset_set_poses(links, home, 2, 0);
    const opx_pose path[4] = {at(0.25, 0.25, 0.25), at(1.0, 1.0, 1.0), at(2.0, 2.0, 2.0), at(3.0, 3.0, 3.0)};
    opx_path_result r;
    path_call(f, links, path, 2, 0, 0, r);
    bool same = true;
    for (uint32_t l = 0; l < 2; ++l) {
        opx_pose now;
        opx_linkset_get_pose(links, l, &now);
        same &= std::memcmp(now.position, home[l].position, sizeof now.position) == 0;
    }
    expect(report, same && r.first_colliding_waypoint == 0, "the path query moved the link set");
    opx_linkset_destroy(links);
}

// A query reused after its link set was destroyed and a different one
// created (the allocator often hands back the same address): the path must
// use the new link set.
void replaced_link_set(PathReport &report) {
    Fixture f;
    const opx_pose pose = at(3.0, 3.0, 3.0);
    int same_address = 0, wrong = 0, wrong_same_address = 0;
    for (int attempt = 0; attempt < 10; ++attempt) {
        opx_linkset *small = sphere_link(0.1);  // clear of the cell at the origin
        opx_path_result r;
        path_call(f, small, &pose, 1, 0, 0, r);
        const void *old_address = small;
        opx_linkset_destroy(small);
        opx_linkset *large = sphere_link(6.0);  // reaches the cell
        const bool same = static_cast<const void *>(large) == old_address;
        path_call(f, large, &pose, 1, 0, 0, r);
        const bool ok = r.collided == 1 && r.min_distance == 0.0;
        same_address += same ? 1 : 0, wrong += ok ? 0 : 1, wrong_same_address += !ok && same ? 1 : 0;
        opx_linkset_destroy(large);
    }
    std::printf("replaced link set: the new set had the old one's address in %d of 10 attempts\n", same_address);
    char text[300];
    std::snprintf(text, sizeof text, "a path query on a new link set (a 6 m sphere) after the query's previous "
                  "one (0.1 m) was destroyed: no collision (the old set's shapes were used) in %d of 10 attempts, "
                  "%d of them with the new set at the old one's address", wrong, wrong_same_address);
    expect(report, wrong == 0, text);
}

}  // namespace

void run_path_cases(PathReport &report) {
    swept_once(report);
    flat_sweep(report);
    bad_arguments(report);
    link_set_unmoved(report);
    replaced_link_set(report);
}

}  // namespace oracle
