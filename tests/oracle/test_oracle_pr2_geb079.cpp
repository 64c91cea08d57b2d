// Real data: the geb079 building map (OctoMap .bt, 0.08 m) and the PR2's 18
// collision meshes (binary STL), one OPX_SHAPE_MESH link per file, at 1,000
// random poses inside the occupied bounds of the map (each link at its own
// random position and uniform random rotation, random paddings, some links
// disabled), and each pose again with one link alone (so that yes/no
// answers go both ways).  The yes/no answers and the contact sets are
// compared with the brute-force oracle (every triangle against every
// occupied leaf near it).
#include "oracle_engine.hpp"
#include "oracle_scenes.hpp"
#include "stl_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

using namespace oracle;

namespace {

constexpr int kPoses = 1000;
constexpr int kExpectedMeshes = 18;

std::vector<std::string> stl_files(const std::string &folder) {
    std::vector<std::string> files;
    for (const auto &entry : std::filesystem::recursive_directory_iterator(folder)) {
        std::string extension = entry.path().extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
        if (entry.is_regular_file() && extension == ".stl") files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

bool load_robot(const std::string &folder, RobotSpec &robot) {
    size_t triangles = 0;
    for (const std::string &file : stl_files(folder)) {
        StlMesh mesh;
        std::string error;
        if (!read_binary_stl(file, mesh, error)) {
            std::printf("FAIL: %s\n", error.c_str());
            return false;
        }
        LinkSpec link;
        link.name = std::filesystem::path(file).stem().string();
        ShapeSpec shape;
        shape.kind = OPX_SHAPE_MESH;
        shape.vertices = mesh.vertices;
        shape.triangles = mesh.triangles;
        triangles += mesh.triangles.size();
        link.shapes.push_back(std::move(shape));
        robot.links.push_back(std::move(link));
    }
    std::printf("PR2: %zu meshes, %zu triangles\n", robot.links.size(), triangles);
    if (robot.links.size() == kExpectedMeshes) return true;
    std::printf("FAIL: expected %d STL meshes under %s\n", kExpectedMeshes, folder.c_str());
    return false;
}

// Only the occupied leaves can be obstacles at the octree's threshold: the
// oracle indexes those (all leaves are still checked by check_leaves).
void index_occupied(Scene &scene) {
    index_scene(scene, false);
    const ObstacleRule rule(scene.options.occupied_threshold, OPX_UNKNOWN_FREE);
    std::vector<MapCell> occupied;
    for (const MapCell &cell : scene.cells->cells())
        if (rule(cell)) occupied.push_back(cell);
    scene.cells = std::make_unique<CellIndex>(std::move(occupied), 4.0 * scene.options.resolution);
}

}  // namespace

int main() {
    elapsed_seconds();
    const std::string map_path = data_path("maps/geb079.bt");
    const std::string mesh_folder = data_path("robots/pr2_description/urdf/meshes");
    if (map_path.empty() || mesh_folder.empty()) return 77;
    RobotSpec robot;
    if (!load_robot(mesh_folder, robot)) return 1;
    Scene scene;
    if (opx_octree_load_file(map_path.c_str(), nullptr, &scene.tree) != OPX_OK) {
        std::printf("FAIL: loading %s: %s\n", map_path.c_str(), opx_last_error());
        return 1;
    }
    scene.label = "geb079";
    index_occupied(scene);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    if (opx_octree_get_stats(scene.tree, &stats) != OPX_OK || !stats.has_occupied) return 1;
    scene.low = Vec3(stats.occupied_min[0], stats.occupied_min[1], stats.occupied_min[2]);
    scene.high = Vec3(stats.occupied_max[0], stats.occupied_max[1], stats.occupied_max[2]);
    std::printf("geb079: %zu leaves, %zu occupied; occupied bounds (%.2f %.2f %.2f) .. (%.2f %.2f %.2f); %.1f s\n",
                scene.leaves.size(), scene.cells->cells().size(), scene.low.x(), scene.low.y(), scene.low.z(),
                scene.high.x(), scene.high.y(), scene.high.z(), elapsed_seconds());

    const uint64_t seed = env_number("OPX_ORACLE_SEED", 79);
    Rng rng(seed);
    RobotOptions options;
    options.max_padding = 0.05;
    options.disabled_fraction = 0.1;
    randomize_state(rng, robot, options, scene.low, scene.high);
    opx_linkset *links = build_linkset(robot);
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    Checker checker("oracle_pr2_geb079");
    for (int i = 0; i < kPoses; ++i) {
        randomize_state(rng, robot, options, scene.low, scene.high);
        update_linkset(links, robot);
        const std::vector<PlacedShape> placed = place_robot(robot);
        QueryCase c;
        c.robot = &robot, c.placed = &placed, c.cells = scene.cells.get();
        c.resolution = scene.options.resolution, c.occupied_threshold = scene.options.occupied_threshold;
        c.label = "geb079 pose " + std::to_string(i) + " (seed " + std::to_string(seed) + ")";
        checker.check(query, scene.tree, links, c);
        // The same pose with one link alone: yes/no answers both ways.
        const size_t alone = size_t(rng.integer(0, kExpectedMeshes - 1));
        for (size_t k = 0; k < robot.links.size(); ++k) robot.links[k].enabled = k == alone;
        update_linkset(links, robot);
        const std::vector<PlacedShape> single = place_robot(robot);
        c.placed = &single;
        c.label += " link " + robot.links[alone].name + " alone";
        checker.check(query, scene.tree, links, c);
    }
    opx_query_destroy(query);
    opx_linkset_destroy(links);
    return checker.finish(elapsed_seconds());
}
