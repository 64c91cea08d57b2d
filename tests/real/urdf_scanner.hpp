// An independent, deliberately simple reading of a URDF for the tests:
// string scanning (no XML library, no urdfdom), and forward kinematics
// composed by hand (own rpy and axis-angle code, not the library's).
#pragma once

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace scan {

// One element: its opening tag (with attributes) and its body ("" when
// self-closing).
struct Element {
    std::string open;
    std::string body;
};

// Every <tag ...> or <tag> in `xml` (not <tagX...>), in order.
std::vector<Element> elements(const std::string &xml, const std::string &tag);
// The attribute `name` of an opening tag, or `fallback`.
std::string attr(const std::string &open, const std::string &name, const std::string &fallback = "");
Eigen::Vector3d vec3(const std::string &text);

struct Collision {
    std::string kind;      // box, sphere, cylinder, mesh
    std::string filename;  // mesh only
};

struct Link {
    std::string name;
    std::vector<Collision> collisions;
};

struct Joint {
    std::string name, type, parent, child;
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero(), rpy = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
    bool has_limit = false;
    double lower = 0, upper = 0;
    std::string mimic;
    double multiplier = 1, offset = 0;
};

struct Robot {
    std::vector<Link> links;    // file order
    std::vector<Joint> joints;  // file order (only real joints, not transmissions)
};

// Comments removed first (the PR2 URDF has commented-out collisions).
std::string without_comments(const std::string &xml);
Robot read_robot(const std::string &xml);

struct Frame {
    Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
    Eigen::Vector3d pos = Eigen::Vector3d::Zero();
};

Eigen::Matrix3d rpy_matrix(const Eigen::Vector3d &rpy);
Eigen::Matrix3d axis_angle_matrix(Eigen::Vector3d axis, double angle);
Eigen::Matrix3d quaternion_matrix(const double q[4]);  // x y z w

// Every link's frame (by name) for joint values by name (fixed joints
// and mimic joints take their value from the rules, not from `values`).
std::map<std::string, Frame> forward_kinematics(const Robot &robot, const std::map<std::string, double> &values,
                                                const Frame &root);

}  // namespace scan
