#include "free_scene.hpp"

#include <stdexcept>

#include "opx_pipelines.hpp"

namespace paper_tables {
namespace {

// The map is sparse (7,784 cells of 8 million), so a free pose is found in
// a few draws; this bound only turns a bug into an error.
constexpr size_t kMaxDrawsPerObject = 100000;

bool collides_in_any_variant(ObjectProbe &probe, const opx_octree *tree, const SceneObject &object) {
    return probe.collides(tree, object, Variant::kPrimitives) || probe.collides(tree, object, Variant::kMeshes);
}

}  // namespace

std::vector<SceneObject> make_free_scene(const std::vector<SceneObject> &drawn, const opx_octree *tree,
                                         const SceneParameters &parameters, FreeSceneReport &report) {
    ObjectProbe probe;
    Rng rng(parameters.redraw_seed);
    std::vector<SceneObject> free_objects = drawn;
    report = FreeSceneReport();
    for (SceneObject &object : free_objects) {
        if (!collides_in_any_variant(probe, tree, object)) continue;
        ++report.redrawn_objects;
        size_t draws = 0;
        do {
            if (++draws > kMaxDrawsPerObject) throw std::runtime_error("no collision-free pose found");
            object.pose = draw_pose(parameters, rng);
        } while (collides_in_any_variant(probe, tree, object));
        report.redraws += draws;
    }
    return free_objects;
}

}  // namespace paper_tables
