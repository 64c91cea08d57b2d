#include "oracle_random.hpp"

#include <cmath>

namespace oracle {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A linear map with singular values in [0.5, 1.5]: keeps a hull's faces.
Mat3 random_linear_map(Rng &rng) {
    const Vec3 scales(rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5));
    return random_rotation(rng).toRotationMatrix() * scales.asDiagonal() *
           random_rotation(rng).toRotationMatrix();
}

ShapeSpec random_tetrahedron(Rng &rng, double scale) {
    ShapeSpec s;
    s.kind = OPX_SHAPE_CONVEX;
    const Vec3 half = Vec3::Constant(0.5 * scale);
    for (;;) {
        s.vertices.clear();
        for (int i = 0; i < 4; ++i) s.vertices.push_back(rng.point(-half, half));
        const double volume = std::abs((s.vertices[1] - s.vertices[0])
                                           .cross(s.vertices[2] - s.vertices[0])
                                           .dot(s.vertices[3] - s.vertices[0])) / 6.0;
        if (volume > 0.002 * scale * scale * scale) break;  // not too flat
    }
    s.hull_faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    return s;
}

// Vertices on the six half-axes (+x -x +y -y +z -z); one face per octant.
ShapeSpec random_octahedron(Rng &rng, double scale) {
    ShapeSpec s;
    s.kind = OPX_SHAPE_CONVEX;
    const Mat3 map = random_linear_map(rng);
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0})
            s.vertices.push_back(map * (Vec3::Unit(axis) * sign * rng.uniform(0.15, 0.33) * scale));
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5}) s.hull_faces.push_back({x, y, z});
    return s;
}

void add_interior_points(Rng &rng, ShapeSpec &s) {
    s.hull_vertex_count = s.vertices.size();
    const int extra = rng.integer(0, 3);
    for (int i = 0; i < extra; ++i) {
        Vec3 point = Vec3::Zero();
        double total = 0.0;
        for (size_t v = 0; v < s.hull_vertex_count; ++v) {
            const double weight = rng.uniform(0.05, 1.0);
            point += weight * s.vertices[v];
            total += weight;
        }
        s.vertices.push_back(point / total);
    }
}

ShapeSpec triangle_soup(Rng &rng, double scale) {
    ShapeSpec s;
    s.kind = OPX_SHAPE_MESH;
    const Vec3 half = Vec3::Constant(0.5 * scale);
    const int count = rng.integer(1, 8);
    for (int t = 0; t < count; ++t) {
        const uint32_t first = uint32_t(s.vertices.size());
        for (int k = 0; k < 3; ++k) s.vertices.push_back(rng.point(-half, half));
        s.triangles.push_back({first, first + 1, first + 2});
        // Now and then a degenerate one, as real meshes have: two corners
        // shared (a segment), or a corner on the opposite edge (collinear).
        const double draw = rng.uniform(0.0, 1.0);
        if (draw < 0.05) s.triangles.back()[2] = first + 1;
        else if (draw < 0.1) s.vertices.back() = s.vertices[first] + 0.25 * (s.vertices[first + 1] - s.vertices[first]);
    }
    return s;
}

}  // namespace

