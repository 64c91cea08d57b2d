#include "oracle_robot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace oracle {

void require_ok(opx_status status, const char *what) {
    if (status == OPX_OK) return;
    std::fprintf(stderr, "FAIL: %s: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    std::exit(1);
}

namespace {

// The vertices as the library receives them: packed, or 4 doubles apart.
std::vector<double> vertex_buffer(const ShapeSpec &spec, bool strided) {
    std::vector<double> buffer;
    for (const Vec3 &v : spec.vertices) {
        buffer.insert(buffer.end(), {v.x(), v.y(), v.z()});
        if (strided) buffer.push_back(std::nan(""));  // must be skipped
    }
    return buffer;
}

opx_shape library_shape(const ShapeSpec &spec, const std::vector<double> &vertices, bool strided) {
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = spec.kind;
    shape.pose = spec.pose;
    shape.radius = spec.radius;
    shape.length = spec.length;
    for (int k = 0; k < 3; ++k) shape.size[k] = spec.size[k];
    if (!spec.vertices.empty()) {
        shape.vertices = vertices.data();
        shape.vertex_count = spec.vertices.size();
        shape.vertex_stride = strided ? 4 * sizeof(double) : 0;
    }
    if (!spec.triangles.empty()) {
        shape.indices = spec.triangles.front().data();
        shape.triangle_count = spec.triangles.size();
    }
    return shape;
}

void grow(PlacedShape &placed, const Vec3 &p) {
    placed.bounds_min = placed.bounds_min.cwiseMin(p);
    placed.bounds_max = placed.bounds_max.cwiseMax(p);
}

// Bounds of the core, then grown by the inflation.
void set_bounds(PlacedShape &s) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    s.bounds_min = Vec3::Constant(kInf);
    s.bounds_max = Vec3::Constant(-kInf);
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: grow(s, s.point); break;
    case OPX_SHAPE_CAPSULE: grow(s, s.segment.a), grow(s, s.segment.b); break;
    case OPX_SHAPE_BOX:
        for (const Vec3 &c : box_corners(s.box)) grow(s, c);
        break;
    case OPX_SHAPE_CYLINDER: {
        // The rim circles' extent along world axis k is r * sqrt(1 - axis_k^2).
        const Vec3 axis = s.cylinder.axes.col(2);
        const Vec3 rim = (Vec3::Ones() - axis.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt() * s.cylinder.radius;
        const Vec3 reach = axis.cwiseAbs() * (0.5 * s.cylinder.length) + rim;
        grow(s, s.cylinder.center - reach), grow(s, s.cylinder.center + reach);
        break;
    }
    case OPX_SHAPE_CONVEX:
        for (const Vec3 &v : s.hull.vertices) grow(s, v);
        break;
    case OPX_SHAPE_MESH:
        for (const Triangle &t : s.triangles) grow(s, t.a), grow(s, t.b), grow(s, t.c);
        break;
    }
    s.bounds_min -= Vec3::Constant(s.inflation);
    s.bounds_max += Vec3::Constant(s.inflation);
}

PlacedShape place_shape(const ShapeSpec &spec, const Eigen::Isometry3d &link_pose, double padding) {
    const Eigen::Isometry3d frame = link_pose * isometry_of(spec.pose);
    const Mat3 axes = frame.linear();
    const Vec3 origin = frame.translation();
    PlacedShape s;
    s.kind = spec.kind;
    s.inflation = padding;
    switch (spec.kind) {
    case OPX_SHAPE_SPHERE: s.point = origin, s.inflation += spec.radius; break;
    case OPX_SHAPE_CAPSULE: {
        const Vec3 half_axis = axes.col(2) * (0.5 * spec.length);
        s.segment = {origin - half_axis, origin + half_axis};
        s.inflation += spec.radius;
        break;
    }
    case OPX_SHAPE_BOX: s.box = {origin, axes, 0.5 * spec.size}; break;
    case OPX_SHAPE_CYLINDER: s.cylinder = {origin, axes, spec.radius, spec.length}; break;
    case OPX_SHAPE_CONVEX:
        for (size_t i = 0; i < spec.hull_vertex_count; ++i) s.hull.vertices.push_back(frame * spec.vertices[i]);
        s.hull.faces = spec.hull_faces;
        break;
    case OPX_SHAPE_MESH:
        for (const auto &t : spec.triangles)
            s.triangles.push_back({frame * spec.vertices[t[0]], frame * spec.vertices[t[1]],
                                   frame * spec.vertices[t[2]]});
        break;
    }
    set_bounds(s);
    return s;
}

double aabb_cell_gap(const Vec3 &low, const Vec3 &high, const Cell &cell) {
    const Vec3 cell_low = cell.center - Vec3::Constant(cell.half);
    const Vec3 cell_high = cell.center + Vec3::Constant(cell.half);
    return (cell_low - high).cwiseMax(low - cell_high).cwiseMax(0.0).norm();
}

double mesh_cell_distance(const std::vector<Triangle> &triangles, const Cell &cell, double cutoff) {
    double best = std::numeric_limits<double>::infinity();
    for (const Triangle &t : triangles) {
        const Vec3 low = t.a.cwiseMin(t.b).cwiseMin(t.c), high = t.a.cwiseMax(t.b).cwiseMax(t.c);
        if (aabb_cell_gap(low, high, cell) > std::min(cutoff, best)) continue;
        best = std::min(best, triangle_cell_distance(t, cell));
    }
    return best;
}

}  // namespace

