// What urdfdom does not keep or explain: the order of links and joints in
// the file (urdfdom stores them in maps), structural errors with a clear
// message (urdfdom only logs them), and the disabled pairs of an SRDF.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace octoprox {

struct UrdfOutline {
    std::vector<std::string> links;   // names, in file order
    std::vector<std::string> joints;  // names, in file order
    // Per link: the element name inside each <collision><geometry>, in
    // order ("" when there is none), to catch what urdfdom drops silently.
    std::vector<std::vector<std::string>> collision_geometry;
};

// Parses `xml` with tinyxml and checks what urdfdom would reject silently:
// a <robot> root, named links and joints, joints with a type, a parent and
// a child that exist, mimic joints that exist.  Throws
// ApiError(OPX_ERROR_CORRUPT) prefixed with `source`.
UrdfOutline read_urdf_outline(const std::string &xml, const std::string &source);

// The <disable_collisions link1 link2> pairs of an SRDF file.  Throws
// ApiError (IO, CORRUPT) prefixed with `source`.
std::vector<std::pair<std::string, std::string>> read_srdf_disabled_pairs(const std::string &path,
                                                                          const std::string &source);

}  // namespace octoprox
