// Self-collision and self-distance against the brute-force oracle
// (oracle_self): every pair of shapes of every checked pair of links,
// measured exactly, at random configurations of
//   arm: generated arms (5 to 9 links in a chain of revolute joints, each
//        link with 1 to 3 shapes of all six kinds, random paddings, some
//        links and some pairs disabled), and
//   pr2: the PR2 from the shared data (URDF with its meshes, boxes,
//        cylinders and spheres), with its SRDF's pairs and without, joints
//        uniform within their limits, with and without padding; it exits
//        77 when the data is absent.
// Usage: oracle_self arm|pr2.  OPX_ORACLE_SEED changes the draw.
#include "oracle_check.hpp"
#include "oracle_random.hpp"
#include "oracle_self_check.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

using namespace oracle;

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- generated arms --------------------------------------------------------

struct Arm {
    RobotSpec robot;
    std::vector<double> lengths;  // link i's joint sits lengths[i - 1] along its parent's x
    std::vector<Vec3> axes;       // joint axes, unit, in the parent frame
};

Arm random_arm(Rng &rng) {
    RobotOptions options;
    options.min_links = 5, options.max_links = 9, options.max_shapes_per_link = 3;
    options.min_scale = 0.05, options.max_scale = 0.3;
    Arm arm;
    arm.robot = random_robot(rng, options);
    for (size_t i = 0; i < arm.robot.links.size(); ++i) {
        arm.lengths.push_back(rng.uniform(0.1, 0.4));
        arm.axes.push_back(random_rotation(rng) * Vec3::UnitZ());
    }
    return arm;
}

// Joint angles in [-pi, pi]; paddings, enabled links as randomize_state.
void pose_arm(Rng &rng, Arm &arm) {
    Eigen::Isometry3d frame = isometry_of(random_pose(rng, Vec3::Constant(-1.0), Vec3::Constant(1.0)));
    RobotSpec &robot = arm.robot;
    robot.global_padding = rng.chance(0.5) ? rng.uniform(0.0, 0.02) : 0.0;
    for (size_t i = 0; i < robot.links.size(); ++i) {
        if (i > 0) {
            frame = frame * Eigen::Translation3d(arm.lengths[i - 1], 0.0, 0.0) *
                    Eigen::AngleAxisd(rng.uniform(-kPi, kPi), arm.axes[i]);
        }
        LinkSpec &link = robot.links[i];
        link.pose = pose_of(frame);
        link.padding = rng.chance(0.5) ? rng.uniform(0.0, 0.02) : 0.0;
        link.enabled = !rng.chance(0.08);
    }
}

int run_arms(uint64_t seed) {
    const int arms = static_cast<int>(env_number("OPX_ORACLE_ROBOTS", 30));
    constexpr int kConfigurations = 40;
    Rng rng(seed);
    opx_query *query = nullptr;
    require_ok(opx_query_create(nullptr, &query), "opx_query_create");
    SelfChecker checker("oracle_self arm");
    for (int a = 0; a < arms; ++a) {
        Arm arm = random_arm(rng);
        pose_arm(rng, arm);
        opx_linkset *links = build_linkset(arm.robot);
        const PairMask pairs = random_pairs(rng, links, arm.robot.links.size(), 0.1);
        for (int k = 0; k < kConfigurations; ++k) {
            pose_arm(rng, arm);
            update_linkset(links, arm.robot, static_cast<unsigned>(k));
            const std::vector<PlacedShape> placed = place_robot(arm.robot);
            const std::string label = "arm " + std::to_string(a) + " configuration " + std::to_string(k) +
                                      " (seed " + std::to_string(seed) + ")";
            checker.check(query, links, {&placed, &pairs, label});
        }
        opx_linkset_destroy(links);
    }
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}

// ---- the PR2 ----------------------------------------------------------------

// The link set's shapes as the oracle describes them (read through the ABI).
RobotSpec spec_of(const opx_linkset *links) {
    RobotSpec robot;
    uint32_t count = 0;
    require_ok(opx_linkset_get_link_count(links, &count), "opx_linkset_get_link_count");
    for (uint32_t i = 0; i < count; ++i) {
        LinkSpec link;
        const char *name = nullptr;
        uint32_t shapes = 0;
        require_ok(opx_linkset_get_link_name(links, i, &name), "opx_linkset_get_link_name");
        require_ok(opx_linkset_get_shape_count(links, i, &shapes), "opx_linkset_get_shape_count");
        link.name = name;
        for (uint32_t j = 0; j < shapes; ++j) {
            opx_shape s = OPX_SHAPE_INIT;
            require_ok(opx_linkset_get_shape(links, i, j, &s), "opx_linkset_get_shape");
            ShapeSpec spec;
            spec.kind = s.kind, spec.pose = s.pose, spec.radius = s.radius, spec.length = s.length;
            spec.size = Vec3(s.size[0], s.size[1], s.size[2]);
            for (size_t v = 0; v < s.vertex_count; ++v)
                spec.vertices.push_back(Vec3(s.vertices[3 * v], s.vertices[3 * v + 1], s.vertices[3 * v + 2]));
            for (size_t t = 0; t < s.triangle_count; ++t)
                spec.triangles.push_back({s.indices[3 * t], s.indices[3 * t + 1], s.indices[3 * t + 2]});
            link.shapes.push_back(std::move(spec));
        }
        robot.links.push_back(std::move(link));
    }
    return robot;
}