opx_linkset *build_linkset(const RobotSpec &robot) {
    opx_linkset *links = nullptr;
    require_ok(opx_linkset_create(&links), "opx_linkset_create");
    unsigned shapes = 0;
    for (const LinkSpec &link : robot.links) {
        uint32_t index = 0;
        require_ok(opx_linkset_add_link(links, link.name.c_str(), &index), "opx_linkset_add_link");
        for (const ShapeSpec &spec : link.shapes) {
            const bool strided = ++shapes % 2 == 0;
            const std::vector<double> vertices = vertex_buffer(spec, strided);
            const opx_shape shape = library_shape(spec, vertices, strided);
            require_ok(opx_linkset_add_shape(links, index, &shape, nullptr), "opx_linkset_add_shape");
        }
    }
    update_linkset(links, robot);
    return links;
}

void update_linkset(opx_linkset *links, const RobotSpec &robot, unsigned variant) {
    // Strided: each pose followed by 3 doubles the library must skip.
    struct PaddedPose {
        opx_pose pose;
        double filler[3];
    };
    std::vector<PaddedPose> poses;
    for (const LinkSpec &link : robot.links) poses.push_back({link.pose, {1e300, -1e300, 0.0}});
    const bool strided = variant & 2u;
    const size_t stride = strided ? sizeof(PaddedPose) : 0;
    std::vector<opx_pose> packed;
    for (const PaddedPose &p : poses) packed.push_back(p.pose);
    const opx_pose *first = strided ? &poses.front().pose : packed.data();
    if (variant & 1u) require_ok(opx_linkset_set_poses(links, first, poses.size(), stride), "opx_linkset_set_poses");
    for (uint32_t i = 0; i < robot.links.size(); ++i) {
        const LinkSpec &link = robot.links[i];
        require_ok(opx_linkset_set_link_padding(links, i, link.padding), "opx_linkset_set_link_padding");
        require_ok(opx_linkset_set_link_enabled(links, i, link.enabled ? 1 : 0), "opx_linkset_set_link_enabled");
    }
    require_ok(opx_linkset_set_padding(links, robot.global_padding), "opx_linkset_set_padding");
    if (!(variant & 1u)) require_ok(opx_linkset_set_poses(links, first, poses.size(), stride), "opx_linkset_set_poses");
}

Eigen::Isometry3d isometry_of(const opx_pose &pose) {
    const Eigen::Quaterniond q(pose.orientation[3], pose.orientation[0], pose.orientation[1],
                               pose.orientation[2]);
    Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
    transform.linear() = q.normalized().toRotationMatrix();
    transform.translation() = Vec3(pose.position[0], pose.position[1], pose.position[2]);
    return transform;
}

