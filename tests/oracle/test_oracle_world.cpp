// Queries with world objects against the brute-force oracle
// (oracle_world_check): random robots (all six shape kinds, paddings,
// disabled links) among random worlds (objects of one to three shapes of
// all six kinds at random poses, some disabled), with
//   objects: no octree, collision and distance against every pair, and
//   maps:    random small octrees beside the objects, the answer with both
//            equal to the union and the minimum of the parts, both engines.
// Usage: oracle_world objects|maps.  OPX_ORACLE_SEED changes the draw,
// OPX_ORACLE_SCENES the number of worlds.
#include "oracle_scenes.hpp"
#include "oracle_world_check.hpp"

#include <cstdio>
#include <cstring>

using namespace oracle;

namespace {

// An object as the oracle describes it: a LinkSpec (padding 0).
LinkSpec random_object(Rng &rng, int index, const Vec3 &low, const Vec3 &high) {
    LinkSpec object;
    object.name = "object " + std::to_string(index);
    const int shapes = rng.integer(1, 3);
    for (int s = 0; s < shapes; ++s) {
        const int32_t kind = static_cast<int32_t>(1 + (index + s) % 6);
        object.shapes.push_back(random_shape(rng, kind, rng.uniform(0.05, 0.5)));
    }
    object.pose = random_pose(rng, low, high);
    object.enabled = !rng.chance(0.1);
    return object;
}

void add_shape(opx_world *world, uint32_t object, const ShapeSpec &spec) {
    std::vector<double> vertices;
    for (const Vec3 &v : spec.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = spec.kind, shape.pose = spec.pose, shape.radius = spec.radius, shape.length = spec.length;
    for (int k = 0; k < 3; ++k) shape.size[k] = spec.size[k];
    if (!vertices.empty()) shape.vertices = vertices.data(), shape.vertex_count = spec.vertices.size();
    if (!spec.triangles.empty()) shape.indices = spec.triangles.front().data(), shape.triangle_count = spec.triangles.size();
    require_ok(opx_world_add_shape(world, object, &shape, nullptr), "opx_world_add_shape");
}

opx_world *build_world(const RobotSpec &objects) {
    opx_world *world = nullptr;
    require_ok(opx_world_create(&world), "opx_world_create");
    for (const LinkSpec &o : objects.links) {
        uint32_t index = 0;
        require_ok(opx_world_add_object(world, o.name.c_str(), &o.pose, &index), "opx_world_add_object");
        for (const ShapeSpec &spec : o.shapes) add_shape(world, index, spec);
        require_ok(opx_world_set_object_enabled(world, index, o.enabled ? 1 : 0), "opx_world_set_object_enabled");
    }
    return world;
}

// The robot's enabled shapes, then the enabled objects' as links after them.
std::vector<PlacedShape> place_all(const RobotSpec &robot, const RobotSpec &objects) {
    std::vector<PlacedShape> placed = place_robot(robot);
    const uint32_t offset = static_cast<uint32_t>(robot.links.size());
    for (PlacedShape s : place_robot(objects)) {
        s.link += offset;
        placed.push_back(std::move(s));
    }
    return placed;
}

struct Setting {
    RobotOptions robot;
    Vec3 low = Vec3::Constant(-1.0), high = Vec3::Constant(1.0);
    int objects = 8, robots = 2, states = 10;
};

opx_query *new_query(int32_t engine) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.engine = engine;
    opx_query *query = nullptr;
    require_ok(opx_query_create(&options, &query), "opx_query_create");
    return query;
}

// Calls check(links, case) for `robots` robots at `states` states each.
template <class Check>
void for_each_state(Rng &rng, const Setting &s, const RobotSpec &objects, const std::string &label, Check &&check) {
    for (int r = 0; r < s.robots; ++r) {
        RobotSpec robot = random_robot(rng, s.robot);
        randomize_state(rng, robot, s.robot, s.low, s.high);
        opx_linkset *links = build_linkset(robot);
        const uint32_t robot_links = static_cast<uint32_t>(robot.links.size());
        const PairMask pairs = link_object_pairs(robot_links, static_cast<uint32_t>(objects.links.size()));
        for (int k = 0; k < s.states; ++k) {
            randomize_state(rng, robot, s.robot, s.low, s.high);
            update_linkset(links, robot, static_cast<unsigned>(k));
            const std::vector<PlacedShape> placed = place_all(robot, objects);
            check(links, WorldCase{&placed, &pairs, robot_links,
                                   label + " robot " + std::to_string(r) + " state " + std::to_string(k)});
        }
        opx_linkset_destroy(links);
    }
}

RobotSpec random_objects(Rng &rng, const Setting &s) {
    RobotSpec objects;
    for (int i = 0; i < s.objects; ++i) objects.links.push_back(random_object(rng, i, s.low, s.high));
    return objects;
}

int run_objects(uint64_t seed) {
    const int worlds = static_cast<int>(env_number("OPX_ORACLE_SCENES", 100));
    Rng rng(seed);
    Setting s;
    s.robot.max_links = 4, s.robot.max_scale = 0.5, s.robot.max_padding = 0.05;
    WorldChecker checker("oracle_world objects");
    opx_query *query = new_query(OPX_ENGINE_DIRECT);
    for (int w = 0; w < worlds; ++w) {
        s.objects = rng.integer(1, 12);
        const RobotSpec objects = random_objects(rng, s);
        opx_world *world = build_world(objects);
        require_ok(opx_query_set_world(query, world), "opx_query_set_world");
        const std::string label = "world " + std::to_string(w) + " (seed " + std::to_string(seed) + ")";
        for_each_state(rng, s, objects, label,
                       [&](const opx_linkset *links, const WorldCase &c) { checker.check_objects(query, links, c); });
        require_ok(opx_query_set_world(query, nullptr), "opx_query_set_world");
        opx_world_destroy(world);
    }
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}

int run_maps(uint64_t seed) {
    const int maps = static_cast<int>(env_number("OPX_ORACLE_SCENES", 100)) / 3;
    Rng rng(seed);
    WorldChecker checker("oracle_world maps");
    opx_query *with_world[2] = {new_query(OPX_ENGINE_DIRECT), new_query(OPX_ENGINE_AMORTIZED)};
    opx_query *plain[2] = {new_query(OPX_ENGINE_DIRECT), new_query(OPX_ENGINE_AMORTIZED)};
    for (int m = 0; m < maps; ++m) {
        const std::unique_ptr<Scene> scene = random_small_scene(rng, false);
        Setting s;
        s.low = scene->low, s.high = scene->high;
        s.robot.max_links = 4, s.robot.max_scale = 0.5, s.robot.max_padding = 0.05;
        s.objects = rng.integer(4, 16), s.states = 8;
        const RobotSpec objects = random_objects(rng, s);
        opx_world *world = build_world(objects);
        for (opx_query *q : with_world) require_ok(opx_query_set_world(q, world), "opx_query_set_world");
        const std::string label = scene->label + " with " + std::to_string(s.objects) + " objects";
        for_each_state(rng, s, objects, label, [&](const opx_linkset *links, const WorldCase &c) {
            checker.check_with_map(with_world, plain, scene->tree, links, c);
        });
        for (opx_query *q : with_world) require_ok(opx_query_set_world(q, nullptr), "opx_query_set_world");
        opx_world_destroy(world);
    }
    for (opx_query *q : with_world) opx_query_destroy(q);
    for (opx_query *q : plain) opx_query_destroy(q);
    return checker.finish(elapsed_seconds());
}

}  // namespace

int main(int argc, char **argv) {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 31);
    if (argc == 2 && std::strcmp(argv[1], "objects") == 0) return run_objects(seed);
    if (argc == 2 && std::strcmp(argv[1], "maps") == 0) return run_maps(seed);
    std::printf("usage: %s objects|maps\n", argv[0]);
    return 2;
}
