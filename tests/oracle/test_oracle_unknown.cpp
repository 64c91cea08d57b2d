// Unknown space counted as occupied (OPX_UNKNOWN_OCCUPIED).
//
// Design: the oracle derives the unknown cubes from the known leaves alone
// (oracle_cells.hpp: every ancestor of a known leaf is an inner node; each
// child of an inner node that is neither an inner node nor a known leaf is a
// maximal unknown cube; no leaf at all: the whole map cube).  The
// derivation is checked two ways before it judges the library:
//  - volume: known leaves and unknown cubes tile the map cube exactly
//    (their volumes, in finest cells, add up to 2^48);
//  - point location: for random points, the oracle's cube holding the point
//    (a known leaf or an unknown cube) is the cell opx_octree_classify
//    reports (class, centre, size; for unknown space "the largest
//    unobserved cube holding the point").
// Then the collision answers and contact sets (unknown cubes included) are
// compared as for the other maps.  Maps: a 2 x 2 x 2 m region observed by
// ray casting from inside (walls of endpoints with a few holes, so the
// unknown is just outside and behind the holes) with links inside it, small
// random maps, and the empty map (every link touches the root cube).
#include "oracle_engine.hpp"
#include "oracle_enclosure.hpp"
#include "oracle_scenes.hpp"

#include <cmath>
#include <cstdio>

using namespace oracle;

namespace {

// A walled cube observed from inside, with 2 to 5 holes in its walls.
std::unique_ptr<Scene> observed_box_scene(Rng &rng) {
    EnclosureOptions options;
    options.free_threshold = rng.chance(0.5) ? 0.4 : 0.5;
    options.min_holes = 2, options.max_holes = 5;
    return enclosed_scene(rng, options);
}

std::unique_ptr<Scene> empty_scene(Rng &rng) {
    auto scene = std::make_unique<Scene>();
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = rng.uniform(0.05, 0.25);
    if (opx_octree_create(&options, &scene->tree) != OPX_OK) std::exit(1);
    scene->low = Vec3::Constant(-3.0), scene->high = Vec3::Constant(3.0);
    scene->label = "empty map";
    index_scene(*scene, true);
    return scene;
}

// Known leaves and unknown cubes tile the map cube: 8^16 finest cells.
bool check_tiling(const Scene &scene) {
    unsigned __int128 volume = 0;
    for (const MapCell &cell : scene.cells->cells()) volume += (unsigned __int128)1 << (3 * (16 - cell.key.depth));
    const bool ok = volume == (unsigned __int128)1 << 48;
    if (!ok) std::printf("MISMATCH %s: known leaves and unknown cubes do not tile the map cube\n", scene.label.c_str());
    return ok;
}

// The oracle's cell holding p: the deepest key present, from the finest up.
const MapCell *oracle_cell_at(const Scene &scene, const Vec3 &p) {
    for (int depth = 16; depth >= 0; --depth) {
        const double size = std::ldexp(scene.options.resolution, 16 - depth);
        const double offset = std::ldexp(1.0, depth - 1);
        const CellKey key{depth, int64_t(std::floor(p.x() / size + offset)), int64_t(std::floor(p.y() / size + offset)),
                          int64_t(std::floor(p.z() / size + offset))};
        if (const MapCell *cell = scene.cells->find(key)) return cell;
    }
    return nullptr;
}

int check_classify(Rng &rng, const Scene &scene, int points) {
    int mismatches = 0;
    for (int i = 0; i < points; ++i) {
        // Near the data mostly, sometimes far away (large unknown cubes).
        const double reach = rng.chance(0.8) ? 1.5 : 500.0;
        const Vec3 p = 0.5 * (scene.low + scene.high) + rng.point(Vec3::Constant(-reach), Vec3::Constant(reach));
        opx_cell_info info = OPX_CELL_INFO_INIT;
        if (opx_octree_classify(scene.tree, p.data(), &info) != OPX_OK) return ++mismatches;
        const MapCell *cell = oracle_cell_at(scene, p);
        const bool same = cell && cell->cell_class == info.cell_class && cell->size == info.size &&
                          (cell->cell.center - Vec3(info.center[0], info.center[1], info.center[2])).norm() <=
                              1e-9 * cell->size &&
                          (cell->unknown() ? info.probability == 0.5 : info.probability == cell->probability);
        if (same) continue;
        if (++mismatches <= 5)
            std::printf("MISMATCH %s: point (%.17g, %.17g, %.17g): classify says class %d size %.17g centre (%.17g, "
                        "%.17g, %.17g) p %.17g; oracle: %s class %d size %.17g\n",
                        scene.label.c_str(), p.x(), p.y(), p.z(), info.cell_class, info.size, info.center[0],
                        info.center[1], info.center[2], info.probability, cell ? "cell" : "NO cell",
                        cell ? cell->cell_class : -1, cell ? cell->size : 0.0);
    }
    return mismatches;
}

void run_scene(Rng &rng, const Scene &scene, opx_query *query, Checker &checker, const Campaign &campaign) {
    if (!check_tiling(scene)) checker.fail(scene.label + ": tiling");
    if (check_classify(rng, scene, 2000) > 0) checker.fail(scene.label + ": point location (see above)");
    run_campaign(rng, scene, campaign, query, checker);
}

}  // namespace

int main() {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 1638);
    const int boxes = int(env_number("OPX_ORACLE_SCENES", 12));
    std::printf("oracle_unknown: seed %llu, %d observed boxes\n", (unsigned long long)seed, boxes);
    Rng rng(seed);
    Checker checker("oracle_unknown");
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    Campaign inside;  // small links inside the observed region
    inside.robot.min_scale = 0.05, inside.robot.max_scale = 0.5, inside.robot.max_padding = 0.1;
    inside.unknown_policy = OPX_UNKNOWN_OCCUPIED;
    inside.robots = 5, inside.states = 500;
    for (int i = 0; i < boxes; ++i) {
        std::unique_ptr<Scene> scene = observed_box_scene(rng);
        scene->label = "box " + std::to_string(i) + " (" + scene->label + ")";
        std::printf("%s: %zu known leaves, %zu cells with the unknown cubes\n", scene->label.c_str(),
                    scene->leaves.size(), scene->cells->cells().size());
        inside.low = scene->low, inside.high = scene->high;
        run_scene(rng, *scene, query, checker, inside);
    }
    Campaign anywhere = inside;  // random maps: links near scattered data
    anywhere.robots = 2, anywhere.states = 200;
    for (int i = 0; i < 5; ++i) {
        std::unique_ptr<Scene> scene = random_small_scene(rng, true);
        scene->label = "random " + std::to_string(i) + " (" + scene->label + ")";
        anywhere.low = scene->low, anywhere.high = scene->high;
        run_scene(rng, *scene, query, checker, anywhere);
    }
    std::unique_ptr<Scene> empty = empty_scene(rng);
    anywhere.low = empty->low, anywhere.high = empty->high;
    run_scene(rng, *empty, query, checker, anywhere);
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}
