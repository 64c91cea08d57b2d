// self_filter_oracle: self-filtered frames against an independent oracle.
// Depth frames rendered exactly (tests/render) of a generated arm above a
// table (`arm`, no data needed) and of the PR2 composited into the shared
// real frame (`pr2`, exit 77 without the data), at 2 and 5 cm, with
// robot_padding 0.02:
//   - no cell holding only robot pixels' points is occupied;
//   - every environment point the oracle keeps (farther than the padding
//     from the robot, its ray too) lands in an occupied cell;
//   - the map equals OctoMap's (octomap::OcTree, computeRayKeys and
//     updateNode) of the kept points plus the rays cut where the oracle
//     finds them entering the padded robot, cell for cell, but for cells
//     within 1e-6 m of a cut point and ambiguous rays (counted, rare);
//   - the report's counts match the oracle's and add up, on the points and
//     on the depth-image path; max_threads 1, 2, 0 give the same bytes;
//   - with max_range, rays cut there and then by the robot: OctoMap's map.
// OPX_SELF_FILTER_LONG=1 runs every configuration and camera.
#include "scene_checks.hpp"

#include "real_support.hpp"
#include "render_pr2.hpp"

#include <cstdlib>
#include <cstring>

namespace {

using filter_oracle::SceneRun;

constexpr double kRobotPadding = 0.02;
const std::vector<double> kResolutions = {0.05, 0.02};
filter_oracle::SceneTimes g_times;

bool long_run() {
    const char *flag = std::getenv("OPX_SELF_FILTER_LONG");
    return flag != nullptr && std::strcmp(flag, "1") == 0;
}

// Configuration and camera pairs: by default each configuration from one
// camera and the first from inside the shoulder; the long run every pair.
std::vector<std::pair<int, size_t>> arm_frames(size_t cameras) {
    if (!long_run()) return {{0, 0}, {1, 1}, {2, 2}, {0, 3}};
    std::vector<std::pair<int, size_t>> all;
    for (int config = 0; config < filter_oracle::arm_configuration_count(); ++config)
        for (size_t c = 0; c < cameras; ++c) all.push_back({config, c});
    return all;
}

void test_arm_frames(void **) {
    const std::vector<render::Camera> cameras = filter_oracle::arm_cameras();
    filter_oracle::ExtraChecks extra;  // all on the first frame, the maps with max_range on all
    for (const auto &frame : arm_frames(cameras.size())) {
        opx_linkset *arm = filter_oracle::make_arm(frame.first);
        // The hand's own padding adds to robot_padding.
        real::check_ok(opx_linkset_set_link_padding(arm, 4, 0.005), "opx_linkset_set_link_padding");
        opx_linkset *world = filter_oracle::make_environment(arm);
        SceneRun run;
        run.label = "arm configuration " + std::to_string(frame.first) + ", camera " + std::to_string(frame.second);
        run.robot = arm;
        run.settings.robot_padding = kRobotPadding;
        run.settings.link_padding = {0, 0, 0, 0, 0.005, 0};
        run.max_range = 1.5;
        run.rendered = filter_oracle::render_frame(run.label, arm, world, cameras[frame.second]);
        run.points = filter_oracle::frame_points(run.rendered);
        filter_oracle::check_scene(run, kResolutions, extra, g_times);
        extra.threads = extra.depth_image = false;
        opx_linkset_destroy(world);
        opx_linkset_destroy(arm);
    }
}

void test_pr2_frames(void **) {
    const std::string dir = render::data_dir();
    for (int pose = 0; pose < render::pr2_arm_pose_count(); ++pose) {
        if (!long_run() && pose % 2 == 1) continue;
        render::Pr2Scene scene = render::make_pr2_scene(dir, pose);
        SceneRun run;
        run.label = "PR2 arm pose " + std::to_string(pose);
        run.robot = scene.robot;
        run.settings.robot_padding = kRobotPadding;
        run.rendered.label = run.label;
        run.rendered.camera = scene.camera;
        run.rendered.robot_depth = scene.robot_depth;
        run.rendered.composite = scene.composite;
        run.points = filter_oracle::frame_points(run.rendered);
        // A self-filtered PR2 insert takes about a second (its meshes): the extra
        // checks once, max_range where the robot cuts rays beyond it.
        filter_oracle::ExtraChecks extra;
        extra.threads = extra.depth_image = pose == 0;
        extra.max_range = pose != 0;
        filter_oracle::check_scene(run, kResolutions, extra, g_times);
        render::destroy(scene);
    }
}

}  // namespace

int main(int argc, char **argv) {
    const std::string which = argc > 1 ? argv[1] : "arm";
    int failed = 0;
    if (which == "pr2") {
        const std::string missing = render::missing_pr2_data(render::data_dir());
        if (!missing.empty()) real::exit_without_data(missing);
        const struct CMUnitTest tests[] = {cmocka_unit_test(test_pr2_frames)};
        failed = cmocka_run_group_tests(tests, nullptr, nullptr);
    } else {
        const struct CMUnitTest tests[] = {cmocka_unit_test(test_arm_frames)};
        failed = cmocka_run_group_tests(tests, nullptr, nullptr);
    }
    std::printf("time: oracle %.2f s, library inserts %.2f s, OctoMap's maps %.2f s\n", g_times.oracle,
                g_times.library, g_times.octomap);
    return failed;
}
