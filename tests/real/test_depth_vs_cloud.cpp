// real_depth_vs_cloud: the real Kinect frame as a 16-bit depth image (TIFF,
// millimetres) inserted through opx_octree_insert_depth_image, and the same
// frame as the organized PCD cloud PCL made of it, inserted as points, give
// the same map.
//
// The cloud is the image back-projected with the frame's intrinsics (row
// after row, pixel (u, v) at index v * 640 + u, NaN where the depth is 0),
// in float32 arithmetic; the library computes in double and rounds once.
// The coordinates differ by at most a few float steps (about 1e-7 m), so
// only a ray or endpoint that grazes a cell boundary can land differently:
// the maps may differ in a few cells, at most kMaxDifferingShare of the
// known ones, a bound observed on this frame (0.15-0.5%), not derived.
// The exact check is the image against the points the header's formula
// gives: the same map, cell for cell.
#include "real_support.hpp"

#include "depth_image.h"
#include "pcd_reader.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace {

constexpr size_t kWidth = 640, kHeight = 480, kFinitePoints = 271575;
// The coordinates of the cloud and of the back-projected image differ by
// float rounding: a few steps of 1.2e-7 m at the frame's 1.7 m at most.
constexpr double kMaxCoordinateGap = 1e-6;
// Known cells whose class differs (or that one map lacks), as a share of
// the known cells of either map.
constexpr double kMaxDifferingShare = 0.01;

depth_image g_depth;
pcd_cloud g_cloud;
std::string g_intrinsics_xml;
opx_camera_intrinsics g_camera = OPX_CAMERA_INTRINSICS_INIT;
double g_depth_scale = 0.0;  // units per metre

// The number in <tag>...</tag> after the first `section` tag of the XML.
double xml_number(const char *section, const char *tag) {
    const size_t start = g_intrinsics_xml.find(std::string("<") + section + ">");
    const size_t at = g_intrinsics_xml.find(std::string("<") + tag + ">", start);
    if (start == std::string::npos || at == std::string::npos) fail_msg("no <%s><%s> in the intrinsics", section, tag);
    return std::strtod(g_intrinsics_xml.c_str() + at + std::strlen(tag) + 2, nullptr);
}

// The depth camera's section of the intrinsics file.
void read_intrinsics() {
    g_camera.fx = xml_number("depth", "focal_length_x");
    g_camera.fy = xml_number("depth", "focal_length_y");
    g_camera.cx = xml_number("depth", "principal_point_x");
    g_camera.cy = xml_number("depth", "principal_point_y");
    g_depth_scale = 1.0 / xml_number("depth", "z_multiplication_factor");
}

void test_intrinsics_of_the_depth_camera(void **) {
    print_message("intrinsics: fx %g, fy %g, cx %g, cy %g; %g depth units a metre\n", g_camera.fx, g_camera.fy,
                  g_camera.cx, g_camera.cy, g_depth_scale);
    assert_true(g_camera.fx == 525.0 && g_camera.fy == 525.0 && g_camera.cx == 320.0 && g_camera.cy == 240.0);
    assert_true(std::fabs(g_depth_scale - 1000.0) < 1e-9);
}

// Pixel (u, v) is point v * width + u; no depth where the point is NaN;
// the intrinsics reproduce x, y and z.
void test_cloud_is_the_back_projected_image(void **) {
    assert_int_equal(g_depth.width, kWidth);
    assert_int_equal(g_depth.height, kHeight);
    assert_int_equal(g_cloud.width, kWidth);
    assert_int_equal(g_cloud.height, kHeight);
    double gap[3] = {0.0, 0.0, 0.0};
    size_t with_depth = 0;
    for (size_t v = 0; v < kHeight; ++v) {
        for (size_t u = 0; u < kWidth; ++u) {
            const uint16_t units = g_depth.pixels[v * kWidth + u];
            const float *p = &g_cloud.xyz[3 * (v * kWidth + u)];
            const bool finite = std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
            if (finite != (units != 0)) fail_msg("pixel (%zu, %zu): depth %u but point finite %d", u, v, units, finite);
            if (units == 0) continue;
            ++with_depth;
            const double z = units / g_depth_scale;
            const double xyz[3] = {(u - g_camera.cx) * z / g_camera.fx, (v - g_camera.cy) * z / g_camera.fy, z};
            for (int axis = 0; axis < 3; ++axis) gap[axis] = std::fmax(gap[axis], std::fabs(xyz[axis] - p[axis]));
        }
    }
    print_message("%zu pixels with depth = the finite points; largest gap x %.3g, y %.3g, z %.3g m\n", with_depth,
                  gap[0], gap[1], gap[2]);
    assert_int_equal(with_depth, kFinitePoints);
    for (double g : gap) assert_true(g <= kMaxCoordinateGap);
}

// The real frame as the library takes it.
opx_depth_image frame_image() {
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    image.data = g_depth.pixels;
    image.width = g_depth.width;
    image.height = g_depth.height;
    image.depth_scale = g_depth_scale;
    return image;
}