Eigen::Quaterniond random_rotation(Rng &rng) {
    const double u1 = rng.uniform(0.0, 1.0), u2 = rng.uniform(0.0, 2.0 * kPi), u3 = rng.uniform(0.0, 2.0 * kPi);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return Eigen::Quaterniond(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
}

opx_pose random_pose(Rng &rng, const Vec3 &low, const Vec3 &high) {
    const Vec3 p = rng.point(low, high);
    const Eigen::Quaterniond q = random_rotation(rng);
    // Not always unit: the library normalises, as the oracle does.
    const double scale = rng.chance(0.3) ? rng.uniform(0.5, 2.0) : 1.0;
    return {{p.x(), p.y(), p.z()}, {scale * q.x(), scale * q.y(), scale * q.z(), scale * q.w()}};
}

// A hull of 1, 2 or 3 points: a point, a segment, a triangle (accepted by
// the library; no faces).
ShapeSpec degenerate_hull(Rng &rng, double scale) {
    ShapeSpec s;
    s.kind = OPX_SHAPE_CONVEX;
    const Vec3 half = Vec3::Constant(0.5 * scale);
    for (int i = rng.integer(1, 3); i > 0; --i) s.vertices.push_back(rng.point(-half, half));
    return s;
}

ShapeSpec random_convex(Rng &rng, double scale) {
    const double draw = rng.uniform(0.0, 1.0);
    ShapeSpec s = draw < 0.1   ? degenerate_hull(rng, scale)
                  : draw < 0.55 ? random_tetrahedron(rng, scale)
                                : random_octahedron(rng, scale);
    add_interior_points(rng, s);
    return s;
}

ShapeSpec random_mesh(Rng &rng, double scale) {
    if (rng.chance(0.5)) return triangle_soup(rng, scale);
    // The closed surface of a hull: a cell inside it touches no triangle.
    ShapeSpec hull = rng.chance(0.5) ? random_tetrahedron(rng, scale) : random_octahedron(rng, scale);
    ShapeSpec s;
    s.kind = OPX_SHAPE_MESH;
    s.vertices = hull.vertices;
    for (const auto &f : hull.hull_faces) s.triangles.push_back({uint32_t(f[0]), uint32_t(f[1]), uint32_t(f[2])});
    return s;
}

ShapeSpec random_shape(Rng &rng, int32_t kind, double scale) {
    ShapeSpec s;
    switch (kind) {
    case OPX_SHAPE_CONVEX: s = random_convex(rng, scale); break;
    case OPX_SHAPE_MESH: s = random_mesh(rng, scale); break;
    case OPX_SHAPE_BOX:
        s.size = Vec3(rng.uniform(0.01, 1.0), rng.uniform(0.01, 1.0), rng.uniform(0.01, 1.0)) * scale;
        break;
    default:  // sphere, cylinder, capsule
        s.radius = rng.uniform(0.005, 0.5) * scale;
        s.length = rng.uniform(0.01, 1.0) * scale;
        if (kind == OPX_SHAPE_CAPSULE && rng.chance(0.1)) s.length = 0.0;  // a sphere
        break;
    }
    s.kind = kind;
    if (rng.chance(0.7)) s.pose = random_pose(rng, Vec3::Constant(-0.3 * scale), Vec3::Constant(0.3 * scale));
    return s;
}

RobotSpec random_robot(Rng &rng, const RobotOptions &options) {
    RobotSpec robot;
    const int links = rng.integer(options.min_links, options.max_links);
    for (int i = 0; i < links; ++i) {
        LinkSpec link;
        link.name = "link" + std::to_string(i);
        const int shapes = rng.integer(1, options.max_shapes_per_link);
        for (int j = 0; j < shapes; ++j) {
            // Cycle through the kinds so every robot mixes them.
            const int32_t kind = 1 + (i * options.max_shapes_per_link + j + rng.integer(0, 5)) % 6;
            link.shapes.push_back(random_shape(rng, kind, rng.uniform(options.min_scale, options.max_scale)));
        }
        robot.links.push_back(std::move(link));
    }
    return robot;
}

void randomize_state(Rng &rng, RobotSpec &robot, const RobotOptions &options, const Vec3 &low,
                     const Vec3 &high) {
    robot.global_padding = rng.chance(0.5) ? rng.uniform(0.0, options.max_padding) : 0.0;
    for (LinkSpec &link : robot.links) {
        link.pose = random_pose(rng, low, high);
        link.padding = rng.chance(0.5) ? rng.uniform(0.0, options.max_padding) : 0.0;
        link.enabled = !rng.chance(options.disabled_fraction);
    }
}

}  // namespace oracle
