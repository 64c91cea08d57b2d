// render_depth: the renderer against depths worked out by hand for each
// solid kind; a convex hull and a closed mesh of a box render as the box;
// attached objects are seen; nearer_depth; the PR2 scenes (skipped, exit
// 77, without the shared data) show the arms in front of the real frame.
#include "render_pr2.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

int g_failures = 0;

#define CHECK(cond, ...)                                          \
    do {                                                          \
        if (!(cond)) {                                            \
            std::printf("FAIL %s:%d: ", __FILE__, __LINE__);      \
            std::printf(__VA_ARGS__);                             \
            std::printf("\n");                                    \
            ++g_failures;                                         \
        }                                                         \
    } while (0)

// A camera at the origin looking along +z, its principal point on a pixel.
render::Camera axis_camera() {
    render::Camera camera;
    camera.cx = 320.0, camera.cy = 240.0;
    return camera;
}

opx_linkset *one_shape(const opx_shape &shape) {
    opx_linkset *robot = nullptr;
    uint32_t link = 0;
    opx_linkset_create(&robot);
    opx_linkset_add_link(robot, "link", &link);
    opx_linkset_add_shape(robot, link, &shape, nullptr);
    const opx_pose identity = OPX_POSE_IDENTITY;
    opx_linkset_set_poses(robot, &identity, 1, 0);
    return robot;
}

opx_shape placed(int32_t kind, double z) {
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = kind;
    shape.pose.position[2] = z;
    return shape;
}

float centre_depth(const opx_shape &shape) {
    opx_linkset *robot = one_shape(shape);
    const render::Camera camera = axis_camera();
    const float depth = render::render_depth(robot, camera)[240 * camera.width + 320];
    opx_linkset_destroy(robot);
    return depth;
}

void test_primitives_on_the_axis() {
    opx_shape sphere = placed(OPX_SHAPE_SPHERE, 3.0);
    sphere.radius = 0.5;
    CHECK(centre_depth(sphere) == 2.5f, "sphere %g", centre_depth(sphere));
    opx_shape box = placed(OPX_SHAPE_BOX, 3.0);
    box.size[0] = 1.0, box.size[1] = 2.0, box.size[2] = 0.4;
    CHECK(centre_depth(box) == 2.8f, "box %g", centre_depth(box));
    opx_shape cylinder = placed(OPX_SHAPE_CYLINDER, 3.0);
    cylinder.radius = 0.25, cylinder.length = 1.0;
    CHECK(centre_depth(cylinder) == 2.5f, "cylinder end %g", centre_depth(cylinder));
    cylinder.pose.orientation[0] = std::sqrt(0.5), cylinder.pose.orientation[3] = std::sqrt(0.5);  // axis along y
    CHECK(centre_depth(cylinder) == 2.75f, "cylinder side %g", centre_depth(cylinder));
    opx_shape capsule = placed(OPX_SHAPE_CAPSULE, 3.0);
    capsule.radius = 0.25, capsule.length = 1.0;
    CHECK(centre_depth(capsule) == 2.25f, "capsule end %g", centre_depth(capsule));
    sphere.pose.position[2] = 0.2;  // holds the camera: not seen
    CHECK(centre_depth(sphere) == 0.0f, "camera inside %g", centre_depth(sphere));
}

// Off the axis: the sphere's entry solved in long double.
void test_sphere_off_the_axis() {
    opx_shape sphere = placed(OPX_SHAPE_SPHERE, 3.0);
    sphere.radius = 0.5;
    opx_linkset *robot = one_shape(sphere);
    const render::Camera camera = axis_camera();
    const std::vector<float> depth = render::render_depth(robot, camera);
    size_t seen = 0;
    for (size_t u = 320; u < 640; u += 7) {
        const long double dx = (static_cast<long double>(u) - 320.0L) / 525.0L;
        const long double a = dx * dx + 1.0L, b = -3.0L, c = 9.0L - 0.25L;
        const long double disc = b * b - a * c;
        const float expected = disc < 0 ? 0.0f : static_cast<float>((-b - std::sqrt(disc)) / a);
        const float got = depth[240 * camera.width + u];
        CHECK(std::fabs(got - expected) <= 1e-6f * expected, "pixel %zu: %.9g, expected %.9g", u, got, expected);
        seen += got > 0.0f;
    }
    CHECK(seen > 5, "the sphere covers %zu sampled pixels", seen);
    opx_linkset_destroy(robot);
}

const double kCube[8][3] = {{-0.3, -0.2, 2.0}, {0.3, -0.2, 2.0}, {-0.3, 0.2, 2.0}, {0.3, 0.2, 2.0},
                            {-0.3, -0.2, 2.5}, {0.3, -0.2, 2.5}, {-0.3, 0.2, 2.5}, {0.3, 0.2, 2.5}};
const uint32_t kCubeTriangles[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};

// Pixels whose depths differ by more than a float step.
size_t differing_pixels(const std::vector<float> &a, const std::vector<float> &b) {
    size_t differing = 0;
    for (size_t i = 0; i < a.size(); ++i) differing += std::fabs(a[i] - b[i]) > 4e-7f * std::fmax(a[i], b[i]);
    return differing;
}

