#include "world/scene_yaml.hpp"

#include "base/error.hpp"
#include "world/scene_shapes.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

namespace octoprox {
namespace {

// SolidPrimitive types and the operations of moveit_msgs/CollisionObject.
constexpr int kBox = 1, kSphere = 2, kCylinder = 3, kCone = 4;

// YAML aliases (*name) repeat an anchored node without repeating its text,
// and nested ones multiply: a few kilobytes could name billions of
// vertices.  Every element read (object, shape, pose, vertex, triangle)
// spends one unit of a budget of four per byte of the text (plus 4096): a
// scene without aliases spends at most one per byte, as every element
// takes a byte or more of it.
constexpr size_t kElementsPerByte = 4;
constexpr size_t kElementsAtLeast = 4096;

class YamlScene {
public:
    YamlScene(const std::string &source, World &world, size_t text_size)
        : source_(source), world_(world), budget_(kElementsPerByte * text_size + kElementsAtLeast) {}

    // `first_line`: where the document starts in the source (0-based).
    void read_document(const YAML::Node &root, int first_line);

private:
    // A node's line (1-based), or its parent's when the node is missing.
    SceneWhere where(const YAML::Node &node, const std::string &field, const YAML::Node &parent = YAML::Node()) const {
        const YAML::Mark mark = node.IsDefined() ? node.Mark() : parent.IsDefined() ? parent.Mark() : YAML::Mark::null_mark();
        return SceneWhere{&source_, mark.is_null() ? 0 : first_line_ + mark.line + 1, field};
    }
    // A missing key (or a key of what is no map) gives an undefined node,
    // which every reader checks (IsDefined) before asking anything else.
    static YAML::Node child(const YAML::Node &map, const char *key) {
        return map.IsDefined() && map.IsMap() ? map[key] : YAML::Node(YAML::NodeType::Undefined);
    }
    double number(const YAML::Node &node, const std::string &field, const YAML::Node &parent);
    double number_or_zero(const YAML::Node &map, const char *key, const std::string &field);
    int integer(const YAML::Node &node, const std::string &field, const YAML::Node &parent);
    std::string text(const YAML::Node &node, const std::string &field);
    YAML::Node sequence(const YAML::Node &map, const char *key, const std::string &field);
    Vec3 point(const YAML::Node &node, const std::string &field);
    Pose pose(const YAML::Node &node, const std::string &field);
    bool pose_given(const YAML::Node &node, const std::string &field);
    std::vector<Pose> poses(const YAML::Node &object, const char *key, const std::string &field);
    ShapeDef primitive(const YAML::Node &node, const std::string &field);
    ShapeDef mesh(const YAML::Node &node, const std::string &field);
    void shapes(const YAML::Node &object, const std::string &field, SceneObjectUpdate &update);
    SceneObjectUpdate object(const YAML::Node &node, const std::string &field);

    // Spends one element of the budget (see kElementsPerByte).
    void spend(const YAML::Node &node, const std::string &field);

