// Random small maps (occupied, free and uncertain cells at several levels,
// some reloaded from .ot or .bt bytes) and random robots of all six shape
// kinds, unknown space free: the library's yes/no answers and contact sets
// against the brute-force oracle.
#include "oracle_engine.hpp"
#include "oracle_scenes.hpp"

#include <cstdio>

using namespace oracle;

namespace {

// Replaces the scene's octree by its copy saved to memory and loaded back.
// .ot keeps every log-odds: the oracle keeps its cells from the original, so
// a lossy round trip (or stale inner nodes after loading) shows up as
// mismatches.  .bt keeps only occupied/free: the oracle re-reads the leaves.
bool reload(Scene &scene, int32_t format) {
    size_t size = 0;
    opx_octree_save_memory(scene.tree, format, nullptr, 0, &size);
    std::vector<unsigned char> bytes(size);
    opx_octree *copy = nullptr;
    if (opx_octree_save_memory(scene.tree, format, bytes.data(), bytes.size(), &size) != OPX_OK ||
        opx_octree_load_memory(bytes.data(), size, &scene.options, &copy) != OPX_OK) {
        std::printf("FAIL: %s: save/load round trip: %s\n", scene.label.c_str(), opx_last_error());
        return false;
    }
    opx_octree_destroy(scene.tree);
    scene.tree = copy;
    scene.label += format == OPX_FORMAT_OT ? ", reloaded from .ot" : ", reloaded from .bt";
    if (format == OPX_FORMAT_BT) index_scene(scene, false);
    return true;
}

}  // namespace

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 20240601);
    const int scenes = int(env_number("OPX_ORACLE_SCENES", 60));
    std::printf("oracle_random_scenes: seed %llu, %d scenes\n", (unsigned long long)seed, scenes);
    Rng rng(seed);
    Checker checker("oracle_random_scenes");
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    int reloaded[2] = {0, 0};
    for (int i = 0; i < scenes; ++i) {
        std::unique_ptr<Scene> scene = random_small_scene(rng, false);
        scene->label = "scene " + std::to_string(i) + " (" + scene->label + ", seed " + std::to_string(seed) + ")";
        const double draw = rng.uniform(0.0, 1.0);
        if (draw < 0.35) {
            const int32_t format = draw < 0.2 ? OPX_FORMAT_OT : OPX_FORMAT_BT;
            if (!reload(*scene, format)) return 1;
            ++reloaded[format == OPX_FORMAT_OT ? 0 : 1];
        }
        Campaign campaign;
        // Smaller or fewer links now and then, so that many queries are clear.
        campaign.robot.max_links = rng.integer(1, 6);
        campaign.robot.max_scale = rng.uniform(0.2, 1.0);
        // Links may stick out of the mapped region a little.
        campaign.low = scene->low - Vec3::Constant(0.5), campaign.high = scene->high + Vec3::Constant(0.5);
        run_campaign(rng, *scene, campaign, query, checker);
    }
    opx_query_destroy(query);
    std::printf("scenes reloaded from .ot: %d, from .bt: %d\n", reloaded[0], reloaded[1]);
    return checker.finish(elapsed_seconds());
}
