#include "filter_scenes.hpp"

#include "render_solids.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace filter_oracle {
namespace {

using Iso = Eigen::Isometry3d;

void check(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

opx_pose pose_of(const Iso &t) {
    const Eigen::Quaterniond q(t.linear());
    return opx_pose{{t.translation().x(), t.translation().y(), t.translation().z()}, {q.x(), q.y(), q.z(), q.w()}};
}

Iso translation(double x, double y, double z) { return Iso(Eigen::Translation3d(x, y, z)); }
Iso about(const Vec3 &axis, double angle) { return Iso(Eigen::AngleAxisd(angle, axis)); }

opx_shape shape_along_x(int32_t kind, double offset) {
    opx_shape s = OPX_SHAPE_INIT;
    s.kind = kind;
    s.pose = pose_of(translation(offset, 0, 0) * about(Vec3::UnitY(), M_PI / 2));  // z onto x
    return s;
}

// The L-shaped prism (two wings along x and y, 4 cm thick): six outline
// points, its outline fanned from the reflex corner (3) on top and bottom.
const double kOutline[6][2] = {{0, -0.05}, {0.1, -0.05}, {0.1, -0.02}, {0.03, -0.02}, {0.03, 0.05}, {0, 0.05}};
std::vector<double> g_hand_vertices;
std::vector<uint32_t> g_hand_indices;

void build_hand_mesh() {
    if (!g_hand_vertices.empty()) return;
    for (int level = 0; level < 2; ++level)
        for (const auto &p : kOutline)
            g_hand_vertices.insert(g_hand_vertices.end(), {p[0], p[1], level ? 0.02 : -0.02});
    const uint32_t fan[4][3] = {{3, 4, 5}, {3, 5, 0}, {3, 0, 1}, {3, 1, 2}};
    for (const auto &t : fan) {
        g_hand_indices.insert(g_hand_indices.end(), {t[0] + 6, t[1] + 6, t[2] + 6});  // top, counter-clockwise
        g_hand_indices.insert(g_hand_indices.end(), {t[0], t[2], t[1]});              // bottom, reversed
    }
    for (uint32_t i = 0; i < 6; ++i) {
        const uint32_t j = (i + 1) % 6;
        g_hand_indices.insert(g_hand_indices.end(), {i, j, j + 6, i, j + 6, i + 6});
    }
}

const double kFinger[4][3] = {{0, -0.015, -0.015}, {0, 0.015, -0.015}, {0, 0, 0.02}, {0.06, 0, 0}};
const uint32_t kFingerFaces[3][3] = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};  // the face 0 1 2 left open
const double kWrist[13][3] = {{0, 0.04, 0},      {0, 0.02, 0.0346},    {0, -0.02, 0.0346}, {0, -0.04, 0},
                              {0, -0.02, -0.0346}, {0, 0.02, -0.0346}, {0.06, 0.04, 0},    {0.06, 0.02, 0.0346},
                              {0.06, -0.02, 0.0346}, {0.06, -0.04, 0}, {0.06, -0.02, -0.0346},
                              {0.06, 0.02, -0.0346}, {0.03, 0, 0}};  // a hexagonal prism and an inner point

void add_shapes(opx_linkset *arm) {
    for (uint32_t link = 0; link < 6; ++link) {
        const opx_shape s = arm_link_shape(static_cast<int>(link));
        check(opx_linkset_add_shape(arm, link, &s, nullptr), "opx_linkset_add_shape");
    }
}

// Shoulder yaw, then the pitches of shoulder, elbow and wrist (radians).
const double kConfigurations[][4] = {{0.2, 0.3, 0.6, 0.5}, {-0.4, 0.1, 1.0, 0.4}, {0.8, 0.6, 0.3, 0.9}};

std::vector<opx_pose> link_poses(int configuration) {
    const double *q = kConfigurations[configuration];
    const Iso shoulder = translation(0, 0, 0.6) * about(Vec3::UnitZ(), q[0]);
    const Iso upper = shoulder * about(Vec3::UnitY(), q[1]);
    const Iso fore = upper * translation(0.3, 0, 0) * about(Vec3::UnitY(), q[2]);
    const Iso wrist = fore * translation(0.28, 0, 0) * about(Vec3::UnitY(), q[3]);
    const Iso hand = wrist * translation(0.06, 0, 0);
    const Iso finger = hand * translation(0.1, -0.035, 0);
    return {pose_of(shoulder), pose_of(upper), pose_of(fore), pose_of(wrist), pose_of(hand), pose_of(finger)};
}

// The lowest z of any solid's corners or triangles.
double lowest_z(const opx_linkset *robot) {
    const render::RobotSolids solids = render::read_robot_solids(robot);
    double low = INFINITY;
    for (const render::Primitive &p : solids.primitives)
        for (const Vec3 &c : p.corners) low = std::min(low, c.z());
    for (const render::Mesh &m : solids.meshes)
        for (const render::Triangle &t : m.triangles) low = std::min({low, t.a.z(), t.b.z(), t.c.z()});
    return low;
}

}  // namespace

