#include "extent_scenes.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>

#include <cmath>
#include <random>

namespace extents_bench {
namespace {

using Eigen::Vector3d;

class Draw {
public:
    explicit Draw(uint64_t seed) : rng_(seed) {}
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

private:
    std::mt19937_64 rng_;
};

SceneObject box(const Vector3d &size, const Vector3d &center, double yaw = 0.0) {
    SceneObject o;
    o.kind = SceneObject::kBox;
    o.size = size;
    o.pose = Eigen::Translation3d(center) * Eigen::AngleAxisd(yaw, Vector3d::UnitZ());
    return o;
}

SceneObject cylinder(double radius, double length, const Vector3d &center) {
    SceneObject o;
    o.kind = SceneObject::kCylinder;
    o.radius = radius, o.length = length;
    o.pose = Eigen::Translation3d(center) * Eigen::Isometry3d::Identity();
    return o;
}

// Objects standing on a surface at height `z`, x in [x0, x1], y in [y0, y1],
// no taller than `max_height`.
void add_items(Draw &draw, int count, double x0, double x1, double y0, double y1, double z, double max_height,
               Scene &scene) {
    for (int i = 0; i < count; ++i) {
        const double x = draw.uniform(x0 + 0.06, x1 - 0.06), y = draw.uniform(y0 + 0.06, y1 - 0.06);
        if (draw.chance(0.5)) {
            const Vector3d size(draw.uniform(0.04, 0.12), draw.uniform(0.04, 0.12), draw.uniform(0.04, max_height));
            scene.objects.push_back(box(size, Vector3d(x, y, z + 0.5 * size.z()), draw.uniform(0.0, M_PI)));
        } else {
            const double height = draw.uniform(0.06, max_height);
            scene.objects.push_back(cylinder(draw.uniform(0.02, 0.05), height, Vector3d(x, y, z + 0.5 * height)));
        }
    }
}

// Points on a rectangle: `origin` plus s u + t v for s in [0, |u|], t in [0, |v|].
void sample_rectangle(const Vector3d &origin, const Vector3d &u, const Vector3d &v, double spacing,
                      std::vector<double> &out) {
    const int nu = std::max(1, int(std::ceil(u.norm() / spacing))), nv = std::max(1, int(std::ceil(v.norm() / spacing)));
    for (int i = 0; i <= nu; ++i)
        for (int j = 0; j <= nv; ++j) {
            const Vector3d p = origin + u * (double(i) / nu) + v * (double(j) / nv);
            out.insert(out.end(), {p.x(), p.y(), p.z()});
        }
}

void sample_box(const SceneObject &o, double spacing, std::vector<double> &out) {
    const Vector3d h = 0.5 * o.size;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = -1; side <= 1; side += 2) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            Vector3d corner = -h, u = Vector3d::Zero(), v = Vector3d::Zero();
            corner[axis] = side * h[axis];
            u[a] = o.size[a], v[b] = o.size[b];
            sample_rectangle(o.pose * corner, o.pose.linear() * u, o.pose.linear() * v, spacing, out);
        }
}

void sample_cylinder(const SceneObject &o, double spacing, std::vector<double> &out) {
    const int around = std::max(8, int(std::ceil(2.0 * M_PI * o.radius / spacing)));
    const int along = std::max(1, int(std::ceil(o.length / spacing)));
    auto add = [&](const Vector3d &local) {
        const Vector3d p = o.pose * local;
        out.insert(out.end(), {p.x(), p.y(), p.z()});
    };
    for (int k = 0; k < around; ++k) {
        const double angle = 2.0 * M_PI * k / around;
        for (int j = 0; j <= along; ++j)
            add(Vector3d(o.radius * std::cos(angle), o.radius * std::sin(angle), -0.5 * o.length + o.length * j / along));
    }
    const int rings = std::max(1, int(std::ceil(o.radius / spacing)));
    for (int r = 0; r <= rings; ++r) {
        const double radius = o.radius * r / rings;
        const int count = std::max(1, int(std::ceil(2.0 * M_PI * radius / spacing)));
        for (int k = 0; k < count; ++k) {
            const double angle = 2.0 * M_PI * k / count;
            for (int side = -1; side <= 1; side += 2)
                add(Vector3d(radius * std::cos(angle), radius * std::sin(angle), side * 0.5 * o.length));
        }
    }
}

}  // namespace

Scene tabletop_scene(uint64_t seed) {
    Draw draw(seed);
    Scene scene;
    scene.name = "tabletop";
    const double top = draw.uniform(0.0, 0.2), near = draw.uniform(0.25, 0.35), far = near + 0.8;
    scene.objects.push_back(box(Vector3d(far - near, 1.2, 0.04), Vector3d(0.5 * (near + far), 0.0, top - 0.02)));
    for (int leg = 0; leg < 4; ++leg) {
        const double x = leg & 1 ? far - 0.05 : near + 0.05, y = leg & 2 ? 0.55 : -0.55;
        scene.objects.push_back(box(Vector3d(0.05, 0.05, 0.6), Vector3d(x, y, top - 0.34)));
    }
    add_items(draw, int(draw.uniform(3, 8)), near, far, -0.6, 0.6, top, 0.3, scene);
    return scene;
}

Scene shelf_scene(uint64_t seed) {
    Draw draw(seed);
    Scene scene;
    scene.name = "shelf";
    const double front = draw.uniform(0.4, 0.5), depth = 0.35, back = front + depth, width = 1.0;
    const double boards[3] = {draw.uniform(-0.3, -0.2), draw.uniform(0.15, 0.25), draw.uniform(0.55, 0.65)};
    const double bottom = boards[0] - 0.02, top = boards[2] + 0.4;
    for (int side = -1; side <= 1; side += 2)
        scene.objects.push_back(
            box(Vector3d(depth, 0.02, top - bottom), Vector3d(front + 0.5 * depth, side * 0.5 * width, 0.5 * (top + bottom))));
    scene.objects.push_back(box(Vector3d(0.02, width, top - bottom), Vector3d(back, 0.0, 0.5 * (top + bottom))));
    for (double board : boards) {
        scene.objects.push_back(box(Vector3d(depth, width, 0.02), Vector3d(front + 0.5 * depth, 0.0, board - 0.01)));
        add_items(draw, int(draw.uniform(1, 4)), front, back, -0.5 * width, 0.5 * width, board, 0.25, scene);
    }
    return scene;
}

std::vector<double> sample_surfaces(const Scene &scene, double spacing) {
    std::vector<double> out;
    for (const SceneObject &o : scene.objects) {
        if (o.kind == SceneObject::kBox) sample_box(o, spacing, out);
        else sample_cylinder(o, spacing, out);
    }
    return out;
}

FclScene fcl_scene(const Scene &scene) {
    FclScene out;
    out.manager = std::make_unique<paper_tables::FclManager>();
    for (const SceneObject &o : scene.objects) {
        std::shared_ptr<fcl::CollisionGeometryd> geometry;
        if (o.kind == SceneObject::kBox) geometry = std::make_shared<fcl::Boxd>(o.size);
        else geometry = std::make_shared<fcl::Cylinderd>(o.radius, o.length);
        out.objects.push_back(std::make_unique<fcl::CollisionObjectd>(geometry, o.pose.linear(), o.pose.translation()));
        out.objects.back()->computeAABB();
        out.manager->registerObject(out.objects.back().get());
    }
    out.manager->setup();
    return out;
}

}  // namespace extents_bench
