// What both scene readers (MoveIt's planning scene YAML, MoveIt's .scene
// text) produce, and how it changes a World: the update of one collision
// object (moveit_msgs/CollisionObject: ADD, REMOVE, APPEND, MOVE), applied
// in file order, and the errors they report, which name the source (a
// file's path), the line and the field.
#pragma once

#include "world/world.hpp"

#include <octoprox/common.h>

#include <string>
#include <vector>

namespace octoprox {

// Where in a scene source something is: its errors read
// "SOURCE: line LINE: FIELD: what".
struct SceneWhere {
    const std::string *source = nullptr;
    int line = 0;  // 1-based; 0: unknown
    std::string field;
};

// Throws ApiError(status) with the message above.
[[noreturn]] void scene_fail(const SceneWhere &where, const std::string &what,
                             opx_status status = OPX_ERROR_CORRUPT);

// moveit_msgs/CollisionObject operations.
enum class SceneOperation { kAdd = 0, kRemove = 1, kAppend = 2, kMove = 3 };

// A shape as a message gives it: its pose (def.local) is in the message's
// object frame.
struct SceneObjectUpdate {
    std::string id;
    SceneOperation operation = SceneOperation::kAdd;
    bool has_pose = false;  // the message's `pose` (else identity)
    Pose pose;
    std::vector<ShapeDef> shapes;
    // MOVE: the shapes' new poses, when the message gives them.
    std::vector<Pose> shape_poses;
    SceneWhere where;  // the object's first line, for errors
};

// Applies one update as MoveIt's PlanningScene does:
//  ADD     replaces an object of the same id; an object of one shape and
//          no pose takes the shape's pose as its own (the shape then sits
//          at its origin), so a later MOVE places it as MoveIt would;
//  APPEND  adds the shapes to the object (made when missing), where the
//          message places them, the object keeping its pose;
//  REMOVE  removes the object (every object when the id is empty); a
//          missing object is no error (MoveIt only warns);
//  MOVE    sets the object's pose (and its shapes' poses, when given, one
//          per shape); a missing object is an error.
void apply_update(World &world, SceneObjectUpdate update);

// Removes every object (a planning scene that is not a diff replaces the
// world).
void clear_world(World &world);

// Pose helpers on the library's Pose.
Pose compose(const Pose &a, const Pose &b);  // a * b
Pose inverse(const Pose &pose);

}  // namespace octoprox