opx_shape arm_link_shape(int link) {
    opx_shape s = OPX_SHAPE_INIT;
    switch (link) {
    case 0: s.kind = OPX_SHAPE_CYLINDER, s.radius = 0.06, s.length = 0.12; break;
    case 1: s = shape_along_x(OPX_SHAPE_CAPSULE, 0.15), s.radius = 0.045, s.length = 0.3; break;
    case 2:
        s.kind = OPX_SHAPE_BOX, s.pose.position[0] = 0.14;
        s.size[0] = 0.28, s.size[1] = 0.07, s.size[2] = 0.06;
        break;
    case 3: s.kind = OPX_SHAPE_CONVEX, s.vertices = &kWrist[0][0], s.vertex_count = 13; break;
    case 4:
        build_hand_mesh();
        s.kind = OPX_SHAPE_MESH, s.vertices = g_hand_vertices.data(), s.vertex_count = 12;
        s.indices = g_hand_indices.data(), s.triangle_count = g_hand_indices.size() / 3;
        break;
    default:
        s.kind = OPX_SHAPE_MESH, s.vertices = &kFinger[0][0], s.vertex_count = 4;
        s.indices = &kFingerFaces[0][0], s.triangle_count = 3;
        break;
    }
    return s;
}

int arm_configuration_count() { return static_cast<int>(sizeof kConfigurations / sizeof kConfigurations[0]); }

opx_linkset *make_arm(int configuration) {
    opx_linkset *arm = nullptr;
    check(opx_linkset_create(&arm), "opx_linkset_create");
    for (const char *name : {"shoulder", "upper", "fore", "wrist", "hand", "finger"})
        check(opx_linkset_add_link(arm, name, nullptr), "opx_linkset_add_link");
    add_shapes(arm);
    opx_shape box = OPX_SHAPE_INIT;
    box.kind = OPX_SHAPE_BOX, box.size[0] = box.size[1] = box.size[2] = 0.04;
    const opx_pose held = pose_of(translation(0.13, 0.03, 0));
    check(opx_linkset_attach_object(arm, 4, "part", &box, 1, &held, nullptr, 0, nullptr), "attach");
    const std::vector<opx_pose> poses = link_poses(configuration);
    check(opx_linkset_set_poses(arm, poses.data(), poses.size(), 0), "opx_linkset_set_poses");
    return arm;
}

opx_linkset *make_environment(const opx_linkset *arm) {
    opx_linkset *world = nullptr;
    check(opx_linkset_create(&world), "opx_linkset_create");
    check(opx_linkset_add_link(world, "scene", nullptr), "opx_linkset_add_link");
    const double top = lowest_z(arm) + 0.01;
    opx_shape table = OPX_SHAPE_INIT, wall = OPX_SHAPE_INIT;
    table.kind = wall.kind = OPX_SHAPE_BOX;
    table.size[0] = table.size[1] = 3.0, table.size[2] = 0.1;
    table.pose.position[2] = top - 0.05;
    wall.size[0] = 0.1, wall.size[1] = 3.0, wall.size[2] = 2.0;
    wall.pose.position[0] = 1.3, wall.pose.position[2] = top + 1.0;
    check(opx_linkset_add_shape(world, 0, &table, nullptr), "table");
    check(opx_linkset_add_shape(world, 0, &wall, nullptr), "wall");
    const opx_pose identity = OPX_POSE_IDENTITY;
    check(opx_linkset_set_poses(world, &identity, 1, 0), "opx_linkset_set_poses");
    return world;
}

std::vector<render::Camera> arm_cameras() {
    // The last eye is inside the shoulder's cylinder: a solid holding the
    // sensor shadows nothing.
    const double eyes[4][3] = {{-0.5, -0.8, 1.2}, {0.3, -0.9, 0.9}, {-0.6, 0.7, 1.0}, {0.0, 0.0, 0.62}};
    const double target[3] = {0.4, 0.0, 0.45}, up[3] = {0.0, 0.0, 1.0};
    std::vector<render::Camera> cameras;
    for (const auto &eye : eyes) {
        render::Camera c;
        c.width = 320, c.height = 240, c.fx = c.fy = 262.5, c.cx = 159.5, c.cy = 119.5;
        c.pose = render::look_at(eye, target, up);
        cameras.push_back(c);
    }
    return cameras;
}

RenderedFrame render_frame(const std::string &label, const opx_linkset *robot, const opx_linkset *environment,
                           const render::Camera &camera) {
    RenderedFrame f;
    f.label = label, f.camera = camera;
    f.robot_depth = render::render_depth(robot, camera);
    f.composite = render::nearer_depth(render::render_depth(environment, camera), f.robot_depth);
    return f;
}

FramePoints frame_points(const RenderedFrame &rendered) {
    const render::Camera &c = rendered.camera;
    const Iso map_from_camera = render::isometry(c.pose);
    FramePoints out;
    const Vec3 origin = map_from_camera.translation();
    out.frame.origin = octomap::point3d(float(origin.x()), float(origin.y()), float(origin.z()));
    for (size_t v = 0; v < c.height; ++v)
        for (size_t u = 0; u < c.width; ++u) {
            const float depth = rendered.composite[v * c.width + u];
            if (!(depth > 0.0f)) continue;
            Vec3 p;
            render::back_project(c, u, v, depth, p.data());
            p = map_from_camera * p;
            out.frame.points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
            out.robot_pixel.push_back(rendered.robot_depth[v * c.width + u] == depth);
        }
    return out;
}

}  // namespace filter_oracle
