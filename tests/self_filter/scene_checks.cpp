#include "scene_checks.hpp"

#include "filter_helpers.hpp"
#include "real_support.hpp"

#include <chrono>
#include <cstring>
#include <unordered_set>

namespace filter_oracle {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Tally {
    size_t kept = 0, on_robot = 0, shadowed = 0, ambiguous = 0;
    size_t env_in_band = 0, env_just_beyond = 0;  // environment points within the padding / 1 cm beyond it
};

Tally tally(const SceneRun &run, const std::vector<Verdict> &verdicts) {
    Tally t;
    for (size_t i = 0; i < verdicts.size(); ++i) {
        const Verdict &v = verdicts[i];
        t.ambiguous += v.ambiguous;
        if (v.ambiguous) continue;
        (v.kind == Verdict::kKept ? t.kept : v.kind == Verdict::kOnRobot ? t.on_robot : t.shadowed) += 1;
        if (run.points.robot_pixel[i]) {
            if (v.kind != Verdict::kOnRobot) fail_msg("%s: robot pixel %zu is not a robot point", run.label.c_str(), i);
            continue;
        }
        const double gap = v.end_gap;
        t.env_in_band += gap <= 0.0;
        t.env_just_beyond += gap > 0.0 && gap <= 0.01;
    }
    return t;
}

opx_insert_options filter_options(const SceneRun &run, uint32_t threads) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.robot = run.robot;
    options.robot_padding = run.settings.robot_padding;
    options.max_threads = threads;
    return options;
}

// The report's counts against the oracle's, up to its ambiguous points.
void check_report(const SceneRun &run, const opx_insert_report &r, const Tally &t) {
    const size_t n = run.points.frame.points.size();
    assert_int_equal(r.points_used + r.points_nonfinite + r.points_out_of_range + r.points_outside_map +
                         r.points_on_robot + r.points_shadowed + r.pixels_no_return,
                     n);
    const auto near = [&](uint64_t got, size_t expected) {
        return got + t.ambiguous >= expected && got <= expected + t.ambiguous;
    };
    if (!near(r.points_used, t.kept) || !near(r.points_on_robot, t.on_robot) || !near(r.points_shadowed, t.shadowed))
        fail_msg("%s: report used %llu, on robot %llu, shadowed %llu; oracle %zu, %zu, %zu (+- %zu ambiguous)",
                 run.label.c_str(), (unsigned long long)r.points_used, (unsigned long long)r.points_on_robot,
                 (unsigned long long)r.points_shadowed, t.kept, t.on_robot, t.shadowed, t.ambiguous);
}

octomap::OcTreeKey key_of(const octomap::OcTree &grid, const octomap::point3d &p) {
    octomap::OcTreeKey key;
    if (!grid.coordToKeyChecked(p, key)) fail_msg("a point outside the map");
    return key;
}

// No cell holding only robot pixels' points is occupied; every kept
// environment point's cell is.
void check_cells(const SceneRun &run, const real::FineCells &cells, const std::vector<Verdict> &verdicts,
                 const octomap::OcTree &grid) {
    std::unordered_set<uint64_t> robot_cells, environment_cells;
    const auto &pts = run.points.frame.points;
    for (size_t i = 0; i < pts.size(); ++i)
        (run.points.robot_pixel[i] ? robot_cells : environment_cells).insert(packed(key_of(grid, pts[i])));
    size_t robot_only = 0;
    for (uint64_t key : robot_cells) {
        if (environment_cells.count(key)) continue;
        ++robot_only;
        const auto cell = cells.find(key);
        if (cell != cells.end() && cell->second > 0.0f)
            fail_msg("%s: a robot-only cell is occupied", run.label.c_str());
    }
    size_t kept = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        if (run.points.robot_pixel[i] || verdicts[i].ambiguous || verdicts[i].kind != Verdict::kKept) continue;
        ++kept;
        const auto cell = cells.find(packed(key_of(grid, pts[i])));
        if (cell == cells.end() || !(cell->second > 0.0f))
            fail_msg("%s: kept point %zu (%.6f %.6f %.6f) is not in an occupied cell", run.label.c_str(), i,
                     pts[i].x(), pts[i].y(), pts[i].z());
    }
    print_message("    %zu robot-only cells none occupied; %zu kept environment points all in occupied cells\n",
                  robot_only, kept);
}

