#include "render_pr2.hpp"

#include "depth_image.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace render {
namespace {

const char *const kDepthFile = "rgbd/frame_20121214T142255.814212_depth.tiff";
const char *const kIntrinsicsFile = "rgbd/frame_20121214T142255.814212_intrinsics.xml";
const char *const kUrdfFile = "robots/pr2_description/urdf/robot.xml";
const char *const kCameraLink = "wide_stereo_optical_frame";
constexpr double kHeadTilt = 0.82;  // rad, as opx-demo --real

const char *const kRightArm[7] = {"r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
                                  "r_elbow_flex_joint",   "r_forearm_roll_joint",  "r_wrist_flex_joint",
                                  "r_wrist_roll_joint"};
const char *const kLeftArm[7] = {"l_shoulder_pan_joint", "l_shoulder_lift_joint", "l_upper_arm_roll_joint",
                                 "l_elbow_flex_joint",   "l_forearm_roll_joint",  "l_wrist_flex_joint",
                                 "l_wrist_roll_joint"};
// MoveIt's pr2.srdf "tuck_right_arm" and "tuck_left_arm": out of view.
const double kRightTucked[7] = {-0.023593, 1.10728, -1.55669, -2.12441, -1.4175, -1.8417, 0.21436};
const double kLeftTucked[7] = {0.06024, 1.24853, 1.78907, -1.68339, -1.73434, -0.0962141, -0.0864407};

struct ArmPose {
    const double *right;
    const double *left;
};

// Chosen by rendering each into the real frame (the table's top lies at
// z 0.45 to 0.52 m, boxes on it up to 0.73 m; the shoulders at 0.74 m):
// the grippers touch the table or hover a few centimetres above it, so
// that some of the scene lies within a padding of the arm.
const double kRightOnTable[7] = {-0.2, 0.6, 0.0, -0.2, 0.0, -0.3, 0.0};
const double kLeftAbove[7] = {0.0, 0.6, 0.0, -0.6, 0.0, -0.3, 0.0};
const double kRightLow[7] = {0.0, 0.4, 0.0, -0.2, 0.0, -0.3, 0.0};
const double kLeftLow[7] = {0.2, 0.5, 0.0, -0.2, 0.0, -0.3, 0.0};
const double kRightAbove[7] = {0.0, 0.6, 0.0, -0.6, 0.0, -0.3, 0.0};
const ArmPose kArmPoses[] = {
    {kRightOnTable, kLeftTucked}, {kRightTucked, kLeftAbove}, {kRightLow, kLeftLow}, {kRightAbove, kLeftTucked}};

void check(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

std::string read_text(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The number in <tag>...</tag> after the first <section> of the XML.
double xml_number(const std::string &xml, const char *section, const char *tag) {
    const size_t start = xml.find(std::string("<") + section + ">");
    const size_t at = xml.find(std::string("<") + tag + ">", start);
    if (start == std::string::npos || at == std::string::npos)
        throw std::runtime_error(std::string("no <") + section + "><" + tag + "> in the intrinsics");
    return std::strtod(xml.c_str() + at + std::strlen(tag) + 2, nullptr);
}

opx_linkset *load_pr2(const std::string &dir) {
    const std::string urdf = dir + "/" + kUrdfFile;
    const std::string package = "moveit_resources_pr2_description=" + dir + "/robots/pr2_description";
    const char *dirs[1] = {package.c_str()};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    opx_linkset *robot = nullptr;
    check(opx_linkset_load_urdf_file(urdf.c_str(), &options, &robot), "opx_linkset_load_urdf_file");
    return robot;
}

opx_pose link_pose(const opx_linkset *robot, const char *name) {
    uint32_t link = 0;
    opx_pose pose = OPX_POSE_IDENTITY;
    check(opx_linkset_find_link(robot, name, &link), "opx_linkset_find_link");
    check(opx_linkset_get_pose(robot, link, &pose), "opx_linkset_get_pose");
    return pose;
}

}  // namespace

std::string data_dir() {
    const char *env = std::getenv("OPX_DATA_DIR");
    return env != nullptr && env[0] != '\0' ? env : OPX_RENDER_DATA_DIR;
}

std::string missing_pr2_data(const std::string &dir) {
    for (const char *file : {kDepthFile, kIntrinsicsFile, kUrdfFile}) {
        const std::string path = dir + "/" + file;
        if (!std::ifstream(path)) return path;
    }
    return "";
}

RealFrame load_real_frame(const std::string &dir) {
    const std::string xml = read_text(dir + "/" + kIntrinsicsFile);
    RealFrame frame;
    frame.camera.fx = xml_number(xml, "depth", "focal_length_x");
    frame.camera.fy = xml_number(xml, "depth", "focal_length_y");
    frame.camera.cx = xml_number(xml, "depth", "principal_point_x");
    frame.camera.cy = xml_number(xml, "depth", "principal_point_y");
    const double metres_per_unit = xml_number(xml, "depth", "z_multiplication_factor");
    depth_image image;
    char error[700];
    if (depth_image_read_file((dir + "/" + kDepthFile).c_str(), &image, error, sizeof error) != 0)
        throw std::runtime_error(error);
    frame.camera.width = image.width, frame.camera.height = image.height;
    frame.depth.resize(static_cast<size_t>(image.width) * image.height);
    for (size_t i = 0; i < frame.depth.size(); ++i)
        frame.depth[i] = static_cast<float>(image.pixels[i] * metres_per_unit);
    depth_image_free(&image);
    return frame;
}

std::vector<float> composite_robot(const opx_linkset *robot, const Camera &camera,
                                   const std::vector<float> &scene_depth) {
    return nearer_depth(scene_depth, render_depth(robot, camera));
}

int pr2_arm_pose_count() { return static_cast<int>(sizeof kArmPoses / sizeof kArmPoses[0]); }

void pr2_joint_positions(int arm_pose, std::vector<const char *> &names, std::vector<double> &positions) {
    if (arm_pose < 0 || arm_pose >= pr2_arm_pose_count()) throw std::invalid_argument("no such PR2 arm pose");
    const ArmPose &pose = kArmPoses[arm_pose];
    names.assign(1, "head_tilt_joint");
    positions.assign(1, kHeadTilt);
    for (int j = 0; j < 7; ++j) {
        names.push_back(kRightArm[j]), positions.push_back(pose.right[j]);
        names.push_back(kLeftArm[j]), positions.push_back(pose.left[j]);
    }
}

Pr2Scene make_pr2_scene(const std::string &dir, int arm_pose) {
    const std::string missing = missing_pr2_data(dir);
    if (!missing.empty()) throw std::runtime_error(missing + " not found; set OPX_DATA_DIR");
    RealFrame frame = load_real_frame(dir);
    Pr2Scene scene;
    scene.robot = load_pr2(dir);
    try {
        std::vector<const char *> names;
        std::vector<double> positions;
        pr2_joint_positions(arm_pose, names, positions);
        const opx_pose base = OPX_POSE_IDENTITY;
        check(opx_linkset_set_named_joint_positions(scene.robot, names.data(), positions.data(), names.size(), &base),
              "opx_linkset_set_named_joint_positions");
        scene.camera = frame.camera;
        scene.camera.pose = link_pose(scene.robot, kCameraLink);
        scene.real_depth = std::move(frame.depth);
        scene.robot_depth = render_depth(scene.robot, scene.camera);
        scene.composite = nearer_depth(scene.real_depth, scene.robot_depth);
    } catch (...) {
        destroy(scene);
        throw;
    }
    return scene;
}

void destroy(Pr2Scene &scene) {
    opx_linkset_destroy(scene.robot);
    scene.robot = nullptr;
}

}  // namespace render