    const std::string &source_;
    World &world_;
    int first_line_ = 0;
    size_t budget_;
};

void YamlScene::spend(const YAML::Node &node, const std::string &field) {
    if (budget_ == 0)
        scene_fail(where(node, field), "the scene's aliases (*name) repeat more elements than its size allows");
    --budget_;
}

double YamlScene::number(const YAML::Node &node, const std::string &field, const YAML::Node &parent) {
    if (!node.IsDefined()) scene_fail(where(node, field, parent), "missing");
    if (!node.IsScalar()) scene_fail(where(node, field), "not a number");
    try {
        return node.as<double>();
    } catch (const YAML::Exception &) {
        scene_fail(where(node, field), "'" + node.Scalar() + "' is not a number");
    }
}

// ROS message fields left out are zero.
double YamlScene::number_or_zero(const YAML::Node &map, const char *key, const std::string &field) {
    const YAML::Node value = child(map, key);
    return value.IsDefined() && !value.IsNull() ? number(value, field + "." + key, map) : 0.0;
}

int YamlScene::integer(const YAML::Node &node, const std::string &field, const YAML::Node &parent) {
    const double value = number(node, field, parent);
    if (!(std::fabs(value) < 1e9) || value != std::floor(value))
        scene_fail(where(node, field), format("%g is not an integer", value));
    return static_cast<int>(value);
}

std::string YamlScene::text(const YAML::Node &node, const std::string &field) {
    if (!node.IsDefined() || node.IsNull()) return std::string();
    if (!node.IsScalar()) scene_fail(where(node, field), "not a string");
    return node.Scalar();
}

// A missing or null sequence is empty.
YAML::Node YamlScene::sequence(const YAML::Node &map, const char *key, const std::string &field) {
    const YAML::Node node = child(map, key);
    if (!node.IsDefined() || node.IsNull()) return YAML::Node(YAML::NodeType::Sequence);
    if (!node.IsSequence()) scene_fail(where(node, field + "." + key), "not a list");
    return node;
}

Vec3 YamlScene::point(const YAML::Node &node, const std::string &field) {
    if (node.IsDefined() && !node.IsNull() && !node.IsMap()) scene_fail(where(node, field), "not a map of x, y, z");
    return Vec3(number_or_zero(node, "x", field), number_or_zero(node, "y", field), number_or_zero(node, "z", field));
}

Pose YamlScene::pose(const YAML::Node &node, const std::string &field) {
    if (node.IsDefined() && !node.IsNull() && !node.IsMap())
        scene_fail(where(node, field), "not a map of position and orientation");
    const YAML::Node orientation = child(node, "orientation");
    const std::string o = field + ".orientation";
    if (orientation.IsDefined() && !orientation.IsNull() && !orientation.IsMap())
        scene_fail(where(orientation, o), "not a map of x, y, z, w");
    const std::array<double, 4> q{number_or_zero(orientation, "x", o), number_or_zero(orientation, "y", o),
                                  number_or_zero(orientation, "z", o), number_or_zero(orientation, "w", o)};
    return scene_pose(point(child(node, "position"), field + ".position"), q, where(node, field));
}

// MoveIt takes a pose of all zeros (orientation included) as "not given";
// `node` has been read by pose() already.
bool YamlScene::pose_given(const YAML::Node &node, const std::string &field) {
    if (!node.IsDefined() || node.IsNull()) return false;
    const YAML::Node position = child(node, "position"), orientation = child(node, "orientation");
    for (const char *key : {"x", "y", "z"})
        if (number_or_zero(position, key, field + ".position") != 0.0) return true;
    for (const char *key : {"x", "y", "z", "w"})
        if (number_or_zero(orientation, key, field + ".orientation") != 0.0) return true;
    return false;
}

std::vector<Pose> YamlScene::poses(const YAML::Node &object, const char *key, const std::string &field) {
    const YAML::Node list = sequence(object, key, field);
    std::vector<Pose> out;
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string f = format("%s.%s[%zu]", field.c_str(), key, i);
        spend(list[i], f);
        out.push_back(pose(list[i], f));
    }
    return out;
}

ShapeDef YamlScene::primitive(const YAML::Node &node, const std::string &field) {
    spend(node, field);
    if (!node.IsMap()) scene_fail(where(node, field), "not a map of type and dimensions");
    const YAML::Node type_node = child(node, "type");
    const int type = integer(type_node, field + ".type", node);
    const YAML::Node dims = sequence(node, "dimensions", field);
    const std::string dims_field = field + ".dimensions";
    std::vector<double> d;
    for (size_t i = 0; i < dims.size(); ++i) d.push_back(number(dims[i], format("%s[%zu]", dims_field.c_str(), i), dims));
    const SceneWhere at = where(child(node, "dimensions"), dims_field, node);
    auto require = [&](size_t count, const char *layout) {
        if (d.size() != count) scene_fail(at, format("%zu value%s; %s", d.size(), d.size() == 1 ? "" : "s", layout));
    };
    switch (type) {
    case kBox: require(3, "a BOX (1) has [x, y, z]"); return scene_box(Vec3(d[0], d[1], d[2]), at);
    case kSphere: require(1, "a SPHERE (2) has [radius]"); return scene_sphere(d[0], at);
    case kCylinder: require(2, "a CYLINDER (3) has [height, radius]"); return scene_cylinder(d[1], d[0], at);
    case kCone: scene_fail(where(type_node, field + ".type"), "CONE (4) primitives are not supported",
                           OPX_ERROR_UNSUPPORTED);
    default:
        scene_fail(where(type_node, field + ".type"),
                   format("primitive type %d is not supported (1 BOX, 2 SPHERE, 3 CYLINDER)", type),
                   OPX_ERROR_UNSUPPORTED);
    }
}

ShapeDef YamlScene::mesh(const YAML::Node &node, const std::string &field) {
    spend(node, field);
    if (!node.IsMap()) scene_fail(where(node, field), "not a map of vertices and triangles");
    const YAML::Node vertices = sequence(node, "vertices", field), triangles = sequence(node, "triangles", field);
    std::vector<Vec3> points;
    for (size_t i = 0; i < vertices.size(); ++i) {
        const std::string f = format("%s.vertices[%zu]", field.c_str(), i);
        spend(vertices[i], f);
        points.push_back(point(vertices[i], f));
    }
    std::vector<std::array<uint32_t, 3>> faces;
    for (size_t t = 0; t < triangles.size(); ++t) {
        const std::string f = format("%s.triangles[%zu]", field.c_str(), t);
        spend(triangles[t], f);
        const YAML::Node indices = sequence(triangles[t], "vertex_indices", f);
        if (indices.size() != 3) scene_fail(where(triangles[t], f + ".vertex_indices"), "not 3 vertex indices");
        std::array<uint32_t, 3> face{};
        for (size_t k = 0; k < 3; ++k) {
            const int index = integer(indices[k], format("%s.vertex_indices[%zu]", f.c_str(), k), indices);
            if (index < 0 || static_cast<size_t>(index) >= points.size())
                scene_fail(where(indices[k], f + ".vertex_indices"),
                           format("vertex %d does not exist (the mesh has %zu vertices)", index, points.size()));
            face[k] = static_cast<uint32_t>(index);
        }
        faces.push_back(face);
    }
    return scene_mesh(std::move(points), std::move(faces), where(node, field));
}

// MoveIt's rule: more poses than shapes is an error; missing poses are the
// identity.
void YamlScene::shapes(const YAML::Node &object, const std::string &field, SceneObjectUpdate &update) {
    struct Kind {
        const char *shapes, *poses;
        bool mesh;
    };
    for (const Kind &kind : {Kind{"primitives", "primitive_poses", false}, Kind{"meshes", "mesh_poses", true}}) {
        const YAML::Node list = sequence(object, kind.shapes, field);
        const std::vector<Pose> placed = poses(object, kind.poses, field);
        if (placed.size() > list.size())
            scene_fail(where(child(object, kind.poses), field + "." + kind.poses),
                       format("%zu poses for %zu %s", placed.size(), list.size(), kind.shapes));
        for (size_t i = 0; i < list.size(); ++i) {
            const std::string f = format("%s.%s[%zu]", field.c_str(), kind.shapes, i);
            ShapeDef def = kind.mesh ? mesh(list[i], f) : primitive(list[i], f);
            if (i < placed.size()) def.local = placed[i];
            update.shapes.push_back(std::move(def));
        }
    }
    if (sequence(object, "planes", field).size() > 0)
        scene_fail(where(child(object, "planes"), field + ".planes"), "planes (infinite) are not supported",
                   OPX_ERROR_UNSUPPORTED);
}

SceneObjectUpdate YamlScene::object(const YAML::Node &node, const std::string &field) {
    spend(node, field);
    if (!node.IsMap()) scene_fail(where(node, field), "not a map (a moveit_msgs/CollisionObject)");
    SceneObjectUpdate u;
    u.where = where(node, field);
    u.id = text(child(node, "id"), field + ".id");
    text(child(child(node, "header"), "frame_id"), field + ".header.frame_id");  // taken as the map frame
    const YAML::Node operation = child(node, "operation");
    const int op = operation.IsDefined() ? integer(operation, field + ".operation", node) : 0;
    if (op < 0 || op > 3)
        scene_fail(where(operation, field + ".operation"), format("%d is not 0 ADD, 1 REMOVE, 2 APPEND or 3 MOVE", op));
    u.operation = static_cast<SceneOperation>(op);
    if (u.id.empty() && u.operation != SceneOperation::kRemove) scene_fail(where(node, field + ".id", node), "empty");
    const YAML::Node pose_node = child(node, "pose");
    if (pose_node.IsDefined() && !pose_node.IsNull()) u.pose = pose(pose_node, field + ".pose");
    u.has_pose = pose_given(pose_node, field + ".pose");
    if (u.operation == SceneOperation::kAdd || u.operation == SceneOperation::kAppend) shapes(node, field, u);
    if (u.operation == SceneOperation::kMove) {
        u.shape_poses = poses(node, "primitive_poses", field);
        for (const Pose &p : poses(node, "mesh_poses", field)) u.shape_poses.push_back(p);
    }
    return u;
}

void YamlScene::read_document(const YAML::Node &root, int first_line) {
    first_line_ = first_line;
    if (!root.IsMap()) {
        SceneWhere at = where(root, "");
        at.line = std::max(at.line, first_line + 1);
        scene_fail(at, "not a map (a moveit_msgs/PlanningScene or PlanningSceneWorld)");
    }
    const YAML::Node world = child(root, "world");
    const bool scene = world.IsDefined();
    if (!scene && !child(root, "collision_objects").IsDefined())
        scene_fail(where(root, "world"), "missing (a moveit_msgs/PlanningScene holds world.collision_objects)");
    if (scene && !world.IsNull() && !world.IsMap()) scene_fail(where(world, "world"), "not a map (a PlanningSceneWorld)");
    const YAML::Node diff = child(root, "is_diff");
    bool is_diff = false;
    if (diff.IsDefined() && !diff.IsNull()) {
        try {
            is_diff = diff.as<bool>();
        } catch (const YAML::Exception &) {
            scene_fail(where(diff, "is_diff"), "'" + diff.Scalar() + "' is not true or false");
        }
    }
    if (!is_diff) clear_world(world_);
    const std::string field = scene ? "world.collision_objects" : "collision_objects";
    const YAML::Node objects = sequence(scene ? world : root, "collision_objects", scene ? "world" : "");
    for (size_t i = 0; i < objects.size(); ++i) apply_update(world_, object(objects[i], format("%s[%zu]", field.c_str(), i)));
}

// A document of the text: from a "---" line (or the start) to the next.
struct YamlPiece {
    std::string text;
    int first_line = 0;  // 0-based, in the whole text
    bool has_content = false;  // more than markers, comments and blanks
};

bool starts_with(const std::string &line, const char *prefix) { return line.compare(0, std::strlen(prefix), prefix) == 0; }

bool is_marker(const std::string &line) {
    return starts_with(line, "---") && (line.size() == 3 || std::isspace(static_cast<unsigned char>(line[3])));
}

// Whether a line holds YAML content: not blank, a comment, "...", or a
// "---" marker with nothing after it.
bool holds_content(const std::string &line) {
    size_t at = is_marker(line) ? 3 : 0;
    if (at == 0 && starts_with(line, "...")) return false;
    while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
    return at < line.size() && line[at] != '#';
}

// yaml-cpp 0.7's LoadAll can loop for ever, allocating, on malformed
// input (a line starting with ','), so each document is parsed alone with
// Load, the text cut at the "---" markers (which YAML does not allow at
// the start of a line inside content).
std::vector<YamlPiece> split_documents(const std::string &text) {
    std::vector<YamlPiece> pieces(1);
    int line_number = 0;
    for (size_t at = 0; at < text.size(); ++line_number) {
        const size_t end = std::min(text.find('\n', at), text.size());
        const std::string line = text.substr(at, end - at);
        if (is_marker(line) && (pieces.back().has_content || !pieces.back().text.empty())) {
            pieces.emplace_back();
            pieces.back().first_line = line_number;
        }
        pieces.back().text += line + "\n";
        pieces.back().has_content = pieces.back().has_content || holds_content(line);
        at = end + 1;
    }
    return pieces;
}

[[noreturn]] void yaml_fail(const std::string &source, const YAML::Exception &error, int first_line, const char *what) {
    const SceneWhere at{&source, error.mark.is_null() ? 0 : first_line + error.mark.line + 1, ""};
    scene_fail(at, what + error.msg);
}

// yaml-cpp refuses lists and maps nested beyond its parser's limit (500
// levels in Debian's build) with the message "bad file"; say what it is.
[[noreturn]] void yaml_too_deep(const std::string &source, const YAML::DeepRecursion &error, int first_line) {
    const SceneWhere at{&source, error.mark.is_null() ? 0 : first_line + error.mark.line + 1, ""};
    scene_fail(at, format("lists and maps nested %d levels deep or more (the YAML reader's limit)",
                          error.depth()));
}

}  // namespace

void read_scene_yaml(const std::string &text, const std::string &source, World &world) {
    YamlScene scene(source, world, text.size());
    bool any = false;
    for (const YamlPiece &piece : split_documents(text)) {
        if (!piece.has_content) continue;
        any = true;
        YAML::Node document;
        try {
            document = YAML::Load(piece.text);
        } catch (const YAML::DeepRecursion &error) {
            yaml_too_deep(source, error, piece.first_line);
        } catch (const YAML::Exception &error) {
            yaml_fail(source, error, piece.first_line, "not valid YAML: ");
        }
        try {
            scene.read_document(document, piece.first_line);
        } catch (const YAML::Exception &error) {
            yaml_fail(source, error, piece.first_line, "unreadable YAML: ");
        }
    }
    if (!any) scene_fail(SceneWhere{&source, 0, ""}, "holds no YAML document");
}

}  // namespace octoprox
