#include "unit_scenes.hpp"

#include "octree/octomap_io.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <tuple>

namespace unit {

octoprox::ShapeDef random_mesh(std::mt19937_64 &rng, int vertices, int triangles, const octoprox::Vec3 &offset) {
    std::uniform_real_distribution<double> coordinate(-0.3, 0.3);
    octoprox::ShapeDef def;
    def.kind = octoprox::ShapeKind::kMesh;
    for (int i = 0; i < vertices; ++i)
        def.vertices.push_back(offset + octoprox::Vec3(coordinate(rng), coordinate(rng), coordinate(rng)));
    std::uniform_int_distribution<uint32_t> pick(0, static_cast<uint32_t>(vertices - 1));
    for (int t = 0; t < triangles; ++t) def.triangles.push_back({pick(rng), pick(rng), pick(rng)});
    octoprox::build_mesh_tree(def);
    return def;
}

using octoprox::Aabb;
using octoprox::Vec3;

std::string data_dir() {
    const char *env = std::getenv("OPX_DATA_DIR");
    if (env != nullptr && env[0] != '\0') return env;
    return OPX_DEFAULT_DATA_DIR;
}

bool file_exists(const std::string &path) { return std::ifstream(path).good(); }

bool data_required() {
    const char *env = std::getenv("OPX_REQUIRE_DATA");
    return env != nullptr && std::string(env) == "1";
}

std::vector<Aabb> random_boxes(size_t n, double extent, double max_edge, std::mt19937_64 &rng) {
    std::uniform_real_distribution<double> position(-extent, extent), edge(1e-3 * max_edge, max_edge);
    std::vector<Aabb> boxes;
    boxes.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3 centre(position(rng), position(rng), position(rng));
        const Vec3 half(0.5 * edge(rng), 0.5 * edge(rng), 0.5 * edge(rng));
        boxes.push_back(Aabb::from_center(centre, half));
    }
    return boxes;
}

std::unique_ptr<octoprox::SensorOctree> empty_octree(double resolution) {
    octoprox::OctreeParams params;
    params.resolution = resolution;
    return std::make_unique<octoprox::SensorOctree>(params);
}

std::unique_ptr<octoprox::SensorOctree> synthetic_octree(uint64_t seed) {
    constexpr size_t kCells = 7784;
    constexpr double kResolution = 0.2, kHalf = 20.0;
    auto tree = empty_octree(kResolution);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(-kHalf, kHalf);
    // One point per distinct cell (OctoMap's key: floor(coordinate / res)).
    std::set<std::tuple<long, long, long>> cells;
    std::vector<double> xyz;
    while (cells.size() < kCells) {
        const Vec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
        const auto key = std::make_tuple(std::lround(std::floor(p.x() / kResolution)),
                                         std::lround(std::floor(p.y() / kResolution)),
                                         std::lround(std::floor(p.z() / kResolution)));
        if (cells.insert(key).second) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    }
    octoprox::InsertSettings settings;
    settings.raycast = false;
    insert_xyz(*tree, xyz, settings);
    return tree;
}

void insert_xyz(octoprox::SensorOctree &tree, const std::vector<double> &xyz, const octoprox::InsertSettings &settings) {
    octoprox::PointSource points;
    points.data = reinterpret_cast<const unsigned char *>(xyz.data());
    points.count = xyz.size() / 3;
    points.stride = 3 * sizeof(double);
    points.is_double = true;
    tree.insert(points, settings);
}

std::unique_ptr<octoprox::SensorOctree> read_octree(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return octoprox::read_map_file_bytes(bytes, octoprox::OctreeParams());
}

octoprox::CellBoxes occupied_cells(const octoprox::SensorOctree &tree) {
    octoprox::CellBands bands;
    bands.threshold_log_odds = static_cast<float>(octoprox::log_odds(tree.params().occupied_threshold));
    bands.free_log_odds = static_cast<float>(octoprox::log_odds(tree.params().free_threshold));
    octoprox::CellBoxes cells;
    octoprox::extract_cell_boxes(tree, bands, cells, nullptr);
    return cells;
}

}  // namespace unit
