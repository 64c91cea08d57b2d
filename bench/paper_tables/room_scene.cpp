#include "room_scene.hpp"

#include <stdexcept>

#include "support/room_frame.h"

namespace paper_tables {
namespace {

// Scene F's objects are 0.5-3 m in a 40 m cube; a tenth of that (5-30 cm:
// cups, boxes, forearms) is their size in a 6 x 5 x 2.8 m room.
constexpr double kObjectScale = 0.1;
constexpr uint64_t kRoomObjectSeed = 0x200Du;
// The room's inside (room_frame.h), map frame, metres.
constexpr double kRoomLow[3] = {-1.0, -2.5, 0.0};
constexpr double kRoomHigh[3] = {5.0, 2.5, 2.8};

SceneObject shrunk(SceneObject object) {
    object.radius *= kObjectScale;
    object.length *= kObjectScale;
    for (double &edge : object.size) edge *= kObjectScale;
    return object;
}

std::vector<SceneObject> draw_room_objects(int per_kind) {
    Rng rng(kRoomObjectSeed);
    std::vector<SceneObject> objects;
    for (ObjectKind kind : {ObjectKind::kSphere, ObjectKind::kBox, ObjectKind::kCylinder}) {
        for (int i = 0; i < per_kind; ++i) {
            SceneObject object = shrunk(draw_shape(kind, rng));
            for (int axis = 0; axis < 3; ++axis) object.pose.position[axis] = rng.uniform(kRoomLow[axis], kRoomHigh[axis]);
            const auto rotation = rng.rotation();
            for (int k = 0; k < 4; ++k) object.pose.orientation[k] = rotation[k];
            objects.push_back(object);
        }
    }
    return objects;
}

OpxOctreePtr insert_room(const room_frame &room, double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_octree *raw = nullptr;
    check_opx(opx_octree_create(&options, &raw), "opx_octree_create");
    OpxOctreePtr tree(raw);
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;  // ray casting
    for (int i = 0; i < 3; ++i) insert.sensor_pose.position[i] = room.sensor_position[i];
    for (int i = 0; i < 4; ++i) insert.sensor_pose.orientation[i] = room.sensor_orientation[i];
    check_opx(opx_octree_insert_points(tree.get(), room.xyz, room.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
              "opx_octree_insert_points");
    return tree;
}

}  // namespace

RoomScene make_room_scene(double resolution) {
    room_frame room;
    if (room_frame_generate(1, &room) != 0) throw std::runtime_error("out of memory generating the room frame");
    RoomScene scene;
    scene.frame_points = room.finite_count;
    scene.maps.resolution = resolution;
    scene.maps.opx = insert_room(room, resolution);
    room_frame_free(&room);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(scene.maps.opx.get(), &stats), "opx_octree_get_stats");
    scene.maps.occupied = stats.leaves_occupied;
    scene.maps.octomap = mirror_through_bt(scene.maps.opx.get(), resolution);
    const size_t mirrored = count_occupied_leaves(*scene.maps.octomap);
    if (mirrored != scene.maps.occupied)
        throw std::runtime_error("room: OctoMap mirror has " + std::to_string(mirrored) + " occupied leaves, OctoProx " +
                                 std::to_string(scene.maps.occupied));
    scene.objects = draw_room_objects(SceneParameters().objects_per_kind);
    return scene;
}

}  // namespace paper_tables
