#include "self_filter/mesh_solid.hpp"

#include "geometry/gjk.hpp"
#include "self_filter/ray_entry.hpp"
#include "self_filter/solid_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {
namespace {

// Relative margin below which a ray's crossing of a triangle is too close
// to an edge to count: the parity test then tries another direction.
constexpr double kGrazing = 1e-9;

// Directions tried in turn for the parity test: irregular, so that a
// mesh's axis-aligned edges and faces are never parallel to them.
const Vec3 kParityDirections[] = {Vec3(0.5773, 0.5717, 0.5829), Vec3(-0.3121, 0.8267, -0.4683),
                                  Vec3(0.7016, -0.2087, -0.6813), Vec3(-0.6421, -0.6091, 0.4657)};

// A median-split tree (AabbTree::build) is about log2 of its triangles
// deep; a walk keeps at most one pending node a level, as the narrow
// phase's walks of the same trees do.
constexpr int kStack = 64;

// Calls leaf(triangle) for the leaves whose box, grown by `margin`,
// passes `keep`.
template <class Keep, class Leaf>
void visit_leaves(const AabbTree &tree, double margin, Keep &&keep, Leaf &&leaf) {
    if (tree.empty()) return;
    int32_t stack[kStack];
    int depth = 0;
    stack[depth++] = tree.root();
    while (depth > 0) {
        const AabbTreeNode &node = tree.node(stack[--depth]);
        Aabb box = node.box;
        box.inflate(margin);
        if (!keep(box)) continue;
        if (node.is_leaf()) {
            leaf(node.item);
            continue;
        }
        stack[depth++] = node.right;
        stack[depth++] = node.left;
    }
}

// Möller and Trumbore's ray-triangle test.  Returns 1 for a crossing at t
// > 0, 0 for none, -1 when too close to call.
int crossing(const Convex &tri, const Vec3 &x, const Vec3 &dir) {
    const Vec3 e1 = tri.v[1] - tri.v[0], e2 = tri.v[2] - tri.v[0];
    const Vec3 p = dir.cross(e2);
    const double det = e1.dot(p);
    const double scale = e1.norm() * e2.norm();
    // Parallel to the triangle's plane: no crossing.  A ray in that plane
    // reaches the triangles around it across their edges, where they call
    // it too close.
    if (std::fabs(det) <= kGrazing * scale) return 0;
    const double inv = 1.0 / det;
    const Vec3 s = x - tri.v[0];
    const double u = s.dot(p) * inv;
    const Vec3 q = s.cross(e1);
    const double v = dir.dot(q) * inv;
    const double t = e2.dot(q) * inv;
    const double margin = kGrazing;
    if (u < -margin || v < -margin || u + v > 1.0 + margin || t < -margin) return 0;
    if (u < margin || v < margin || u + v > 1.0 - margin || t < margin) return -1;
    return 1;
}

}  // namespace

bool MeshSolid::near_surface(const Vec3 &x) const {
    bool found = false;
    visit_leaves(
        mesh_.mesh_tree, radius_,
        [&](const Aabb &box) { return !found && box.squared_distance(Aabb{x, x}) == 0.0; },
        [&](int32_t item) {
            if (grown_core_holds(mesh_.triangle(item), radius_, x)) found = true;
        });
    return found;
}

bool MeshSolid::count_crossings(const Vec3 &x, const Vec3 &dir, int &crossings) const {
    crossings = 0;
    bool clear = true;
    const double far = std::numeric_limits<double>::infinity();
    visit_leaves(
        mesh_.mesh_tree, 0.0,
        [&](const Aabb &box) {
            double t0 = 0.0, t1 = far;
            return clear && segment_in_box(box, x, dir, t0, t1);
        },
        [&](int32_t item) {
            const int c = crossing(mesh_.triangle(item), x, dir);
            if (c < 0) clear = false;
            crossings += c > 0 ? 1 : 0;
        });
    return clear;
}

bool MeshSolid::inside(const Vec3 &x) const {
    if (mesh_.mesh_tree.empty() || mesh_.mesh_tree.node(mesh_.mesh_tree.root()).box.squared_distance(Aabb{x, x}) > 0.0)
        return false;
    // The first ray that passes clear of every edge and vertex decides;
    // a point all of whose rays graze one is taken as outside (it would
    // need four rays each meeting an edge within 1e-9 of its length).
    for (const Vec3 &dir : kParityDirections) {
        int crossings = 0;
        if (count_crossings(x, dir, crossings)) return crossings % 2 == 1;
    }
    return false;
}

double grown_faces_entry(const MeshFaces &faces, const Convex &pose, double radius, const Vec3 &origin,
                         const Vec3 &dir, double t_max) {
    // In the shape frame, where the faces and the tree's boxes were made
    // once: a rigid motion of the ray keeps its parameter.
    if (faces.nodes.empty()) return -1.0;
    const Vec3 o = pose.axes.transpose() * (origin - pose.center);
    const Vec3 d = pose.axes.transpose() * dir;
    const double grown = radius + kEntryTouch;
    const RaySlabs slabs(o, d);
    double best = -1.0, limit = t_max;
    // Nodes nearer the sensor first, each with the parameter where the ray
    // enters its grown box: a hit found early shortens the ray for the rest.
    struct Pending {
        int32_t node;
        double t0;
    };
    Pending stack[kStack];
    int depth = 0;
    const auto push = [&](int32_t index) {
        double t0;
        if (slabs.enters(faces.nodes[index].box, grown, limit, t0)) stack[depth++] = Pending{index, t0};
    };
    push(0);
    while (depth > 0) {
        const Pending next = stack[--depth];
        if (next.t0 > limit) continue;
        const FaceNode &node = faces.nodes[next.node];
        if (node.is_leaf()) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                const double t = face_entry(faces.faces[i], grown, o, d, limit);
                if (t >= 0.0) best = t, limit = t;
            }
            continue;
        }
        const int before = depth;
        push(node.right);
        push(node.left);
        if (depth - before == 2 && stack[depth - 1].t0 > stack[depth - 2].t0) std::swap(stack[depth - 1], stack[depth - 2]);
    }
    return best;
}

bool MeshSolid::touches_box(const Aabb &box) const {
    bool touches = false;
    const Vec3 center = box.center(), half = box.half_extent();
    visit_leaves(
        mesh_.mesh_tree, 0.0, [&](const Aabb &node) { return !touches && node.overlaps(box); },
        [&](int32_t item) {
            const Convex t = mesh_.triangle(item);
            GjkQuery query;
            query.cell_center = center, query.cell_half = half, query.shape = &t;
            query.stop_above = 0.0;
            const GjkResult result = gjk_cell_distance(query);
            touches = result.intersecting || result.distance <= 0.0;
        });
    return touches;
}

}  // namespace octoprox
