// What urdfdom does not keep or explain, and what it must not be handed:
// the order of links and joints in the file (urdfdom stores them in maps),
// structural errors with a clear message (urdfdom reports them on stderr
// only), a checked copy of the parts the library reads (urdfdom parses
// that, never the caller's text), and the disabled pairs of an SRDF.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace octoprox {

struct UrdfOutline {
    std::vector<std::string> links;   // names, in file order
    std::vector<std::string> joints;  // names, in file order
    std::vector<size_t> collision_counts;  // per link, its <collision> elements
    // The URDF for urdfdom: the robot, its links with their collisions and
    // its joints, every value checked (see urdf_elements.hpp).
    std::string checked_xml;
};

// Checks `xml` (see check_xml_text), parses it with tinyxml and checks
// everything urdfdom would reject or mishandle: a <robot> root of version
// 1.0, named links and joints, joints with a type, a parent and a child
// that exist, mimic joints that exist, one kinematic tree (see
// check_kinematic_tree), and the values of the parts the library reads.
// Throws ApiError (CORRUPT, UNSUPPORTED) prefixed with `source`.
UrdfOutline read_urdf_outline(const std::string &xml, const std::string &source);

// The <disable_collisions link1 link2> pairs of an SRDF file.  Throws
// ApiError (IO, CORRUPT) prefixed with `source`.
std::vector<std::pair<std::string, std::string>> read_srdf_disabled_pairs(const std::string &path,
                                                                          const std::string &source);

}  // namespace octoprox
