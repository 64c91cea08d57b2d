/*
 * Fuzz target: URDF strings (opx_linkset_load_urdf_string).  Mesh files
 * resolve against package and base folders that do not exist, so every
 * mesh fails cleanly as an I/O error; inputs that could name an existing
 * file by an absolute path are skipped, so a run never reads the disk
 * beyond failed stat() calls.  A robot that loads is then read, moved by
 * forward kinematics and queried against a small map.
 */
#include "fuzz_check.h"
#include "fuzz_tree.h"

#include <console_bridge/console.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv);

namespace {

const char *const kPackageDirs[] = {"/nonexistent-opx-fuzz/packages", "robot=/nonexistent-opx-fuzz/robot"};

// An attribute value starting with '/' (an absolute path), a file: URI or
// a character reference (&#47; is '/') could reach a real file.
bool may_name_a_real_file(const std::string &xml) {
    if (xml.find("file:") != std::string::npos || xml.find("&#") != std::string::npos) return true;
    for (size_t quote = xml.find_first_of("\"'"); quote != std::string::npos;
         quote = xml.find_first_of("\"'", quote + 1)) {
        size_t before = quote;
        while (before > 0 && std::isspace(static_cast<unsigned char>(xml[before - 1]))) --before;
        if (before > 0 && xml[before - 1] == '=' && quote + 1 < xml.size() && xml[quote + 1] == '/') return true;
    }
    return false;
}

void read_joints(opx_linkset *robot) {
    uint32_t joints = 0;
    FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_joint_count, robot, &joints) == OPX_OK);
    for (uint32_t j = 0; j < joints; ++j) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_joint_info, robot, j, &info) == OPX_OK);
        FUZZ_REQUIRE(info.name != nullptr);
        uint32_t found = 0;
        FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_find_joint, robot, info.name, &found) == OPX_OK);
    }
    // Every joint at 0.3 (rad or m), then read back.
    std::vector<double> positions(joints, 0.3);
    const opx_pose base = {{0.1, -0.2, 0.3}, {0.0, 0.0, 0.0, 1.0}};
    FUZZ_CALL(opx_linkset_set_joint_positions, robot, positions.data(), positions.size(), &base);
    size_t count = 0;
    FUZZ_CALL(opx_linkset_get_joint_positions, robot, positions.data(), positions.size(), &count);
    FUZZ_REQUIRE(count == joints);
}

void read_links(opx_linkset *robot) {
    uint32_t links = 0;
    FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_link_count, robot, &links) == OPX_OK);
    for (uint32_t l = 0; l < links; ++l) {
        const char *name = nullptr;
        FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_link_name, robot, l, &name) == OPX_OK && name != nullptr);
        uint32_t shapes = 0;
        FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_shape_count, robot, l, &shapes) == OPX_OK);
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_shape, robot, l, s, &shape) == OPX_OK);
        }
        opx_pose pose;
        FUZZ_REQUIRE(FUZZ_CALL(opx_linkset_get_pose, robot, l, &pose) == OPX_OK);
    }
}

// A few occupied cells around the origin, made once.
const opx_octree *small_map() {
    static opx_octree *tree = nullptr;
    if (tree != nullptr) return tree;
    FUZZ_REQUIRE(opx_octree_create(nullptr, &tree) == OPX_OK);
    const float points[] = {0.2f, 0.0f, 0.1f, -0.3f, 0.2f, 0.4f, 0.0f, 0.0f, 1.0f, 1.0f, 1.0f, 0.0f};
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.sensor_pose.position[2] = 2.0;
    FUZZ_REQUIRE(opx_octree_insert_points(tree, points, 4, 0, OPX_SCALAR_FLOAT32, &options, nullptr) == OPX_OK);
    return tree;
}

void query_robot(opx_linkset *robot) {
    static opx_query *query = nullptr;
    if (query == nullptr) FUZZ_REQUIRE(opx_query_create(nullptr, &query) == OPX_OK);
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 4;
    opx_collision_result collision = OPX_COLLISION_RESULT_INIT;
    FUZZ_CALL(opx_query_collide, query, small_map(), robot, &request, &collision);
    opx_distance_result distance = OPX_DISTANCE_RESULT_INIT;
    FUZZ_CALL(opx_query_distance, query, small_map(), robot, nullptr, &distance);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
    // urdfdom explains every rejected URDF on stderr: millions of lines.
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const std::string xml(reinterpret_cast<const char *>(data), size);
    if (may_name_a_real_file(xml)) return 0;
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = kPackageDirs;
    options.package_dir_count = sizeof kPackageDirs / sizeof kPackageDirs[0];
    options.base_dir = "/nonexistent-opx-fuzz/base";
    opx_linkset *robot = reinterpret_cast<opx_linkset *>(&robot);  // must be reset to NULL on failure
    if (FUZZ_CALL(opx_linkset_load_urdf_string, xml.c_str(), &options, &robot) != OPX_OK) {
        FUZZ_REQUIRE(robot == nullptr);
        return 0;
    }
    FUZZ_REQUIRE(robot != nullptr);
    read_joints(robot);
    read_links(robot);
    query_robot(robot);
    opx_linkset_destroy(robot);
    return 0;
}
