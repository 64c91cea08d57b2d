#include "world_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "pr2_scene.hpp"
#include "rng.hpp"

namespace world_bench {
namespace {

using paper_tables::check_opx;
using paper_tables::ObjectKind;
using paper_tables::SceneObject;

constexpr double kEdge = 0.16;                 // an object's mean edge (m)
constexpr double kObjectsPerReachBox = 10.0;
// Objects around the reach box keep this far from it in x and y (m): the
// grippers reach past their links' origins, and objects have a size.
constexpr double kMarginAroundReach = 0.3;
constexpr size_t kMeshEvery = 10;  // every tenth object is a mesh
constexpr int kMaxDrawsPerObject = 1000;

bool same_position(const opx_pose &a, const opx_pose &b) {
    for (int i = 0; i < 3; ++i)
        if (std::fabs(a.position[i] - b.position[i]) > 1e-12) return false;
    return true;
}

// The links that move and the box their origins reach, from a fixed draw
// of configurations, so that the scenes do not depend on how many
// configurations are checked.
constexpr int kReachConfigurations = 1000;
constexpr uint64_t kReachSeed = 0x5EAC4u;

void find_reach(Robot &robot) {
    const opx_pose base = OPX_POSE_IDENTITY;
    const std::vector<paper_tables::Configuration> sample =
        paper_tables::draw_reaching_configurations(robot.links.get(), kReachConfigurations, kReachSeed, base);
    const std::vector<opx_pose> &first = sample.front().poses;
    robot.moving.assign(first.size(), 0);
    for (const paper_tables::Configuration &c : sample)
        for (size_t l = 0; l < first.size(); ++l) robot.moving[l] |= !same_position(c.poses[l], first[l]);
    std::fill(robot.reach_min, robot.reach_min + 3, INFINITY);
    std::fill(robot.reach_max, robot.reach_max + 3, -INFINITY);
    for (const paper_tables::Configuration &c : sample)
        for (size_t l = 0; l < first.size(); ++l)
            for (int i = 0; robot.moving[l] && i < 3; ++i) {
                robot.reach_min[i] = std::min(robot.reach_min[i], c.poses[l].position[i]);
                robot.reach_max[i] = std::max(robot.reach_max[i], c.poses[l].position[i]);
            }
}

opx_shape primitive_shape(const SceneObject &object) {
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = object.kind == ObjectKind::kBox      ? OPX_SHAPE_BOX
                 : object.kind == ObjectKind::kSphere ? OPX_SHAPE_SPHERE
                                                      : OPX_SHAPE_CYLINDER;
    shape.radius = object.radius, shape.length = object.length;
    std::copy(object.size.begin(), object.size.end(), shape.size);
    return shape;
}

// Tells whether an object touches the robot's links that never move.
class StillBody {
public:
    explicit StillBody(const Robot &robot) {
        opx_linkset *clone = nullptr;
        check_opx(opx_linkset_clone(robot.links.get(), &clone), "opx_linkset_clone");
        links_.reset(clone);
        for (uint32_t l = 0; l < robot.moving.size(); ++l)
            if (robot.moving[l]) check_opx(opx_linkset_set_link_enabled(clone, l, 0), "opx_linkset_set_link_enabled");
        opx_world *world = nullptr;
        check_opx(opx_world_create(&world), "opx_world_create");
        world_.reset(world);
        query_ = paper_tables::make_direct_query();
        check_opx(opx_query_set_world(query_.get(), world), "opx_query_set_world");
    }
    ~StillBody() { opx_query_set_world(query_.get(), nullptr); }

