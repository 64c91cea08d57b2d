// The "2 cm Kinect-like frame" of Table I: the generated room of
// examples/support/room_frame.c (640 x 480 points from its own camera)
// ray-cast into a 2 cm octree, the same leaves in OctoMap, and the 300
// objects of scene F shrunk to the room's scale and drawn inside it.
#pragma once

#include <vector>

#include "pr2_scene.hpp"
#include "scene.hpp"

namespace paper_tables {

struct RoomScene {
    FrameMaps maps;                   // resolution, occupied leaves, both trees
    std::vector<SceneObject> objects;  // 100 spheres, 100 boxes, 100 cylinders
    size_t frame_points = 0;          // finite points of the frame
};

// Throws std::runtime_error when the frame cannot be generated.
RoomScene make_room_scene(double resolution);

}  // namespace paper_tables
