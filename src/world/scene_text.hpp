// MoveIt's .scene text (PlanningScene::saveGeometryToStream): a scene
// name line, then per object
//   * NAME
//   X Y Z                  the object's pose (MoveIt 1.1 and later)
//   QX QY QZ QW
//   SHAPE_COUNT
//   per shape: its kind and sizes, its pose in the object frame (two
//   lines as above), a colour line R G B A (ignored):
//     box X Y Z            full edge lengths
//     sphere RADIUS
//     cylinder RADIUS LENGTH   along z (note: radius first)
//     mesh V T, then V lines X Y Z and T lines of three vertex indices
//     cone and plane are refused (OPX_ERROR_UNSUPPORTED)
//   SUBFRAME_COUNT, then per subframe NAME and a pose (MoveIt 1.1 and
//   later; ignored)
// and a line "." at the end.  Files without object poses and subframes
// (older MoveIt) are told apart as MoveIt does: the line after the first
// "*" line holds a space (a pose) or not (a count).  An object replaces one
// of the same name.
#pragma once

#include "world/world.hpp"

#include <string>

namespace octoprox {

// Throws ApiError naming `source`, the line and the field on bad input.
void read_scene_text(const std::string &text, const std::string &source, World &world);

}  // namespace octoprox
