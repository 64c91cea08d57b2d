// Link sets from URDF: links and collision shapes (urdfdom parses, assimp
// reads meshes), the joint tree, and optionally SRDF disabled pairs.
#pragma once

#include "robot/linkset.hpp"
#include "robot/resource_paths.hpp"
#include "robot/robot_model.hpp"

#include <string>

namespace octoprox {

struct UrdfInput {
    std::string xml;
    std::string source;     // names the input in messages: "path '/a.urdf'" or "xml"
    ResourcePaths paths;
    std::string srdf_path;  // "" = none
};

// Fills an empty link set and robot model; all links posed by FK at zero
// with the root at the origin.  Throws ApiError (IO, CORRUPT).
void load_urdf(const UrdfInput &input, LinkSet &links, RobotModel &robot);

}  // namespace octoprox
