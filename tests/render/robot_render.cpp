#include "robot_render.hpp"

#include "render_solids.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace render {
namespace {

// Surfaces nearer the camera than this (optical z, metres) are not seen:
// the near plane lets a solid around the camera (its housing) cover only
// the pixels its part beyond the plane projects to.
constexpr double kNearDepth = 1e-4;

// The pixels a convex solid can cover: the rectangle around the projected
// hull of its corners cut at the near plane (a margin of a pixel).
struct PixelRect {
    size_t u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // [u0, u1) x [v0, v1)
};

// The corners (camera frame) of the hull's part beyond the near plane:
// the corners there and where edges between corners cross the plane.
std::vector<Vec3> beyond_near_plane(const std::vector<Vec3> &corners) {
    std::vector<Vec3> out;
    for (const Vec3 &p : corners)
        if (p.z() >= kNearDepth) out.push_back(p);
    for (const Vec3 &p : corners)
        for (const Vec3 &q : corners)
            if (p.z() >= kNearDepth && q.z() < kNearDepth)
                out.push_back(p + (kNearDepth - p.z()) / (q.z() - p.z()) * (q - p));
    return out;
}

PixelRect covered_pixels(const Camera &camera, const Eigen::Isometry3d &camera_from_map, const Vec3 *corners,
                         size_t count) {
    std::vector<Vec3> local(count);
    for (size_t i = 0; i < count; ++i) local[i] = camera_from_map * corners[i];
    double lo_u = kNoHit, hi_u = -kNoHit, lo_v = kNoHit, hi_v = -kNoHit;
    for (const Vec3 &p : beyond_near_plane(local)) {
        const double u = camera.fx * p.x() / p.z() + camera.cx, v = camera.fy * p.y() / p.z() + camera.cy;
        lo_u = std::min(lo_u, u), hi_u = std::max(hi_u, u), lo_v = std::min(lo_v, v), hi_v = std::max(hi_v, v);
    }
    if (!(lo_u <= hi_u)) return PixelRect{};  // wholly before the near plane
    const auto clamp = [](double x, size_t n) {
        return static_cast<size_t>(std::clamp(x, 0.0, static_cast<double>(n)));
    };
    return PixelRect{clamp(std::floor(lo_u) - 1.0, camera.width), clamp(std::ceil(hi_u) + 2.0, camera.width),
                     clamp(std::floor(lo_v) - 1.0, camera.height), clamp(std::ceil(hi_v) + 2.0, camera.height)};
}

// Keeps the nearest hit per pixel over the rectangle's rays.
template <class Hit>
void trace(const Camera &camera, const Eigen::Isometry3d &map_from_camera, const PixelRect &rect,
           std::vector<double> &nearest, Hit &&hit) {
    const Vec3 origin = map_from_camera.translation();
    for (size_t v = rect.v0; v < rect.v1; ++v)
        for (size_t u = rect.u0; u < rect.u1; ++u) {
            const Vec3 dir = map_from_camera.linear() *
                             Vec3((static_cast<double>(u) - camera.cx) / camera.fx,
                                  (static_cast<double>(v) - camera.cy) / camera.fy, 1.0);
            double &best = nearest[v * camera.width + u];
            const double t = hit(origin, dir);
            if (t >= kNearDepth) best = std::min(best, t);
        }
}

}  // namespace

Camera kinect_camera(const opx_pose &pose) {
    Camera camera;
    camera.pose = pose;
    return camera;
}

opx_pose look_at(const double eye[3], const double target[3], const double up[3]) {
    const Vec3 z = (Vec3(target[0], target[1], target[2]) - Vec3(eye[0], eye[1], eye[2])).normalized();
    const Vec3 x = z.cross(Vec3(up[0], up[1], up[2])).normalized();  // right = forward x up
    const Vec3 y = z.cross(x);                                              // down
    Eigen::Matrix3d rotation;
    rotation << x, y, z;
    const Eigen::Quaterniond q(rotation);
    opx_pose pose = OPX_POSE_IDENTITY;
    for (int a = 0; a < 3; ++a) pose.position[a] = eye[a];
    pose.orientation[0] = q.x(), pose.orientation[1] = q.y(), pose.orientation[2] = q.z(), pose.orientation[3] = q.w();
    return pose;
}

std::vector<float> render_depth(const opx_linkset *robot, const Camera &camera) {
    const RobotSolids scene = read_robot_solids(robot);
    const Eigen::Isometry3d map_from_camera = isometry(camera.pose), camera_from_map = map_from_camera.inverse();
    std::vector<double> nearest(camera.width * camera.height, kNoHit);
    for (const Primitive &solid : scene.primitives) {
        const PixelRect rect = covered_pixels(camera, camera_from_map, solid.corners.data(), solid.corners.size());
        trace(camera, map_from_camera, rect, nearest,
              [&](const Vec3 &o, const Vec3 &d) { return first_hit(solid, o, d); });
    }
    for (const Mesh &mesh : scene.meshes)
        for (const Triangle &triangle : mesh.triangles) {
            const PixelRect rect = covered_pixels(camera, camera_from_map, &triangle.a, 3);
            trace(camera, map_from_camera, rect, nearest,
                  [&](const Vec3 &o, const Vec3 &d) { return triangle_hit(triangle, o, d); });
        }
    // The ray's direction has optical z 1: its parameter is the depth.
    std::vector<float> depth(nearest.size(), 0.0f);
    for (size_t i = 0; i < nearest.size(); ++i)
        if (nearest[i] < kNoHit) depth[i] = static_cast<float>(nearest[i]);
    return depth;
}

std::vector<float> nearer_depth(const std::vector<float> &a, const std::vector<float> &b) {
    if (a.size() != b.size()) throw std::invalid_argument("nearer_depth: images of different sizes");
    std::vector<float> out(a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i] > 0.0f && b[i] > 0.0f) out[i] = std::min(a[i], b[i]);
        else out[i] = a[i] > 0.0f ? a[i] : b[i];
    }
    return out;
}

void back_project(const Camera &camera, size_t u, size_t v, double depth, double out_xyz[3]) {
    out_xyz[0] = (static_cast<double>(u) - camera.cx) * depth / camera.fx;
    out_xyz[1] = (static_cast<double>(v) - camera.cy) * depth / camera.fy;
    out_xyz[2] = depth;
}

}  // namespace render