void compare_maps(double resolution) {
    const opx_insert_options identity = OPX_INSERT_OPTIONS_INIT;
    opx_octree *from_depth = real::new_octree(resolution), *from_cloud = real::new_octree(resolution);
    const opx_depth_image image = frame_image();
    opx_insert_report depth_report = OPX_INSERT_REPORT_INIT, cloud_report = OPX_INSERT_REPORT_INIT;
    real::check_ok(opx_octree_insert_depth_image(from_depth, &image, &g_camera, &identity, &depth_report),
                   "opx_octree_insert_depth_image");
    real::check_ok(opx_octree_insert_points(from_cloud, g_cloud.xyz, g_cloud.count, 0, OPX_SCALAR_FLOAT32,
                                            &identity, &cloud_report),
                   "opx_octree_insert_points");
    assert_int_equal(depth_report.points_used, kFinitePoints);
    assert_int_equal(depth_report.pixels_no_return, kWidth * kHeight - kFinitePoints);
    assert_int_equal(cloud_report.points_used, kFinitePoints);

    const real::CellComparison c =
        real::compare_cells(real::expand_octoprox(from_depth), real::expand_octoprox(from_cloud));
    const size_t known = c.common + c.only_octoprox + c.only_octomap;
    const size_t differing = c.only_octoprox + c.only_octomap + c.class_mismatch;
    const double share = static_cast<double>(differing) / static_cast<double>(known);
    std::printf("%g cm: %zu known cells; %zu only from the image, %zu only from the cloud, %zu of another class, "
                "%zu with other log-odds: %.4f%% of the known cells differ in class (at most %.1f%%); cells hit "
                "%llu vs %llu, missed %llu vs %llu\n",
                resolution * 100, known, c.only_octoprox, c.only_octomap, c.class_mismatch, c.value_mismatch,
                100.0 * share, 100.0 * kMaxDifferingShare, (unsigned long long)depth_report.cells_hit,
                (unsigned long long)cloud_report.cells_hit, (unsigned long long)depth_report.cells_missed,
                (unsigned long long)cloud_report.cells_missed);
    assert_true(known > 1000);
    assert_true(share <= kMaxDifferingShare);
    opx_octree_destroy(from_depth);
    opx_octree_destroy(from_cloud);
}

// The image's map is exactly the map of the points octree.h says it
// back-projects ((u - cx) z / fx, (v - cy) z / fy, z in double, each rounded
// to float): not a cell and not a bit of log-odds apart.  (The cloud above
// is PCL's float32 back-projection, a few float steps away from these.)
void image_is_its_documented_points(double resolution) {
    std::vector<float> xyz;
    for (size_t v = 0; v < kHeight; ++v)
        for (size_t u = 0; u < kWidth; ++u) {
            const uint16_t units = g_depth.pixels[v * kWidth + u];
            if (units == 0) continue;
            const double z = units / g_depth_scale;
            xyz.push_back(static_cast<float>((static_cast<double>(u) - g_camera.cx) * z / g_camera.fx));
            xyz.push_back(static_cast<float>((static_cast<double>(v) - g_camera.cy) * z / g_camera.fy));
            xyz.push_back(static_cast<float>(z));
        }
    const opx_insert_options identity = OPX_INSERT_OPTIONS_INIT;
    opx_octree *from_depth = real::new_octree(resolution), *from_points = real::new_octree(resolution);
    const opx_depth_image image = frame_image();
    real::check_ok(opx_octree_insert_depth_image(from_depth, &image, &g_camera, &identity, nullptr),
                   "opx_octree_insert_depth_image");
    real::check_ok(opx_octree_insert_points(from_points, xyz.data(), xyz.size() / 3, 0, OPX_SCALAR_FLOAT32,
                                            &identity, nullptr),
                   "opx_octree_insert_points");
    const real::CellComparison c =
        real::compare_cells(real::expand_octoprox(from_depth), real::expand_octoprox(from_points));
    real::print_comparison(resolution == 0.05 ? "image vs its points, 5 cm" : "image vs its points, 2 cm", c);
    assert_true(c.identical());
    opx_octree_destroy(from_depth);
    opx_octree_destroy(from_points);
}

void test_image_is_its_points_at_5cm(void **) { image_is_its_documented_points(0.05); }
void test_image_is_its_points_at_2cm(void **) { image_is_its_documented_points(0.02); }

void test_same_map_at_5cm(void **) { compare_maps(0.05); }
void test_same_map_at_2cm(void **) { compare_maps(0.02); }

}  // namespace

int main() {
    const std::string tiff = real::require_data_file("rgbd/frame_20121214T142255.814212_depth.tiff");
    const std::string pcd = real::require_data_file("rgbd/frame_20121214T142255.814212_binary.pcd");
    const std::string xml = real::require_data_file("rgbd/frame_20121214T142255.814212_intrinsics.xml");
    char error[700];
    if (depth_image_read_file(tiff.c_str(), &g_depth, error, sizeof error) != 0 ||
        pcd_read_file(pcd.c_str(), &g_cloud, error, sizeof error) != 0) {
        std::fprintf(stderr, "%s\n", error);
        return 1;
    }
    std::ifstream xml_file(xml);
    std::stringstream text;
    text << xml_file.rdbuf();
    g_intrinsics_xml = text.str();
    read_intrinsics();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_intrinsics_of_the_depth_camera),
        cmocka_unit_test(test_cloud_is_the_back_projected_image),
        cmocka_unit_test(test_image_is_its_points_at_5cm),
        cmocka_unit_test(test_image_is_its_points_at_2cm),
        cmocka_unit_test(test_same_map_at_5cm),
        cmocka_unit_test(test_same_map_at_2cm),
    };
    const int failures = cmocka_run_group_tests_name("real_depth_vs_cloud", tests, nullptr, nullptr);
    depth_image_free(&g_depth);
    pcd_free(&g_cloud);
    return failures == 0 ? 0 : 1;
}