void check_threads(const SceneRun &run, double resolution) {
    std::vector<unsigned char> first;
    opx_insert_report first_report = OPX_INSERT_REPORT_INIT;
    for (uint32_t threads : {1u, 2u, 0u}) {
        opx_octree *tree = real::new_octree(resolution);
        const opx_insert_report r = insert_frame(tree, run.points.frame, filter_options(run, threads));
        const std::vector<unsigned char> bytes = saved_bytes(tree);
        opx_octree_destroy(tree);
        if (threads == 1u) {
            first = bytes, first_report = r;
            continue;
        }
        if (bytes != first || std::memcmp(&r, &first_report, sizeof r) != 0)
            fail_msg("%s: max_threads %u changes the map or the report", run.label.c_str(), threads);
    }
    print_message("    max_threads 1, 2, 0: the same %zu bytes and report\n", first.size());
}

// The composite as a float32 depth image: every pixel counted once.
void check_depth_image_report(const SceneRun &run, double resolution) {
    const render::Camera &c = run.rendered.camera;
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    image.scalar_type = OPX_SCALAR_FLOAT32, image.data = run.rendered.composite.data();
    image.width = c.width, image.height = c.height;
    opx_camera_intrinsics intrinsics = OPX_CAMERA_INTRINSICS_INIT;
    intrinsics.fx = c.fx, intrinsics.fy = c.fy, intrinsics.cx = c.cx, intrinsics.cy = c.cy;
    opx_insert_options options = filter_options(run, 1);
    options.sensor_pose = c.pose;
    opx_insert_report r = OPX_INSERT_REPORT_INIT;
    opx_octree *tree = real::new_octree(resolution);
    real::check_ok(opx_octree_insert_depth_image(tree, &image, &intrinsics, &options, &r), "insert_depth_image");
    opx_octree_destroy(tree);
    assert_int_equal(r.points_used + r.points_nonfinite + r.points_out_of_range + r.points_outside_map +
                         r.points_on_robot + r.points_shadowed + r.pixels_no_return,
                     c.width * c.height);
    assert_true(r.points_on_robot > 0);
}

void check_resolution(const SceneRun &run, double resolution, const std::vector<Verdict> &verdicts, const Tally &t,
                      SceneTimes &times) {
    opx_octree *tree = real::new_octree(resolution);
    Clock::time_point start = Clock::now();
    const opx_insert_report report = insert_frame(tree, run.points.frame, filter_options(run, 1));
    times.library += seconds_since(start);
    check_report(run, report, t);
    start = Clock::now();
    const Expected expected = expected_map(resolution, run.points.frame, verdicts);
    times.octomap += seconds_since(start);
    print_message("  %g cm: report used %llu, on robot %llu, shadowed %llu\n", resolution * 100,
                  (unsigned long long)report.points_used, (unsigned long long)report.points_on_robot,
                  (unsigned long long)report.points_shadowed);
    check_cells(run, real::expand_octoprox(tree), verdicts, *expected.tree);
    const MapDifference d = compare_maps(tree, expected);
    print_message("    map vs OctoMap's: %zu cells, %zu differ outside the tolerated ones, %zu tolerated differ "
                  "(%zu cut points within 1e-6 m of a face, %zu ambiguous rays)\n",
                  d.cells, d.differing, d.tolerated_differing, expected.cuts_near_a_face, expected.ambiguous_rays);
    opx_octree_destroy(tree);
    if (d.differing != 0) fail_msg("%s at %g m: %zu cells differ", run.label.c_str(), resolution, d.differing);
    if (d.tolerated_differing * 1000 > d.cells) fail_msg("%s: too many tolerated cells differ", run.label.c_str());
}

