#include "scene.hpp"

#include <stdexcept>
#include <string>

namespace paper_tables {
namespace {

constexpr int kMeshResolution = 16;  // sphere slices and stacks, cylinder sides

bool cell_is_unknown(const opx_octree *tree, const std::array<double, 3> &point) {
    opx_cell_info info = OPX_CELL_INFO_INIT;
    check_opx(opx_octree_classify(tree, point.data(), &info), "opx_octree_classify");
    return info.cell_class == OPX_CELL_UNKNOWN;
}

void insert_single_hit(opx_octree *tree, const std::array<double, 3> &point) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = OPX_INSERT_ENDPOINTS;
    check_opx(opx_octree_insert_points(tree, point.data(), 1, 0, OPX_SCALAR_FLOAT64, &options, nullptr),
              "opx_octree_insert_points");
}

uint64_t occupied_leaf_count(const opx_octree *tree) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
    return stats.leaves_occupied;
}

OpxOctreePtr make_random_opx_octree(const SceneParameters &parameters) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = parameters.resolution;
    opx_octree *raw = nullptr;
    check_opx(opx_octree_create(&options, &raw), "opx_octree_create");
    OpxOctreePtr tree(raw);
    Rng rng(parameters.octree_seed);
    // With endpoints mode and the default thresholds one hit makes a cell
    // occupied (p = 0.7), so every point landing in a new cell adds one.
    for (size_t inserted = 0; inserted < parameters.occupied_cells;) {
        const auto point = rng.point_in_cube(-parameters.half_extent, parameters.half_extent);
        if (!cell_is_unknown(tree.get(), point)) continue;
        insert_single_hit(tree.get(), point);
        ++inserted;
    }
    const uint64_t occupied = occupied_leaf_count(tree.get());
    if (occupied != parameters.occupied_cells)
        throw std::runtime_error("octree has " + std::to_string(occupied) + " occupied leaves, expected " +
                                 std::to_string(parameters.occupied_cells));
    return tree;
}

std::vector<opx_leaf> occupied_leaves(const opx_octree *tree) {
    size_t count = 0;
    const opx_status status = opx_octree_get_leaves(tree, OPX_MASK_OCCUPIED, nullptr, 0, &count);
    if (status != OPX_ERROR_BUFFER_TOO_SMALL) check_opx(status, "opx_octree_get_leaves (count)");
    std::vector<opx_leaf> leaves(count);
    check_opx(opx_octree_get_leaves(tree, OPX_MASK_OCCUPIED, leaves.data(), leaves.size(), &count),
              "opx_octree_get_leaves");
    return leaves;
}

// One hit per cell centre gives log-odds 0.847 (p 0.7): occupied.
std::shared_ptr<octomap::OcTree> mirror_in_octomap(const opx_octree *tree, const SceneParameters &parameters) {
    auto mirror = std::make_shared<octomap::OcTree>(parameters.resolution);
    for (const opx_leaf &leaf : occupied_leaves(tree)) {
        const octomap::point3d center(static_cast<float>(leaf.center[0]), static_cast<float>(leaf.center[1]),
                                      static_cast<float>(leaf.center[2]));
        mirror->updateNode(center, true);
    }
    const size_t occupied = count_occupied_leaves(*mirror);
    if (occupied != parameters.occupied_cells)
        throw std::runtime_error("OctoMap mirror has " + std::to_string(occupied) + " occupied leaves");
    return mirror;
}

}  // namespace

SceneObject draw_shape(ObjectKind kind, Rng &rng) {
    SceneObject object;
    object.kind = kind;
    switch (kind) {
    case ObjectKind::kSphere: object.radius = rng.uniform(0.5, 1.5); break;
    case ObjectKind::kBox:
        for (double &edge : object.size) edge = rng.uniform(0.5, 2.5);
        break;
    case ObjectKind::kCylinder:
        object.radius = rng.uniform(0.3, 1.2);
        object.length = rng.uniform(0.5, 3.0);
        break;
    }
    return object;
}

void check_opx(opx_status status, const char *what) {
    if (status == OPX_OK) return;
    throw std::runtime_error(std::string(what) + " failed: " + opx_status_name(status) + ": " + opx_last_error());
}

OpxOctreePtr copy_octree(const opx_octree *tree) {
    size_t size = 0;
    opx_octree_save_memory(tree, OPX_FORMAT_OPX, nullptr, 0, &size);  // BUFFER_TOO_SMALL gives the size
    std::vector<unsigned char> bytes(size);
    check_opx(opx_octree_save_memory(tree, OPX_FORMAT_OPX, bytes.data(), bytes.size(), &size),
              "opx_octree_save_memory");
    opx_octree *raw = nullptr;
    check_opx(opx_octree_load_memory(bytes.data(), size, nullptr, &raw), "opx_octree_load_memory");
    return OpxOctreePtr(raw);
}

const char *variant_letter(Variant variant) { return variant == Variant::kPrimitives ? "a" : "b"; }

TriangleMesh object_mesh(const SceneObject &object) {
    switch (object.kind) {
    case ObjectKind::kSphere: return make_uv_sphere(object.radius, kMeshResolution, kMeshResolution);
    case ObjectKind::kBox: return make_box(object.size[0], object.size[1], object.size[2]);
    case ObjectKind::kCylinder: return make_cylinder(object.radius, object.length, kMeshResolution);
    }
    return TriangleMesh();
}

OccupancyMaps build_occupancy_maps(const SceneParameters &parameters) {
    OccupancyMaps maps;
    maps.opx = make_random_opx_octree(parameters);
    maps.octomap = mirror_in_octomap(maps.opx.get(), parameters);
    return maps;
}

opx_pose draw_pose(const SceneParameters &parameters, Rng &rng) {
    opx_pose pose = OPX_POSE_IDENTITY;
    const auto position = rng.point_in_cube(-parameters.half_extent, parameters.half_extent);
    const auto rotation = rng.rotation();
    for (int i = 0; i < 3; ++i) pose.position[i] = position[i];
    for (int i = 0; i < 4; ++i) pose.orientation[i] = rotation[i];
    return pose;
}

std::vector<SceneObject> draw_objects(const SceneParameters &parameters, Rng &rng) {
    std::vector<SceneObject> objects;
    for (ObjectKind kind : {ObjectKind::kSphere, ObjectKind::kBox, ObjectKind::kCylinder}) {
        for (int i = 0; i < parameters.objects_per_kind; ++i) {
            SceneObject object = draw_shape(kind, rng);
            object.pose = draw_pose(parameters, rng);
            objects.push_back(object);
        }
    }
    return objects;
}

size_t count_occupied_leaves(const octomap::OcTree &tree) {
    size_t count = 0;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it)
        if (tree.isNodeOccupied(*it)) ++count;
    return count;
}

}  // namespace paper_tables