opx_pose pose_of(const Eigen::Isometry3d &transform) {
    const Eigen::Quaterniond q(transform.linear());
    opx_pose pose = {{transform.translation().x(), transform.translation().y(), transform.translation().z()},
                     {q.x(), q.y(), q.z(), q.w()}};
    return pose;
}

std::vector<PlacedShape> place_robot(const RobotSpec &robot) {
    std::vector<PlacedShape> placed;
    for (uint32_t i = 0; i < robot.links.size(); ++i) {
        const LinkSpec &link = robot.links[i];
        if (!link.enabled) continue;
        const Eigen::Isometry3d pose = isometry_of(link.pose);
        for (uint32_t j = 0; j < link.shapes.size(); ++j) {
            PlacedShape s = place_shape(link.shapes[j], pose, link.padding + robot.global_padding);
            s.link = i, s.shape = j;
            placed.push_back(std::move(s));
        }
    }
    return placed;
}

double shape_cell_distance(const PlacedShape &s, const Cell &cell, double cutoff) {
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: return point_cell_distance(s.point, cell);
    case OPX_SHAPE_CAPSULE: return segment_cell_distance(s.segment, cell);
    case OPX_SHAPE_BOX: return box_cell_distance(s.box, cell);
    case OPX_SHAPE_CYLINDER: return cylinder_cell_distance(s.cylinder, cell);
    case OPX_SHAPE_CONVEX: {
        const std::vector<Vec3> &v = s.hull.vertices;
        if (v.size() == 1) return point_cell_distance(v[0], cell);  // degenerate hulls
        if (v.size() == 2) return segment_cell_distance({v[0], v[1]}, cell);
        if (v.size() == 3) return triangle_cell_distance({v[0], v[1], v[2]}, cell);
        return polytope_cell_distance(s.hull, cell);
    }
    case OPX_SHAPE_MESH: return mesh_cell_distance(s.triangles, cell, cutoff);
    }
    return std::numeric_limits<double>::infinity();
}

double bounds_gap(const PlacedShape &shape, const Cell &cell) {
    return aabb_cell_gap(shape.bounds_min, shape.bounds_max, cell);
}

Verdict judge(const PlacedShape &shape, double distance) {
    const double threshold = shape.inflation + kTouchTolerance;
    const double band = shape.kind == OPX_SHAPE_CYLINDER ? kCurvedAmbiguity : kExactAmbiguity;
    if (std::abs(distance - threshold) < band) return Verdict::kAmbiguous;
    return distance <= threshold ? Verdict::kTouch : Verdict::kClear;
}

const char *kind_name(int32_t kind) {
    static const char *names[] = {"?", "sphere", "box", "cylinder", "capsule", "convex", "mesh"};
    return kind >= 1 && kind <= 6 ? names[kind] : names[0];
}

std::string describe_pose(const opx_pose &p) {
    std::ostringstream out;
    out.precision(17);
    out << "pos(" << p.position[0] << ", " << p.position[1] << ", " << p.position[2] << ") quat_xyzw("
        << p.orientation[0] << ", " << p.orientation[1] << ", " << p.orientation[2] << ", " << p.orientation[3]
        << ")";
    return out.str();
}

std::string describe_shape(const ShapeSpec &s) {
    std::ostringstream out;
    out.precision(17);
    out << kind_name(s.kind) << " radius=" << s.radius << " length=" << s.length << " size=("
        << s.size.x() << ", " << s.size.y() << ", " << s.size.z() << ") shape_pose " << describe_pose(s.pose);
    if (!s.vertices.empty()) {
        out << " vertices[" << s.vertices.size() << "]={";
        for (size_t i = 0; i < s.vertices.size() && i < 12; ++i)
            out << "(" << s.vertices[i].x() << ", " << s.vertices[i].y() << ", " << s.vertices[i].z() << ")";
        out << (s.vertices.size() > 12 ? "...}" : "}");
    }
    if (!s.triangles.empty()) out << " triangles=" << s.triangles.size();
    return out.str();
}

}  // namespace oracle
