// Objects attached to links (opx_linkset_attach_object) against brute force:
// random robots (all six shape kinds, paddings, disabled links, disabled
// pairs) holding one to four random objects of one or two shapes each, at
// random poses in random links, with random touch links.
//   self:  self-collision and self-distance against oracle_self, the
//          attached objects as extra bodies (link_count + i) whose pairs
//          follow the attached rules: not their own link, not their touch
//          links (whatever the link pairs say), not objects on the same
//          link; every touching pair, collided, the distance.
//   map:   beside random small octrees and world objects, both engines: the
//          answers equal those of the same robot with each object's shapes
//          added to its link as the link's own shapes (collided, distance,
//          per-link distances), whose octree and world answers the other
//          oracles check.
// Usage: oracle_attached self|map.  OPX_ORACLE_SEED changes the draw,
// OPX_ORACLE_SCENES the number of robots.
#include "oracle_check.hpp"
#include "oracle_random.hpp"
#include "oracle_scenes.hpp"
#include "oracle_self_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <set>
#include <tuple>

using namespace oracle;

namespace {

struct AttachedSpec {
    uint32_t link = 0;
    opx_pose pose = OPX_POSE_IDENTITY;  // the object frame in the link frame
    std::vector<ShapeSpec> shapes;      // poses in the object frame
    std::vector<uint32_t> touch_links;
};

// The library's view of a ShapeSpec; `vertices` keeps the packed points.
opx_shape shape_of(const ShapeSpec &spec, std::vector<double> &vertices) {
    vertices.clear();
    for (const Vec3 &v : spec.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = spec.kind, shape.pose = spec.pose, shape.radius = spec.radius, shape.length = spec.length;
    for (int k = 0; k < 3; ++k) shape.size[k] = spec.size[k];
    if (!vertices.empty()) shape.vertices = vertices.data(), shape.vertex_count = spec.vertices.size();
    if (!spec.triangles.empty())
        shape.indices = spec.triangles.front().data(), shape.triangle_count = spec.triangles.size();
    return shape;
}

std::vector<AttachedSpec> random_attached(Rng &rng, const RobotSpec &robot) {
    std::vector<AttachedSpec> objects(static_cast<size_t>(rng.integer(1, 4)));
    const int links = static_cast<int>(robot.links.size());
    for (size_t i = 0; i < objects.size(); ++i) {
        AttachedSpec &o = objects[i];
        o.link = static_cast<uint32_t>(rng.integer(0, links - 1));
        o.pose = random_pose(rng, Vec3::Constant(-0.4), Vec3::Constant(0.4));
        const int shapes = rng.integer(1, 2);
        for (int s = 0; s < shapes; ++s)
            o.shapes.push_back(random_shape(rng, 1 + static_cast<int32_t>((i + s) % 6), rng.uniform(0.05, 0.4)));
        for (int l = 0; l < links; ++l)
            if (static_cast<uint32_t>(l) != o.link && rng.chance(0.3)) o.touch_links.push_back(static_cast<uint32_t>(l));
    }
    return objects;
}

void attach_all(opx_linkset *links, const RobotSpec &robot, const std::vector<AttachedSpec> &objects) {
    for (const AttachedSpec &o : objects) {
        std::vector<std::vector<double>> vertices(o.shapes.size());
        std::vector<opx_shape> shapes;
        for (size_t s = 0; s < o.shapes.size(); ++s) shapes.push_back(shape_of(o.shapes[s], vertices[s]));
        std::vector<const char *> names;
        for (uint32_t l : o.touch_links) names.push_back(robot.links[l].name.c_str());
        require_ok(opx_linkset_attach_object(links, o.link, "held", shapes.data(), shapes.size(), &o.pose,
                                             names.data(), names.size(), nullptr),
                   "opx_linkset_attach_object");
    }
}

// The robot's links, then each object as a body at its link's pose times
// its own, with its link's padding and enabled flag.
RobotSpec bodies_of(const RobotSpec &robot, const std::vector<AttachedSpec> &objects) {
    RobotSpec bodies = robot;
    for (const AttachedSpec &o : objects) {
        const LinkSpec &link = robot.links[o.link];
        LinkSpec body;
        body.name = "held on " + link.name;
        body.shapes = o.shapes;
        body.padding = link.padding, body.enabled = link.enabled;
        body.pose = pose_of(isometry_of(link.pose) * isometry_of(o.pose));
        bodies.links.push_back(body);
    }
    return bodies;
}

// The rules of BodyPairs (src/query/self/link_boxes.hpp), written anew.
PairMask body_pairs(const PairMask &link_pairs, const std::vector<AttachedSpec> &objects) {
    const uint32_t n = static_cast<uint32_t>(link_pairs.links());
    PairMask mask(n + objects.size());
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = a + 1; b < n; ++b) mask.set(a, b, link_pairs.enabled(a, b));
    for (uint32_t i = 0; i < objects.size(); ++i) {
        const AttachedSpec &o = objects[i];
        for (uint32_t l = 0; l < n; ++l) {
            const bool touch = std::find(o.touch_links.begin(), o.touch_links.end(), l) != o.touch_links.end();
            mask.set(n + i, l, l != o.link && !touch);
        }
        for (uint32_t j = i + 1; j < objects.size(); ++j) mask.set(n + i, n + j, o.link != objects[j].link);
    }
    return mask;
}

class Tally {
public:
    explicit Tally(const char *name) : name_(name) {}
    void fail(const std::string &message) {
        if (++mismatches_ <= 10) std::printf("MISMATCH: %s\n", message.c_str());
    }
    void count(bool collided) { ++states_, collided_ += collided; }
    int finish() const {
        std::printf("%s: %llu states, %llu colliding, %llu mismatches, %.1f s\n", name_,
                    static_cast<unsigned long long>(states_), static_cast<unsigned long long>(collided_),
                    static_cast<unsigned long long>(mismatches_), elapsed_seconds());
        const bool varied = collided_ > 0 && collided_ < states_;
        if (!varied) std::printf("FAIL: %s: the states do not vary (all or none colliding)\n", name_);
        return mismatches_ == 0 && varied ? 0 : 1;
    }

private:
    const char *name_;
    uint64_t states_ = 0, collided_ = 0, mismatches_ = 0;
};

using BodyShape = std::tuple<uint32_t, uint32_t>;  // body, shape

BodyShape body_of(uint32_t link, int32_t attached, uint32_t shape, uint32_t links) {
    return {attached < 0 ? link : links + static_cast<uint32_t>(attached), shape};
}

// Every touching pair the oracle decides must be a library contact, and
// every contact a touching or ambiguous pair of the oracle (self_verdicts
// leaves out the clear ones).
void check_self(opx_query *query, const opx_linkset *links, const std::vector<PlacedShape> &placed,
                const PairMask &mask, uint32_t link_count, const std::string &label, Tally &tally) {
    const std::vector<ShapePairVerdict> verdicts = self_verdicts(placed, mask);
    std::set<std::pair<BodyShape, BodyShape>> touching, ambiguous;
    for (const ShapePairVerdict &v : verdicts) {
        const auto key = std::make_pair(BodyShape{v.a->link, v.a->shape}, BodyShape{v.b->link, v.b->shape});
        (v.verdict == Verdict::kTouch ? touching : ambiguous).insert(key);
    }
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    request.max_contacts = UINT32_MAX;
    opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
    require_ok(opx_query_self_collide(query, links, &request, &result), "opx_query_self_collide");
    size_t found = 0;
    for (size_t i = 0; i < result.contact_count; ++i) {
        opx_self_contact c = OPX_SELF_CONTACT_INIT;
        require_ok(opx_query_get_self_contact(query, i, &c), "opx_query_get_self_contact");
        BodyShape a = body_of(c.link_a, c.attached_a, c.shape_a, link_count);
        BodyShape b = body_of(c.link_b, c.attached_b, c.shape_b, link_count);
        if (std::get<0>(b) < std::get<0>(a)) std::swap(a, b);
        if (!mask.enabled(std::get<0>(a), std::get<0>(b)))
            tally.fail(label + ": a contact between bodies " + std::to_string(std::get<0>(a)) + " and " +
                       std::to_string(std::get<0>(b)) + ", a pair the attached rules do not check");
        else if (!touching.count({a, b}) && !ambiguous.count({a, b}))
            tally.fail(label + ": a contact between bodies " + std::to_string(std::get<0>(a)) + " and " +
                       std::to_string(std::get<0>(b)) + " the oracle finds clear");
        found += touching.count({a, b});
    }
    if (found != touching.size())
        tally.fail(label + ": " + std::to_string(touching.size()) + " touching pairs, the library reports " +
                   std::to_string(found) + " of them");
    if (ambiguous.empty() && (result.collided != 0) != !touching.empty()) tally.fail(label + ": collided differs");
    tally.count(!touching.empty());

    const SelfMinimum m = self_minimum(placed, mask, std::numeric_limits<double>::infinity());
    opx_self_distance_result d = OPX_SELF_DISTANCE_RESULT_INIT;
    require_ok(opx_query_self_distance(query, links, nullptr, &d), "opx_query_self_distance");
    const double tol = m.curved ? 1e-6 : 1e-9;
    if (m.found != (d.found != 0)) return tally.fail(label + ": found differs");
    if (m.found && (d.distance < m.distance.low - tol || d.distance > m.distance.high + tol))
        tally.fail(label + ": distance " + std::to_string(d.distance) + ", the oracle's in [" +
                   std::to_string(m.distance.low) + ", " + std::to_string(m.distance.high) + "]");
}

int run_self(uint64_t seed) {
    Rng rng(seed);
    Tally tally("oracle_attached self");
    RobotOptions options;
    options.min_links = 2, options.max_links = 6, options.max_scale = 0.5, options.max_padding = 0.05;
    opx_query *query = nullptr;
    require_ok(opx_query_create(nullptr, &query), "opx_query_create");
    const int robots = static_cast<int>(env_number("OPX_ORACLE_SCENES", 100));
    for (int r = 0; r < robots; ++r) {
        RobotSpec robot = random_robot(rng, options);
        opx_linkset *links = build_linkset(robot);
        const uint32_t n = static_cast<uint32_t>(robot.links.size());
        const PairMask link_pairs = random_pairs(rng, links, n, 0.2);
        const std::vector<AttachedSpec> objects = random_attached(rng, robot);
        attach_all(links, robot, objects);
        const PairMask mask = body_pairs(link_pairs, objects);
        for (int k = 0; k < 8; ++k) {
            randomize_state(rng, robot, options, Vec3::Constant(-0.6), Vec3::Constant(0.6));
            update_linkset(links, robot, static_cast<unsigned>(k));
            const std::vector<PlacedShape> placed = place_robot(bodies_of(robot, objects));
            check_self(query, links, placed, mask, n,
                       "robot " + std::to_string(r) + " state " + std::to_string(k) + " (seed " +
                           std::to_string(seed) + ")",
                       tally);
        }
        opx_linkset_destroy(links);
    }
    opx_query_destroy(query);
    return tally.finish();
}

// ---- beside octrees and world objects: as the link's own shapes ------------

// The same robot with each object's shapes added to its link, placed at
// the object's pose times the shape's.
opx_linkset *as_own_shapes(const RobotSpec &robot, const std::vector<AttachedSpec> &objects) {
    RobotSpec merged = robot;
    for (const AttachedSpec &o : objects) {
        for (ShapeSpec shape : o.shapes) {
            shape.pose = pose_of(isometry_of(o.pose) * isometry_of(shape.pose));
            merged.links[o.link].shapes.push_back(shape);
        }
    }
    return build_linkset(merged);
}

opx_world *random_world(Rng &rng, const Vec3 &low, const Vec3 &high) {
    opx_world *world = nullptr;
    require_ok(opx_world_create(&world), "opx_world_create");
    const int objects = rng.integer(2, 8);
    for (int i = 0; i < objects; ++i) {
        const opx_pose at = random_pose(rng, low, high);
        uint32_t index = 0;
        require_ok(opx_world_add_object(world, "thing", &at, &index), "opx_world_add_object");
        std::vector<double> vertices;
        const ShapeSpec spec = random_shape(rng, 1 + i % 6, rng.uniform(0.05, 0.4));
        const opx_shape shape = shape_of(spec, vertices);
        require_ok(opx_world_add_shape(world, index, &shape, nullptr), "opx_world_add_shape");
    }
    return world;
}

struct Answer {
    int32_t collided = 0;
    double distance = 0.0;
    std::vector<double> per_link;
};

Answer ask(opx_query *query, const opx_octree *tree, const opx_linkset *links, size_t link_count) {
    Answer a;
    opx_collision_request collide = OPX_COLLISION_REQUEST_INIT;
    collide.max_contacts = 0;
    opx_collision_result cr = OPX_COLLISION_RESULT_INIT;
    require_ok(opx_query_collide(query, tree, links, &collide, &cr), "opx_query_collide");
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.per_link = 1;
    opx_distance_result dr = OPX_DISTANCE_RESULT_INIT;
    require_ok(opx_query_distance(query, tree, links, &request, &dr), "opx_query_distance");
    a.collided = cr.collided, a.distance = dr.distance;
    a.per_link.resize(link_count);
    size_t count = 0;
    require_ok(opx_query_get_link_distances(query, a.per_link.data(), link_count, &count),
               "opx_query_get_link_distances");
    return a;
}

bool near(double a, double b) { return (std::isinf(a) && a == b) || std::abs(a - b) <= 1e-9; }

int run_map(uint64_t seed) {
    Rng rng(seed);
    Tally tally("oracle_attached map");
    opx_query *queries[2] = {nullptr, nullptr};
    const int32_t engines[2] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};
    for (int e = 0; e < 2; ++e) {
        opx_query_options options = OPX_QUERY_OPTIONS_INIT;
        options.engine = engines[e];
        require_ok(opx_query_create(&options, &queries[e]), "opx_query_create");
    }
    const int maps = static_cast<int>(env_number("OPX_ORACLE_SCENES", 100)) / 3;
    for (int m = 0; m < maps; ++m) {
        const std::unique_ptr<Scene> scene = random_small_scene(rng, false);
        opx_world *world = random_world(rng, scene->low, scene->high);
        RobotOptions options;
        options.max_links = 4, options.max_scale = 0.5, options.max_padding = 0.05;
        RobotSpec robot = random_robot(rng, options);
        const std::vector<AttachedSpec> objects = random_attached(rng, robot);
        opx_linkset *links = build_linkset(robot);
        attach_all(links, robot, objects);
        for (int k = 0; k < 6; ++k) {
            randomize_state(rng, robot, options, scene->low, scene->high);
            update_linkset(links, robot, static_cast<unsigned>(k));
            opx_linkset *merged = as_own_shapes(robot, objects);
            update_linkset(merged, robot, 0);
            for (int e = 0; e < 2; ++e) {
                for (int with_world = 0; with_world < 2; ++with_world) {
                    require_ok(opx_query_set_world(queries[e], with_world ? world : nullptr), "opx_query_set_world");
                    const Answer a = ask(queries[e], scene->tree, links, robot.links.size());
                    const Answer b = ask(queries[e], scene->tree, merged, robot.links.size());
                    const std::string label = scene->label + " state " + std::to_string(k) + " engine " +
                                              std::to_string(e) + (with_world ? " with world" : "");
                    if (!near(a.distance, b.distance))
                        tally.fail(label + ": distance " + std::to_string(a.distance) + ", as own shapes " +
                                   std::to_string(b.distance));
                    if (a.collided != b.collided && std::abs(a.distance) > 1e-8)
                        tally.fail(label + ": collided differs from the link's own shapes'");
                    for (size_t l = 0; l < a.per_link.size(); ++l)
                        if (!near(a.per_link[l], b.per_link[l])) tally.fail(label + ": link distance differs");
                    if (e == 0 && with_world) tally.count(b.collided != 0);
                }
            }
            opx_linkset_destroy(merged);
        }
        for (opx_query *q : queries) require_ok(opx_query_set_world(q, nullptr), "opx_query_set_world");
        opx_linkset_destroy(links);
        opx_world_destroy(world);
    }
    for (opx_query *q : queries) opx_query_destroy(q);
    return tally.finish();
}

}  // namespace

int main(int argc, char **argv) {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 37);
    if (argc == 2 && std::strcmp(argv[1], "self") == 0) return run_self(seed);
    if (argc == 2 && std::strcmp(argv[1], "map") == 0) return run_map(seed);
    std::printf("usage: %s self|map\n", argv[0]);
    return 2;
}