void test_hull_and_mesh_render_as_the_box() {
    opx_shape box = placed(OPX_SHAPE_BOX, 2.25);
    box.size[0] = 0.6, box.size[1] = 0.4, box.size[2] = 0.5;
    opx_shape hull = OPX_SHAPE_INIT, mesh = OPX_SHAPE_INIT;
    hull.kind = OPX_SHAPE_CONVEX, mesh.kind = OPX_SHAPE_MESH;
    hull.vertices = mesh.vertices = &kCube[0][0];
    hull.vertex_count = mesh.vertex_count = 8;
    mesh.indices = &kCubeTriangles[0][0];
    mesh.triangle_count = 12;
    render::Camera camera = render::kinect_camera(OPX_POSE_IDENTITY);
    camera.pose.position[0] = 0.13, camera.pose.position[1] = -0.07;
    std::vector<float> images[3];
    const opx_shape *shapes[3] = {&box, &hull, &mesh};
    for (int i = 0; i < 3; ++i) {
        opx_linkset *robot = one_shape(*shapes[i]);
        images[i] = render::render_depth(robot, camera);
        opx_linkset_destroy(robot);
    }
    size_t covered = 0;
    for (float d : images[0]) covered += d > 0.0f;
    const size_t hull_off = differing_pixels(images[0], images[1]), mesh_off = differing_pixels(images[0], images[2]);
    std::printf("box covers %zu pixels; the hull differs in %zu, the closed mesh in %zu (edge pixels)\n", covered,
                hull_off, mesh_off);
    CHECK(covered > 10000, "box covers %zu pixels", covered);
    CHECK(hull_off <= 4 && mesh_off <= 4, "hull %zu, mesh %zu pixels differ", hull_off, mesh_off);
}

void test_attached_objects_are_seen() {
    opx_shape box = placed(OPX_SHAPE_BOX, 0.0);
    box.size[0] = box.size[1] = box.size[2] = 0.1;
    opx_linkset *robot = one_shape(box);  // the link's box at the origin, behind the camera below
    opx_shape ball = placed(OPX_SHAPE_SPHERE, 0.5);
    ball.radius = 0.1;
    opx_pose object = OPX_POSE_IDENTITY;
    object.position[2] = 1.0;  // ball at z = 1.5 in the map
    opx_linkset_attach_object(robot, 0, "ball", &ball, 1, &object, nullptr, 0, nullptr);
    render::Camera camera = axis_camera();
    camera.pose.position[2] = 0.2;
    const float depth = render::render_depth(robot, camera)[240 * camera.width + 320];
    CHECK(std::fabs(depth - 1.2f) < 1e-6f, "attached ball at %g", depth);
    opx_linkset_destroy(robot);
}

void test_nearer_depth() {
    const std::vector<float> a = {0.0f, 1.0f, 2.0f, 0.0f}, b = {0.0f, 0.0f, 1.5f, 3.0f};
    const std::vector<float> n = render::nearer_depth(a, b);
    CHECK(n[0] == 0.0f && n[1] == 1.0f && n[2] == 1.5f && n[3] == 3.0f, "nearer_depth");
}

// Each configuration shows an arm in front of the real scene.
void test_pr2_scenes() {
    const std::string dir = render::data_dir();
    const std::string missing = render::missing_pr2_data(dir);
    if (!missing.empty()) {
        const char *required = std::getenv("OPX_REQUIRE_DATA");
        CHECK(required == nullptr || std::string(required) != "1", "the PR2 scenes need %s and OPX_REQUIRE_DATA=1",
              missing.c_str());
        std::printf("PR2 scenes skipped: %s not found (set OPX_DATA_DIR)\n", missing.c_str());
        return;
    }
    for (int pose = 0; pose < render::pr2_arm_pose_count(); ++pose) {
        render::Pr2Scene scene = render::make_pr2_scene(dir, pose);
        size_t robot = 0, in_front = 0, near = 0;
        for (size_t i = 0; i < scene.composite.size(); ++i) {
            const float r = scene.robot_depth[i], behind = scene.real_depth[i] - r;
            robot += r > 0.0f;
            in_front += r > 0.0f && scene.composite[i] == r;
            near += r > 0.0f && behind >= 0.0f && behind < 0.02f;  // the scene within 2 cm behind the arm
        }
        std::printf("PR2 arm pose %d: %zu robot pixels, %zu in front of the scene, %zu with the scene less than "
                    "2 cm behind; camera at (%.3f %.3f %.3f)\n", pose, robot, in_front, near,
                    scene.camera.pose.position[0], scene.camera.pose.position[1], scene.camera.pose.position[2]);
        CHECK(in_front > 5000, "arm pose %d: only %zu robot pixels in front", pose, in_front);
        CHECK(near > 50, "arm pose %d: only %zu pixels with the scene near the arm", pose, near);
        render::destroy(scene);
    }
}

}  // namespace

int main() {
    test_primitives_on_the_axis();
    test_sphere_off_the_axis();
    test_hull_and_mesh_render_as_the_box();
    test_attached_objects_are_seen();
    test_nearer_depth();
    test_pr2_scenes();
    if (g_failures > 0) std::printf("%d checks failed\n", g_failures);
    return g_failures == 0 ? 0 : 1;
}