opx_linkset *load_pr2(const std::string &dir, bool with_srdf) {
    const std::string package = "moveit_resources_pr2_description=" + dir;
    const char *package_dirs[] = {package.c_str()};
    const std::string srdf = dir + "/srdf/pr2.srdf";
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = package_dirs, options.package_dir_count = 1;
    options.srdf_path = with_srdf ? srdf.c_str() : nullptr;
    opx_linkset *links = nullptr;
    require_ok(opx_linkset_load_urdf_file((dir + "/urdf/robot.xml").c_str(), &options, &links), "loading the PR2");
    return links;
}

// The SRDF's list, as the oracle's mask; the library's pairs must agree.
PairMask srdf_mask(const opx_linkset *links, size_t count, SelfChecker &checker) {
    PairMask mask(count);
    uint32_t listed = 0;
    require_ok(opx_linkset_get_disabled_pair_count(links, &listed), "opx_linkset_get_disabled_pair_count");
    for (uint32_t i = 0; i < listed; ++i) {
        uint32_t a = 0, b = 0;
        require_ok(opx_linkset_get_disabled_pair(links, i, &a, &b), "opx_linkset_get_disabled_pair");
        if (a != b) mask.set(a, b, false);
    }
    for (uint32_t a = 0; a < count; ++a) {
        for (uint32_t b = a + 1; b < count; ++b) {
            int32_t enabled = -1;
            require_ok(opx_linkset_get_pair_enabled(links, a, b, &enabled), "opx_linkset_get_pair_enabled");
            if ((enabled == 1) != mask.enabled(a, b)) checker.fail("SRDF pair " + std::to_string(a) + "-" +
                                                                  std::to_string(b) + " not as listed");
        }
    }
    return mask;
}

// Every moving joint uniform within its limits (continuous: a full turn).
std::vector<double> random_configuration(Rng &rng, const opx_linkset *links) {
    uint32_t count = 0;
    require_ok(opx_linkset_get_joint_count(links, &count), "opx_linkset_get_joint_count");
    std::vector<double> q(count, 0.0);
    for (uint32_t j = 0; j < count; ++j) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        require_ok(opx_linkset_get_joint_info(links, j, &info), "opx_linkset_get_joint_info");
        if (info.type == OPX_JOINT_CONTINUOUS) q[j] = rng.uniform(-kPi, kPi);
        else if ((info.type == OPX_JOINT_REVOLUTE || info.type == OPX_JOINT_PRISMATIC) && info.has_limits)
            q[j] = rng.uniform(info.lower, info.upper);
    }
    return q;
}

void check_pr2(const std::string &dir, bool with_srdf, int configurations, Rng &rng, uint64_t seed,
               SelfChecker &checker) {
    opx_linkset *links = load_pr2(dir, with_srdf);
    RobotSpec robot = spec_of(links);
    const PairMask pairs = with_srdf ? srdf_mask(links, robot.links.size(), checker) : PairMask(robot.links.size());
    opx_query *query = nullptr;
    require_ok(opx_query_create(nullptr, &query), "opx_query_create");
    for (int k = 0; k < configurations; ++k) {
        const std::vector<double> q = random_configuration(rng, links);
        require_ok(opx_linkset_set_joint_positions(links, q.data(), q.size(), nullptr), "set_joint_positions");
        robot.global_padding = k % 2 == 0 ? 0.0 : 0.01;
        require_ok(opx_linkset_set_padding(links, robot.global_padding), "opx_linkset_set_padding");
        for (uint32_t i = 0; i < robot.links.size(); ++i)
            require_ok(opx_linkset_get_pose(links, i, &robot.links[i].pose), "opx_linkset_get_pose");
        const std::vector<PlacedShape> placed = place_robot(robot);
        const std::string label = std::string("PR2 ") + (with_srdf ? "with" : "without") + " SRDF configuration " +
                                  std::to_string(k) + " (seed " + std::to_string(seed) + ")";
        checker.check(query, links, {&placed, &pairs, label});
    }
    opx_query_destroy(query);
    opx_linkset_destroy(links);
}

int run_pr2(uint64_t seed) {
    const std::string dir = data_path("robots/pr2_description");
    if (dir.empty()) return 77;
    Rng rng(seed);
    SelfChecker checker("oracle_self pr2");
    check_pr2(dir, true, static_cast<int>(env_number("OPX_ORACLE_SCENES", 60)), rng, seed, checker);
    check_pr2(dir, false, static_cast<int>(env_number("OPX_ORACLE_SCENES", 60)) / 3, rng, seed, checker);
    return checker.finish(elapsed_seconds());
}

}  // namespace

int main(int argc, char **argv) {
    elapsed_seconds();
    const uint64_t seed = env_number("OPX_ORACLE_SEED", 24);
    if (argc == 2 && std::strcmp(argv[1], "arm") == 0) return run_arms(seed);
    if (argc == 2 && std::strcmp(argv[1], "pr2") == 0) return run_pr2(seed);
    std::printf("usage: %s arm|pr2\n", argv[0]);
    return 2;
}
