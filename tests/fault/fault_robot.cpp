// The arm of the fault tests (see fault_scene.hpp).
#include "fault_scene.hpp"

#include <cmath>

namespace fault {

const char kArmUrdf[] =
    "<?xml version=\"1.0\"?>\n"
    "<robot name=\"fault_arm\">\n"
    " <link name=\"base\"><collision><origin xyz=\"0 0 0.075\"/>"
    "<geometry><box size=\"0.3 0.3 0.15\"/></geometry></collision></link>\n"
    " <link name=\"turret\"><collision><origin xyz=\"0 0 0.05\"/>"
    "<geometry><cylinder radius=\"0.08\" length=\"0.1\"/></geometry></collision></link>\n"
    " <link name=\"upper\">"
    "<collision><origin xyz=\"0.2 0 0\"/><geometry><box size=\"0.4 0.08 0.08\"/></geometry></collision>"
    "<collision><geometry><sphere radius=\"0.06\"/></geometry></collision></link>\n"
    " <link name=\"forearm\"><collision><origin xyz=\"0.15 0 0\" rpy=\"0 1.5707963267948966 0\"/>"
    "<geometry><cylinder radius=\"0.04\" length=\"0.3\"/></geometry></collision></link>\n"
    " <link name=\"wrist\"><collision><geometry><sphere radius=\"0.05\"/></geometry></collision></link>\n"
    " <link name=\"tool\"><collision><origin xyz=\"0.03 0 0\" rpy=\"0.2 0 0\"/>"
    "<geometry><box size=\"0.04 0.1 0.02\"/></geometry></collision></link>\n"
    " <joint name=\"yaw\" type=\"revolute\"><parent link=\"base\"/><child link=\"turret\"/>"
    "<origin xyz=\"0 0 0.15\"/><axis xyz=\"0 0 1\"/>"
    "<limit lower=\"-2\" upper=\"2\" effort=\"10\" velocity=\"1\"/></joint>\n"
    " <joint name=\"shoulder\" type=\"revolute\"><parent link=\"turret\"/><child link=\"upper\"/>"
    "<origin xyz=\"0 0 0.1\"/><axis xyz=\"0 1 0\"/>"
    "<limit lower=\"-1.5\" upper=\"1.5\" effort=\"10\" velocity=\"1\"/></joint>\n"
    " <joint name=\"reach\" type=\"prismatic\"><parent link=\"upper\"/><child link=\"forearm\"/>"
    "<origin xyz=\"0.4 0 0\"/><axis xyz=\"1 0 0\"/>"
    "<limit lower=\"0\" upper=\"0.3\" effort=\"10\" velocity=\"0.2\"/></joint>\n"
    " <joint name=\"roll\" type=\"continuous\"><parent link=\"forearm\"/><child link=\"wrist\"/>"
    "<origin xyz=\"0.3 0 0\"/><axis xyz=\"1 0 0\"/></joint>\n"
    " <joint name=\"tool\" type=\"fixed\"><parent link=\"wrist\"/><child link=\"tool\"/>"
    "<origin xyz=\"0.1 0 0\"/></joint>\n"
    "</robot>\n";

namespace {

const char kSphereArmUrdf[] =
    "<?xml version=\"1.0\"?><robot name=\"sphere_arm\">"
    "<link name=\"base\"><collision><origin xyz=\"0 0 0.1\"/><geometry><sphere radius=\"0.12\"/></geometry>"
    "</collision></link>"
    "<link name=\"upper\"><collision><origin xyz=\"0.2 0 0\"/><geometry><sphere radius=\"0.08\"/></geometry>"
    "</collision><collision><origin xyz=\"0.45 0 0\"/><geometry><sphere radius=\"0.06\"/></geometry>"
    "</collision></link>"
    "<link name=\"fore\"><collision><origin xyz=\"0.25 0 0\"/><geometry><sphere radius=\"0.07\"/></geometry>"
    "</collision></link>"
    "<joint name=\"yaw\" type=\"continuous\"><parent link=\"base\"/><child link=\"upper\"/>"
    "<origin xyz=\"0 0 0.3\"/><axis xyz=\"0 0 1\"/></joint>"
    "<joint name=\"pitch\" type=\"continuous\"><parent link=\"upper\"/><child link=\"fore\"/>"
    "<origin xyz=\"0.5 0 0\"/><axis xyz=\"0 1 0\"/></joint></robot>";

constexpr uint32_t kToolLink = 5;
constexpr uint32_t kGripperLink = 6;

// A cube of edge 0.06 (convex hull) and an octahedron (closed mesh).
const double kCube[24] = {0, 0, 0, 0.06, 0, 0, 0, 0.06, 0, 0.06, 0.06, 0,
                          0, 0, 0.06, 0.06, 0, 0.06, 0, 0.06, 0.06, 0.06, 0.06, 0.06};
const double kOctahedron[18] = {0.04, 0, 0, -0.04, 0, 0, 0, 0.04, 0, 0, -0.04, 0, 0, 0, 0.04, 0, 0, -0.04};
const uint32_t kOctahedronFaces[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                       2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

opx_shape shape_at(int32_t kind, double x) {
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = kind;
    shape.pose.position[0] = x;
    return shape;
}

void add_gripper(opx_linkset *arm) {
    uint32_t link = 0;
    require_ok(opx_linkset_add_link(arm, "gripper", &link), "opx_linkset_add_link");
    opx_shape capsule = shape_at(OPX_SHAPE_CAPSULE, 0.05);
    capsule.radius = 0.02;
    capsule.length = 0.08;
    capsule.pose.orientation[1] = std::sqrt(0.5);  // along x
    capsule.pose.orientation[3] = std::sqrt(0.5);
    opx_shape hull = shape_at(OPX_SHAPE_CONVEX, 0.1);
    hull.vertices = kCube;
    hull.vertex_count = 8;
    opx_shape mesh = shape_at(OPX_SHAPE_MESH, 0.2);
    mesh.vertices = kOctahedron;
    mesh.vertex_count = 6;
    mesh.indices = kOctahedronFaces;
    mesh.triangle_count = 8;
    for (const opx_shape &shape : {capsule, hull, mesh})
        require_ok(opx_linkset_add_shape(arm, link, &shape, nullptr), "opx_linkset_add_shape");
}

double fraction(double x) { return x - std::floor(x); }

}  // namespace

opx_linkset *arm_with_gripper() {
    opx_linkset *arm = nullptr;
    require_ok(opx_linkset_load_urdf_string(kArmUrdf, nullptr, &arm), "opx_linkset_load_urdf_string");
    add_gripper(arm);
    return arm;
}

std::vector<double> arm_configuration(size_t i) {
    const double n = static_cast<double>(i);
    return {-1.2 + 2.4 * fraction(0.618 * n + 0.1), -0.9 + 1.6 * fraction(0.414 * n + 0.3),
            0.3 * fraction(0.732 * n), 0.37 * n, 0.0};
}

void arm_pose(opx_linkset *arm, size_t i) {
    const std::vector<double> joints = arm_configuration(i);
    opx_pose base = OPX_POSE_IDENTITY;
    base.position[0] = 0.45;
    base.position[2] = 0.05;
    require_ok(opx_linkset_set_joint_positions(arm, joints.data(), joints.size(), &base),
               "opx_linkset_set_joint_positions");
    uint32_t count = 0;
    require_ok(opx_linkset_get_link_count(arm, &count), "opx_linkset_get_link_count");
    std::vector<opx_pose> poses(count);
    for (uint32_t link = 0; link < count; ++link)
        require_ok(opx_linkset_get_pose(arm, link, &poses[link]), "opx_linkset_get_pose");
    poses[kGripperLink] = poses[kToolLink];
    require_ok(opx_linkset_set_poses(arm, poses.data(), count, 0), "opx_linkset_set_poses");
}

std::vector<opx_pose> arm_link_poses(const opx_linkset *arm, size_t i) {
    opx_linkset *clone = nullptr;
    require_ok(opx_linkset_clone(arm, &clone), "opx_linkset_clone");
    arm_pose(clone, i);
    uint32_t count = 0;
    require_ok(opx_linkset_get_link_count(clone, &count), "opx_linkset_get_link_count");
    std::vector<opx_pose> poses(count);
    for (uint32_t link = 0; link < count; ++link)
        require_ok(opx_linkset_get_pose(clone, link, &poses[link]), "opx_linkset_get_pose");
    opx_linkset_destroy(clone);
    return poses;
}

std::vector<opx_pose> arm_path(const opx_linkset *arm, size_t first, size_t count) {
    std::vector<opx_pose> path;
    for (size_t w = 0; w < count; ++w) {
        const std::vector<opx_pose> poses = arm_link_poses(arm, first + w);
        path.insert(path.end(), poses.begin(), poses.end());
    }
    return path;
}

opx_linkset *sphere_arm() {
    opx_linkset *arm = nullptr;
    require_ok(opx_linkset_load_urdf_string(kSphereArmUrdf, nullptr, &arm), "opx_linkset_load_urdf_string");
    return arm;
}

std::vector<double> sphere_arm_rows(size_t count, uint64_t seed) {
    Lcg rng(seed);
    std::vector<double> rows;
    for (size_t i = 0; i < kSphereArmJoints * count; ++i) rows.push_back(rng.uniform(-3.0, 3.0));
    return rows;
}

}  // namespace fault