// With max_range: the points beyond it (OctoMap's float test) are their
// rays cut at max_range, judged as rays only, then cut again where they
// enter the padded robot; the map must still equal OctoMap's.
void check_max_range(const SceneRun &run, const OracleRobot &oracle, double resolution, double max_range) {
    const MapFrame &frame = run.points.frame;
    MapFrame rays;
    rays.origin = frame.origin;
    std::vector<bool> cut(frame.points.size(), false);
    size_t beyond = 0;
    for (size_t i = 0; i < frame.points.size(); ++i) {
        const octomap::point3d &p = frame.points[i];
        if ((p - frame.origin).norm() <= max_range) {
            rays.points.push_back(p);
            continue;
        }
        cut[i] = true, ++beyond;
        rays.points.push_back(frame.origin + (p - frame.origin).normalized() * static_cast<float>(max_range));
    }
    const std::vector<Verdict> verdicts = oracle.judge_frame(as_double(frame.origin), as_doubles(rays.points), cut);
    size_t cut_by_robot = 0;
    for (size_t i = 0; i < verdicts.size(); ++i) cut_by_robot += cut[i] && verdicts[i].kind != Verdict::kKept;
    opx_octree *tree = real::new_octree(resolution);
    opx_insert_options options = filter_options(run, 1);
    options.max_range = max_range;
    const opx_insert_report r = insert_frame(tree, frame, options);
    const MapDifference d = compare_maps(tree, expected_map(resolution, rays, verdicts));
    opx_octree_destroy(tree);
    print_message("  max_range %g m at %g cm: %zu points beyond it (report %llu), %zu of their rays then cut by the "
                  "robot; %zu cells, %zu differ, %zu tolerated differ\n",
                  max_range, resolution * 100, beyond, (unsigned long long)r.points_out_of_range, cut_by_robot, d.cells,
                  d.differing, d.tolerated_differing);
    assert_int_equal(r.points_out_of_range, beyond);
    if (d.differing != 0) fail_msg("%s with max_range: %zu cells differ", run.label.c_str(), d.differing);
}

}  // namespace

void check_scene(const SceneRun &run, const std::vector<double> &resolutions, const ExtraChecks &extra,
                 SceneTimes &times) {
    Clock::time_point start = Clock::now();
    const OracleRobot oracle(run.robot, run.settings);
    const std::vector<Verdict> verdicts =
        oracle.judge_frame(as_double(run.points.frame.origin), as_doubles(run.points.frame.points));
    const Tally t = tally(run, verdicts);
    times.oracle += seconds_since(start);
    print_message("%s: %zu points: oracle kept %zu, robot %zu, shadowed %zu, ambiguous %zu; environment points "
                  "within the padding %zu, up to 1 cm beyond %zu (%zu closed meshes, %zu hulls; %zu solids hold the "
                  "sensor)\n",
                  run.label.c_str(), run.points.frame.points.size(), t.kept, t.on_robot, t.shadowed, t.ambiguous,
                  t.env_in_band, t.env_just_beyond, oracle.closed_meshes(), oracle.hull_meshes(),
                  oracle.solids_holding(as_double(run.points.frame.origin)));
    if (t.ambiguous * 1000 > run.points.frame.points.size())
        fail_msg("%s: too many ambiguous points", run.label.c_str());
    for (double resolution : resolutions) check_resolution(run, resolution, verdicts, t, times);
    if (extra.max_range) check_max_range(run, oracle, resolutions.front(), run.max_range);
    if (extra.depth_image) check_depth_image_report(run, resolutions.front());
    if (extra.threads) check_threads(run, resolutions.front());
}

}  // namespace filter_oracle
