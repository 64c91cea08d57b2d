// Scene F of the tables: no object touches an occupied cell, so a
// collision query must traverse everything to answer "no".
#pragma once

#include <vector>

#include "scene.hpp"

namespace paper_tables {

struct FreeSceneReport {
    size_t redrawn_objects = 0;  // objects that collided as drawn (scene H)
    size_t redraws = 0;          // poses drawn in all
};

// Scene F from the drawn scene H: every object that collides (decided by
// OctoProx, max_contacts 1) as a primitive OR as its mesh gets new random
// poses until it collides as neither, so one scene F serves both variants.
std::vector<SceneObject> make_free_scene(const std::vector<SceneObject> &drawn, const opx_octree *tree,
                                         const SceneParameters &parameters, FreeSceneReport &report);

}  // namespace paper_tables
