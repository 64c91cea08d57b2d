// The scenes of opx-bench-world: the PR2 of Table IV (root link at the
// map origin, head tilted), its reaching configurations (the sampling of
// opx-bench-batch and Table IV), the real 2 cm RGB-D frame as seen from its
// head camera, and clutter of random objects at the arms' height: boxes,
// cylinders and spheres of 8-24 cm, every tenth one given as a triangle
// mesh of its shape (paper_tables::object_mesh), none touching the robot's
// still body (base, torso, head).  Every scene holds the same 10 objects in
// the box the arms' links reach; the others lie around it at the same
// density, 30 cm or more outside it, in a region about 10 or 100 times its
// floor area (as high): a scene of 100 or 1,000 objects has more objects,
// not more within reach.  Each object set exists twice: as an opx_world, and as FCL
// collision objects in a dynamic AABB tree.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fcl_pipelines.hpp"
#include "opx_pipelines.hpp"
#include "pr2_configurations.hpp"
#include "pr2_fcl.hpp"
#include "scene.hpp"

namespace world_bench {

struct WorldDeleter {
    void operator()(opx_world *world) const { opx_world_destroy(world); }
};
using OpxWorldPtr = std::unique_ptr<opx_world, WorldDeleter>;

struct Robot {
    paper_tables::OpxLinksetPtr links;
    std::unique_ptr<paper_tables::FclRobot> fcl;
    std::vector<paper_tables::Configuration> configurations;  // joints, and link poses for FCL
    std::vector<char> moving;  // per link: moves between configurations
    double reach_min[3] = {0, 0, 0}, reach_max[3] = {0, 0, 0};  // the moving links' origins, map frame
};

// The PR2 with `count` reaching configurations drawn from `seed`.
Robot load_robot(size_t count, uint64_t seed);

// The real RGB-D frame at 2 cm, seen from the PR2's head camera.
paper_tables::OpxOctreePtr real_map(const Robot &robot);

struct ObjectSet {
    std::vector<paper_tables::SceneObject> objects;
    std::vector<char> is_mesh;  // per object: given as a triangle mesh
    size_t meshes = 0;
    OpxWorldPtr world;
    paper_tables::FclObjectSet fcl;  // the same objects, one manager
};

// `count` objects (see above); the first 10 are the same for every count.
ObjectSet draw_objects(Robot &robot, size_t count, uint64_t seed);

// "10 boxes, cylinders and spheres (1 as meshes)".
std::string describe(const ObjectSet &set);

}  // namespace world_bench
