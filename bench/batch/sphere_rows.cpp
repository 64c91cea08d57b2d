#include "sphere_rows.hpp"

#include "arm_urdf.hpp"
#include "pipelines.hpp"
#include "rng.hpp"
#include "timing.hpp"

namespace batch_bench {
namespace {

using paper_tables::check_opx;

constexpr double kSphereRadius = 0.05;
constexpr uint64_t kSphereSeed = 0x5F11E7u;

std::vector<opx_pose> sphere_poses(const opx_octree *tree, size_t count) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
    paper_tables::Rng rng(kSphereSeed);
    std::vector<opx_pose> poses(count, opx_pose(OPX_POSE_IDENTITY));
    for (opx_pose &pose : poses)
        for (int axis = 0; axis < 3; ++axis)
            pose.position[axis] = rng.uniform(stats.occupied_min[axis], stats.occupied_max[axis]);
    return poses;
}

paper_tables::OpxLinksetPtr one_sphere() {
    opx_linkset *raw = nullptr;
    check_opx(opx_linkset_create(&raw), "opx_linkset_create");
    paper_tables::OpxLinksetPtr links(raw);
    uint32_t link = 0;
    check_opx(opx_linkset_add_link(raw, "sphere", &link), "opx_linkset_add_link");
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_SPHERE;
    shape.radius = kSphereRadius;
    check_opx(opx_linkset_add_shape(raw, link, &shape, nullptr), "opx_linkset_add_shape");
    return links;
}

// One batch call of the set's first configuration on a fresh copy of the
// map, in microseconds.
double first_batch_us(const Robot &arm, const Scene &scene, const ConfigurationSet &set) {
    const paper_tables::OpxOctreePtr tree = paper_tables::copy_octree(scene.tree.get());
    const paper_tables::OpxQueryPtr query = paper_tables::make_direct_query();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    uint8_t collided = 0;
    return 1e3 * paper_tables::time_once_ms([&] {
        check_opx(opx_query_check_configurations(query.get(), tree.get(), arm.links.get(), set.rows.data(), 1,
                                                 set.joints, 0, &set.base, 1, 0, &request, &collided, nullptr, 1),
                  "opx_query_check_configurations");
    });
}

}  // namespace

SphereArmTiming time_sphere_arm(Robot &arm, const Scene &scene, size_t count, int rounds) {
    const ConfigurationSet set = draw_configurations(arm, scene.arm_base, count, kSphereSeed, false);
    const Workload work{arm, scene, set, false, rounds};
    SphereArmTiming out;
    out.first_call_us = first_batch_us(arm, scene, set);
    const Timing timing = time_interleaved(work, {batch_call(work, 1)})[0];
    out.configurations = count;
    for (uint8_t c : timing.collided) out.collided += c;
    out.us_per_configuration = timing.us_per_configuration;
    out.ns_per_sphere = 1000.0 * timing.us_per_configuration / kArmSpheres;
    return out;
}

SphereCallTiming time_single_sphere_calls(const Scene &scene, size_t count, int rounds, bool link_set) {
    const paper_tables::OpxOctreePtr tree = paper_tables::copy_octree(scene.tree.get());
    const std::vector<opx_pose> poses = sphere_poses(tree.get(), count);
    const paper_tables::OpxLinksetPtr sphere = one_sphere();
    const paper_tables::OpxQueryPtr query = paper_tables::make_direct_query();
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 0;
    std::vector<double> rows;
    for (const opx_pose &pose : poses) rows.insert(rows.end(), {pose.position[0], pose.position[1], pose.position[2], kSphereRadius});
    SphereCallTiming out;
    out.calls = count;
    auto through_link_set = [&](size_t i) {
        check_opx(opx_linkset_set_poses(sphere.get(), &poses[i], 1, 0), "opx_linkset_set_poses");
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        check_opx(opx_query_collide(query.get(), tree.get(), sphere.get(), &request, &result),
                  "opx_query_collide");
        return result.collided != 0;
    };
    auto through_spheres_call = [&](size_t i) {
        uint8_t collided = 0;
        check_opx(opx_query_collide_spheres(query.get(), tree.get(), &rows[4 * i], 1, 0, nullptr, &collided, 1),
                  "opx_query_collide_spheres");
        return collided != 0;
    };
    auto call = [&](size_t i) { return link_set ? through_link_set(i) : through_spheres_call(i); };
    auto run = [&] {
        size_t collided = 0;
        for (size_t i = 0; i < poses.size(); ++i) collided += call(i);
        out.collided = collided;
    };
    out.first_call_us = 1e3 * paper_tables::time_once_ms([&] { call(0); });
    run();
    std::vector<double> ns;
    for (int r = 0; r < rounds; ++r) ns.push_back(1e6 * paper_tables::time_once_ms(run) / double(count));
    out.ns_per_call = paper_tables::median(ns);
    return out;
}

}  // namespace batch_bench
