#include "oracle_enclosure.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace oracle {
namespace {

struct Hole {
    int face = 0;
    Vec3 center = Vec3::Zero();
    double radius = 0.0;
};

// Endpoints every `spacing` on the six faces of the cube [c - h, c + h],
// except inside the holes.
std::vector<Vec3> wall_points(const Vec3 &center, double half, double spacing, const std::vector<Hole> &holes) {
    std::vector<Vec3> points;
    const int steps = int(std::ceil(2.0 * half / spacing));
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; j <= steps; ++j) {
                Vec3 local;
                local[axis] = face % 2 ? half : -half;
                local[(axis + 1) % 3] = -half + i * spacing;
                local[(axis + 2) % 3] = -half + j * spacing;
                const Vec3 p = center + local;
                bool in_hole = false;
                for (const Hole &hole : holes) in_hole |= hole.face == face && (p - hole.center).norm() < hole.radius;
                if (!in_hole) points.push_back(p);
            }
    }
    return points;
}

opx_octree *create_tree(double resolution, double free_threshold) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    options.free_threshold = free_threshold;
    opx_octree *tree = nullptr;
    if (opx_octree_create(&options, &tree) != OPX_OK) {
        std::printf("FAIL: opx_octree_create: %s\n", opx_last_error());
        std::exit(1);
    }
    return tree;
}

}  // namespace

std::unique_ptr<Scene> enclosed_scene(Rng &rng, const EnclosureOptions &o) {
    auto scene = std::make_unique<Scene>();
    const double resolution = rng.uniform(o.min_resolution, o.max_resolution);
    scene->tree = create_tree(resolution, o.free_threshold);
    const Vec3 center = rng.point(Vec3::Constant(-2.0), Vec3::Constant(2.0));
    std::vector<Hole> holes;
    for (int i = rng.integer(o.min_holes, o.max_holes); i > 0; --i) {
        Hole hole;
        hole.face = rng.integer(0, 5);
        hole.center = center + rng.point(Vec3::Constant(-o.half), Vec3::Constant(o.half));
        hole.radius = rng.uniform(0.15, 0.4);
        holes.push_back(hole);
    }
    const std::vector<Vec3> walls = wall_points(center, o.half, 0.5 * resolution, holes);
    for (int sensor = 0; sensor < o.sensors; ++sensor) {
        const opx_pose pose = random_pose(rng, center - Vec3::Constant(0.3), center + Vec3::Constant(0.3));
        insert_frame(scene->tree, walls, pose, OPX_INSERT_RAYCAST);
    }
    scene->low = center - Vec3::Constant(o.half - 0.15), scene->high = center + Vec3::Constant(o.half - 0.15);
    char label[160];
    std::snprintf(label, sizeof label, "enclosure res %.4f free_threshold %.2f centre (%.3f, %.3f, %.3f), %zu holes",
                  resolution, o.free_threshold, center.x(), center.y(), center.z(), holes.size());
    scene->label = label;
    index_scene(*scene, o.with_unknown);
    return scene;
}

std::unique_ptr<Scene> cells_scene(double resolution, const std::vector<Vec3> &points, bool with_unknown) {
    auto scene = std::make_unique<Scene>();
    scene->tree = create_tree(resolution, 0.5);
    if (!points.empty()) insert_frame(scene->tree, points, opx_pose OPX_POSE_IDENTITY, OPX_INSERT_ENDPOINTS);
    scene->label = "explicit cells";
    index_scene(*scene, with_unknown);
    return scene;
}

}  // namespace oracle