    bool touches(const SceneObject &object) {
        uint32_t index = 0;
        check_opx(opx_world_add_object(world_.get(), "probe", &object.pose, &index), "opx_world_add_object");
        const opx_shape shape = primitive_shape(object);
        check_opx(opx_world_add_shape(world_.get(), index, &shape, nullptr), "opx_world_add_shape");
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        check_opx(opx_query_collide(query_.get(), nullptr, links_.get(), &request, &result), "opx_query_collide");
        check_opx(opx_world_remove_object(world_.get(), index), "opx_world_remove_object");
        return result.collided != 0;
    }

private:
    paper_tables::OpxLinksetPtr links_;
    OpxWorldPtr world_;
    paper_tables::OpxQueryPtr query_;
};

// Where objects go: the reach box grown in x and y by `spread`, as high.
struct Region {
    double min[3], max[3];
    bool inside(const double p[3]) const {
        for (int i = 0; i < 3; ++i)
            if (p[i] < min[i] || p[i] > max[i]) return false;
        return true;
    }
};

// The reach box grown in x and y by the factor `spread` and then by
// `margin` on each side, as high.
Region region_of(const Robot &robot, double spread, double margin = 0.0) {
    Region r;
    for (int i = 0; i < 3; ++i) {
        const double centre = 0.5 * (robot.reach_min[i] + robot.reach_max[i]);
        const double half = 0.5 * (robot.reach_max[i] - robot.reach_min[i]) * (i < 2 ? spread : 1.0);
        const double grow = i < 2 ? margin : 0.0;
        r.min[i] = centre - half - grow, r.max[i] = centre + half + grow;
    }
    return r;
}

SceneObject draw_object(ObjectKind kind, double edge, const Region &region, paper_tables::Rng &rng) {
    SceneObject object;
    object.kind = kind;
    switch (kind) {
    case ObjectKind::kBox:
        for (double &e : object.size) e = rng.uniform(0.5, 1.5) * edge;
        break;
    case ObjectKind::kSphere: object.radius = rng.uniform(0.25, 0.75) * edge; break;
    case ObjectKind::kCylinder:
        object.radius = rng.uniform(0.2, 0.5) * edge;
        object.length = rng.uniform(0.5, 1.5) * edge;
        break;
    }
    for (int i = 0; i < 3; ++i) object.pose.position[i] = rng.uniform(region.min[i], region.max[i]);
    const auto q = rng.rotation();
    std::copy(q.begin(), q.end(), object.pose.orientation);
    return object;
}

void add_to_world(opx_world *world, const SceneObject &object, bool as_mesh, size_t index) {
    static const char *const kKinds[] = {"sphere", "box", "cylinder"};
    const std::string name = std::string(as_mesh ? "mesh " : "") + kKinds[int(object.kind)] + " " + std::to_string(index);
    uint32_t o = 0;
    check_opx(opx_world_add_object(world, name.c_str(), &object.pose, &o), "opx_world_add_object");
    opx_shape shape = primitive_shape(object);
    paper_tables::TriangleMesh mesh;
    if (as_mesh) {
        mesh = paper_tables::object_mesh(object);
        shape = OPX_SHAPE_INIT;
        shape.kind = OPX_SHAPE_MESH;
        shape.vertices = mesh.vertices.data(), shape.vertex_count = mesh.vertex_count();
        shape.indices = mesh.indices.data(), shape.triangle_count = mesh.triangle_count();
    }
    check_opx(opx_world_add_shape(world, o, &shape, nullptr), "opx_world_add_shape");
}

// The FCL objects: primitives as FCL shapes, meshes as BVHModel<OBBRSS>
// over the same triangles, all in one dynamic AABB tree.
paper_tables::FclObjectSet fcl_objects(const ObjectSet &set) {
    std::vector<SceneObject> primitives, meshes;
    for (size_t i = 0; i < set.objects.size(); ++i) (set.is_mesh[i] ? meshes : primitives).push_back(set.objects[i]);
    paper_tables::FclObjectSet all;
    for (auto *part : {&primitives, &meshes}) {
        const auto variant = part == &meshes ? paper_tables::Variant::kMeshes : paper_tables::Variant::kPrimitives;
        paper_tables::FclObjectSet one = paper_tables::make_fcl_object_set(*part, variant);
        for (auto &object : one.objects) all.objects.push_back(std::move(object));
    }
    all.manager = paper_tables::manage_objects(all.objects);
    return all;
}

}  // namespace

Robot load_robot(size_t count, uint64_t seed) {
    Robot robot;
    robot.links = paper_tables::load_pr2();
    robot.fcl = std::make_unique<paper_tables::FclRobot>(robot.links.get());
    const opx_pose base = OPX_POSE_IDENTITY;
    robot.configurations =
        paper_tables::draw_reaching_configurations(robot.links.get(), static_cast<int>(count), seed, base);
    find_reach(robot);
    return robot;
}

paper_tables::OpxOctreePtr real_map(const Robot &robot) {
    return paper_tables::build_frame_maps(paper_tables::camera_pose(robot.links.get()), {0.02}, 0).opx;
}

namespace {

// Object i of a scene of `count`: the first kObjectsPerReachBox in the
// reach box (the same in every scene), the others in the grown region
// around it, kMarginAroundReach or more from the reach box.
SceneObject place_object(size_t i, size_t count, const Robot &robot, StillBody &still, paper_tables::Rng &rng) {
    const Region reach = region_of(robot, 1.0), keep_out = region_of(robot, 1.0, kMarginAroundReach);
    const Region around = region_of(robot, std::sqrt(double(count) / kObjectsPerReachBox), kMarginAroundReach);
    const bool within_reach = double(i) < kObjectsPerReachBox;
    const auto kind = static_cast<ObjectKind>(i % 3);
    for (int draws = 0; draws < kMaxDrawsPerObject; ++draws) {
        const SceneObject object = draw_object(kind, kEdge, within_reach ? reach : around, rng);
        if (!within_reach && keep_out.inside(object.pose.position)) continue;
        if (!still.touches(object)) return object;
    }
    throw std::runtime_error("no room for an object beside the PR2's body");
}

}  // namespace

ObjectSet draw_objects(Robot &robot, size_t count, uint64_t seed) {
    paper_tables::Rng rng(seed);
    StillBody still(robot);
    ObjectSet set;
    opx_world *world = nullptr;
    check_opx(opx_world_create(&world), "opx_world_create");
    set.world.reset(world);
    for (size_t i = 0; i < count; ++i) {
        const SceneObject object = place_object(i, count, robot, still, rng);
        const bool as_mesh = i % kMeshEvery == kMeshEvery - 1;
        add_to_world(world, object, as_mesh, i);
        set.objects.push_back(object);
        set.is_mesh.push_back(as_mesh);
        set.meshes += as_mesh;
    }
    set.fcl = fcl_objects(set);
    return set;
}

std::string describe(const ObjectSet &set) {
    char text[128];
    std::snprintf(text, sizeof text, "%zu boxes, cylinders and spheres (%zu as meshes)", set.objects.size(), set.meshes);
    return text;
}

}  // namespace world_bench
