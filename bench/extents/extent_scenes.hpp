// The scenes of opx-bench-extents: tabletops and shelves of known boxes
// and cylinders in front of a 7-joint arm based at the origin (z up), each
// object's surface sampled into a cloud as a depth sensor would see it
// densely, and the same objects for FCL as the exact reference.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fcl_pipelines.hpp"

namespace extents_bench {

struct SceneObject {
    enum Kind { kBox, kCylinder } kind = kBox;
    Eigen::Vector3d size = Eigen::Vector3d::Zero();  // box: full edges
    double radius = 0.0, length = 0.0;                // cylinder along its z
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // map frame
};

struct Scene {
    std::string name;
    std::vector<SceneObject> objects;
};

// A table in front of the arm with 3 to 7 boxes and cylinders on it.
Scene tabletop_scene(uint64_t seed);
// A shelf of three boards in front of the arm, objects on each board.
Scene shelf_scene(uint64_t seed);

// Points on every object's surface, at most `spacing` apart (x y z,
// map frame, packed).
std::vector<double> sample_surfaces(const Scene &scene, double spacing);

// The objects as FCL collision objects in one manager.
struct FclScene {
    std::vector<paper_tables::FclObjectPtr> objects;
    std::unique_ptr<paper_tables::FclManager> manager;
};
FclScene fcl_scene(const Scene &scene);

}  // namespace extents_bench
