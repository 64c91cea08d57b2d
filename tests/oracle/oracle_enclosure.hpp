// Small maps observed from inside: the six walls of a cube, made of
// endpoints every half cell and ray cast from sensors near its centre, so
// the inside is known free (or uncertain), the walls occupied, and unknown
// space lies just outside the walls and behind holes in them.  With no hole
// the observed region is fully enclosed.  test_oracle_unknown.cpp's
// observed boxes are these with 2 to 5 holes.
#pragma once

#include "oracle_scenes.hpp"

namespace oracle {

struct EnclosureOptions {
    double min_resolution = 0.1, max_resolution = 0.2;
    double free_threshold = 0.5;   // 0.4: cells seen once free are uncertain
    int min_holes = 0, max_holes = 0;  // holes in the walls
    int sensors = 2;               // ray-cast frames
    double half = 1.05;            // half edge of the walled cube (metres)
    bool with_unknown = true;      // index the unknown cubes too
};

// The scene's low/high (where links go) is the inside of the walls, 0.15 m in.
std::unique_ptr<Scene> enclosed_scene(Rng &rng, const EnclosureOptions &options);

// A map of the given cells (one hit each at their centres) and nothing else.
std::unique_ptr<Scene> cells_scene(double resolution, const std::vector<Vec3> &points, bool with_unknown);

}  // namespace oracle
