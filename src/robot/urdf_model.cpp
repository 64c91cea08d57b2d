#include "robot/urdf_model.hpp"

#include "base/error.hpp"
#include "robot/mesh_loader.hpp"
#include "robot/urdf_values.hpp"
#include "robot/urdf_xml.hpp"

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <map>
#include <unordered_map>

namespace octoprox {
namespace {

using NameIndex = std::unordered_map<std::string, uint32_t>;

Pose to_pose(const urdf::Pose &p) {
    Eigen::Quaterniond q(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
    q.normalize();
    Pose pose;
    pose.rotation = q.toRotationMatrix();
    pose.translation = Vec3(p.position.x, p.position.y, p.position.z);
    return pose;
}

Vec3 to_vec(const urdf::Vector3 &v) { return Vec3(v.x, v.y, v.z); }

// Reads each mesh file once per load, whatever the number of links using it.
class ShapeBuilder {
public:
    ShapeBuilder(const UrdfInput &input) : input_(input) {}

    ShapeDef build(const urdf::Collision &collision, const std::string &where) {
        if (!collision.geometry) throw_corrupt(where + " has no geometry");
        ShapeDef def;
        def.local = to_pose(collision.origin);
        const urdf::Geometry &g = *collision.geometry;
        switch (g.type) {
        case urdf::Geometry::SPHERE:
            def.kind = ShapeKind::kSphere;
            def.radius = positive(static_cast<const urdf::Sphere &>(g).radius, where + " sphere radius");
            break;
        case urdf::Geometry::BOX: {
            const urdf::Vector3 &d = static_cast<const urdf::Box &>(g).dim;
            def.kind = ShapeKind::kBox;
            def.half_size = 0.5 * Vec3(positive(d.x, where + " box size x"), positive(d.y, where + " box size y"),
                                       positive(d.z, where + " box size z"));
            break;
        }
        case urdf::Geometry::CYLINDER: {
            const auto &c = static_cast<const urdf::Cylinder &>(g);
            def.kind = ShapeKind::kCylinder;
            def.radius = positive(c.radius, where + " cylinder radius");
            def.half_length = 0.5 * positive(c.length, where + " cylinder length");
            break;
        }
        case urdf::Geometry::MESH: mesh(static_cast<const urdf::Mesh &>(g), where, def); break;
        default: throw ApiError(OPX_ERROR_UNSUPPORTED, where + " has a geometry type this library does not know");
        }
        return def;
    }

private:
    static double positive(double value, const std::string &what) {
        if (!(value > 0.0) || !std::isfinite(value)) throw_corrupt(what + " is " + std::to_string(value) + ", not > 0");
        return value;
    }

    void mesh(const urdf::Mesh &m, const std::string &where, ShapeDef &def) {
        const Vec3 scale = to_vec(m.scale);
        if (!scale.allFinite() || scale.x() == 0.0 || scale.y() == 0.0 || scale.z() == 0.0)
            throw_corrupt(where + " mesh scale is zero or not finite");
        try {
            const std::string path = resolve_resource(input_.paths, m.filename);
            auto cached = cache_.find(path);
            if (cached == cache_.end()) cached = cache_.emplace(path, load_mesh_file(path)).first;
            TriangleMesh mesh = scaled(cached->second, scale);
            for (const Vec3 &v : mesh.vertices)
                if (!(v.cwiseAbs().maxCoeff() <= kMaxUrdfMagnitude))
                    throw_corrupt("mesh '" + m.filename + "' has a vertex beyond +-1e6 m once scaled");
            def.kind = ShapeKind::kMesh;
            def.vertices = std::move(mesh.vertices);
            def.triangles = std::move(mesh.triangles);
        } catch (const ApiError &error) {
            throw ApiError(error.status(), where + ": " + error.what());
        }
    }

    const UrdfInput &input_;
    std::map<std::string, TriangleMesh> cache_;
};

// urdfdom parses the outline's checked copy, never the caller's text: it
// then has nothing to reject (it would say why on stderr only).
urdf::ModelInterfaceSharedPtr parse_model(const UrdfOutline &outline, const std::string &source) {
    urdf::ModelInterfaceSharedPtr model;
    try {
        model = urdf::parseURDF(outline.checked_xml);
    } catch (const std::bad_alloc &) {
        throw;
    } catch (const std::exception &error) {
        throw ApiError(OPX_ERROR_INTERNAL, source + ": urdfdom failed on the checked URDF: " + error.what());
    }
    if (!model) throw ApiError(OPX_ERROR_INTERNAL, source + ": urdfdom rejected the checked URDF");
    return model;
}

void add_links(const urdf::ModelInterface &model, const UrdfOutline &outline, const UrdfInput &input,
               LinkSet &links) {
    ShapeBuilder shapes(input);
    for (size_t l = 0; l < outline.links.size(); ++l) {
        const std::string &name = outline.links[l];
        const uint32_t index = links.add_link(name);
        const urdf::LinkConstSharedPtr link = model.getLink(name);
        if (!link || link->collision_array.size() != outline.collision_counts[l])
            throw ApiError(OPX_ERROR_INTERNAL, input.source + ": urdfdom did not read link '" + name + "' as checked");
        for (size_t c = 0; c < link->collision_array.size(); ++c) {
            const std::string where = input.source + ": link '" + name + "' collision " + std::to_string(c);
            links.add_shape(index, shapes.build(*link->collision_array[c], where));
        }
    }
}

JointType joint_type(int urdf_type) {
    switch (urdf_type) {
    case urdf::Joint::REVOLUTE: return JointType::kRevolute;
    case urdf::Joint::CONTINUOUS: return JointType::kContinuous;
    case urdf::Joint::PRISMATIC: return JointType::kPrismatic;
    case urdf::Joint::FLOATING: return JointType::kFloating;
    case urdf::Joint::PLANAR: return JointType::kPlanar;
    default: return JointType::kFixed;
    }
}

Joint convert_joint(const urdf::Joint &in, const NameIndex &links, const NameIndex &joints, const std::string &source) {
    Joint j;
    j.name = in.name;
    j.type = joint_type(in.type);
    j.parent_link = links.at(in.parent_link_name);
    j.child_link = links.at(in.child_link_name);
    j.origin = to_pose(in.parent_to_joint_origin_transform);
    j.axis = to_vec(in.axis);
    if (j.moves() && !(j.axis.norm() > 1e-12 && j.axis.allFinite()))
        throw_corrupt(source + ": joint '" + j.name + "' has a zero or non-finite axis");
    if (j.axis.norm() > 1e-12) j.axis.normalize();
    if (in.limits) {
        j.has_limits = true;
        j.lower = in.limits->lower, j.upper = in.limits->upper;
        j.velocity = in.limits->velocity, j.effort = in.limits->effort;
    }
    if (j.type == JointType::kContinuous) j.lower = -INFINITY, j.upper = INFINITY;
    if (in.mimic) {
        j.mimic = joints.at(in.mimic->joint_name);
        j.multiplier = in.mimic->multiplier, j.offset = in.mimic->offset;
    }
    return j;
}

NameIndex index_names(const std::vector<std::string> &names) {
    NameIndex index;
    for (uint32_t i = 0; i < names.size(); ++i) index.emplace(names[i], i);
    return index;
}

void build_joints(const urdf::ModelInterface &model, const UrdfOutline &outline, const UrdfInput &input,
                  RobotModel &robot) {
    const NameIndex links = index_names(outline.links), joints = index_names(outline.joints);
    std::vector<Joint> converted;
    for (const std::string &name : outline.joints) {
        const urdf::JointConstSharedPtr joint = model.getJoint(name);
        if (!joint) throw_corrupt(input.source + ": joint '" + name + "' was not parsed");
        converted.push_back(convert_joint(*joint, links, joints, input.source));
    }
    const uint32_t root = model.getRoot() ? links.at(model.getRoot()->name) : kNoIndex;
    robot.joints.build(std::move(converted), outline.links.size(), root, input.source);
}

void read_disabled_pairs(const UrdfInput &input, const LinkSet &links, RobotModel &robot) {
    const std::string source = "options->srdf_path '" + input.srdf_path + "'";
    NameIndex index;
    for (uint32_t i = 0; i < links.link_count(); ++i) index.emplace(links.link(i).name, i);
    for (const auto &[a, b] : read_srdf_disabled_pairs(input.srdf_path, source)) {
        const auto ia = index.find(a), ib = index.find(b);
        if (ia == index.end() || ib == index.end())
            throw_corrupt(source + ": disable_collisions names link '" + (ia == index.end() ? a : b) +
                          "', which is not in the URDF");
        robot.disabled_pairs.push_back({ia->second, ib->second});
    }
}

// Self-collision skips the SRDF's pairs (a pair of a link with itself
// means nothing: a link never collides with itself).
void disable_srdf_pairs(const RobotModel &robot, LinkSet &links) {
    for (const auto &[a, b] : robot.disabled_pairs)
        if (a != b) links.set_pair_enabled(a, b, false);
}

}  // namespace

void load_urdf(const UrdfInput &input, LinkSet &links, RobotModel &robot) {
    const UrdfOutline outline = read_urdf_outline(input.xml, input.source);
    const urdf::ModelInterfaceSharedPtr model = parse_model(outline, input.source);
    if (model->links_.size() != outline.links.size() || model->joints_.size() != outline.joints.size())
        throw ApiError(OPX_ERROR_INTERNAL, input.source + ": urdfdom read another number of links or joints");
    add_links(*model, outline, input, links);
    build_joints(*model, outline, input, robot);
    if (!input.srdf_path.empty()) read_disabled_pairs(input, links, robot);
    disable_srdf_pairs(robot, links);
    robot.apply(links, Pose());
}

}  // namespace octoprox
