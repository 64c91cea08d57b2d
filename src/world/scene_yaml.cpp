#include "world/scene_yaml.hpp"

#include "base/error.hpp"
#include "world/scene_shapes.hpp"
#include "world/scene_yaml_documents.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace octoprox {
namespace {

// SolidPrimitive types and the operations of moveit_msgs/CollisionObject,
// each also written as its word (robowflex's YAML, MotionBenchMaker's
// scenes), in any case.
constexpr int kBox = 1, kSphere = 2, kCylinder = 3, kCone = 4;
constexpr const char *kPrimitiveWords[] = {"box", "sphere", "cylinder", "cone"};  // 1 to 4
constexpr const char *kOperationWords[] = {"add", "remove", "append", "move"};   // 0 to 3

// A pose's values as written (before scene_pose checks them): all zeros
// is MoveIt's "no pose given".
struct RawPose {
    Vec3 position = Vec3(0.0, 0.0, 0.0);
    std::array<double, 4> quaternion{0.0, 0.0, 0.0, 0.0};
    bool given() const {
        return position != Vec3(0.0, 0.0, 0.0) || quaternion != std::array<double, 4>{0.0, 0.0, 0.0, 0.0};
    }
};

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
    int word_or_integer(const YAML::Node &node, const std::string &field, const YAML::Node &parent,
                        const char *const *words, size_t word_count, int first, const char *choices);
    template <size_t N>
    std::array<double, N> values(const YAML::Node &node, const std::string &field, const char *const (&keys)[N],
                                 const char *layout);
    Vec3 point(const YAML::Node &node, const std::string &field);
    RawPose raw_pose(const YAML::Node &node, const std::string &field, const char *position, const char *rotation);
    Pose pose(const YAML::Node &node, const std::string &field);
    std::vector<Pose> poses(const YAML::Node &object, const char *key, const std::string &field);
    ShapeDef primitive(const YAML::Node &node, const std::string &field);
    ShapeDef mesh(const YAML::Node &node, const std::string &field);
    void shapes(const YAML::Node &object, const std::string &field, SceneObjectUpdate &update);
    SceneObjectUpdate object(const YAML::Node &node, const std::string &field);
    void fixed_frames(const YAML::Node &root, bool is_diff);
    void place_in_frame(const std::string &frame, SceneObjectUpdate &update) const;

    // Spends one element of the budget (see kElementsPerByte).
    void spend(const YAML::Node &node, const std::string &field);

    const std::string &source_;
    World &world_;
    int first_line_ = 0;
    size_t budget_;
    // fixed_frame_transforms: each child frame's pose in the map frame (a
    // hash map: a scene may hold as many frames as objects).
    std::unordered_map<std::string, Pose> frames_;
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
    if (!node.IsSequence()) scene_fail(where(node, field.empty() ? key : field + "." + key), "not a list");
    return node;
}

// A number, or one of `words` (any case) standing for first, first + 1, ...
int YamlScene::word_or_integer(const YAML::Node &node, const std::string &field, const YAML::Node &parent,
                               const char *const *words, size_t word_count, int first, const char *choices) {
    if (node.IsDefined() && node.IsScalar()) {
        std::string word = node.Scalar();
        std::transform(word.begin(), word.end(), word.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        for (size_t i = 0; i < word_count; ++i)
            if (word == words[i]) return first + static_cast<int>(i);
        double unused = 0.0;
        if (!YAML::convert<double>::decode(node, unused))
            scene_fail(where(node, field), "'" + node.Scalar() + "' is none of " + choices);
    }
    return integer(node, field, parent);
}

// N numbers as a map of `keys` (ROS message fields left out are zero) or
// as a list of N (robowflex's YAML, MotionBenchMaker's scenes); null is
// all zeros.
template <size_t N>
std::array<double, N> YamlScene::values(const YAML::Node &node, const std::string &field,
                                        const char *const (&keys)[N], const char *layout) {
    std::array<double, N> out{};
    if (!node.IsDefined() || node.IsNull()) return out;
    if (node.IsSequence()) {
        if (node.size() != N)
            scene_fail(where(node, field), format("%zu values; a list [%s] or a map of %s", node.size(), layout, layout));
        for (size_t i = 0; i < N; ++i) out[i] = number(node[i], format("%s[%zu]", field.c_str(), i), node);
        return out;
    }
    if (!node.IsMap()) scene_fail(where(node, field), format("not a map of %s or a list [%s]", layout, layout));
    for (size_t i = 0; i < N; ++i) out[i] = number_or_zero(node, keys[i], field);
    return out;
}

Vec3 YamlScene::point(const YAML::Node &node, const std::string &field) {
    static constexpr const char *kKeys[] = {"x", "y", "z"};
    const std::array<double, 3> v = values(node, field, kKeys, "x, y, z");
    return Vec3(v[0], v[1], v[2]);
}

// A geometry_msgs/Pose (`position`, `orientation`) or Transform
// (`translation`, `rotation`).
RawPose YamlScene::raw_pose(const YAML::Node &node, const std::string &field, const char *position,
                            const char *rotation) {
    if (node.IsDefined() && !node.IsNull() && !node.IsMap())
        scene_fail(where(node, field), format("not a map of %s and %s", position, rotation));
    static constexpr const char *kKeys[] = {"x", "y", "z", "w"};
    RawPose raw;
    raw.position = point(child(node, position), field + "." + position);
    raw.quaternion = values(child(node, rotation), field + "." + rotation, kKeys, "x, y, z, w");
    return raw;
}

Pose YamlScene::pose(const YAML::Node &node, const std::string &field) {
    const RawPose raw = raw_pose(node, field, "position", "orientation");
    return scene_pose(raw.position, raw.quaternion, where(node, field));
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
    const int type = word_or_integer(type_node, field + ".type", node, kPrimitiveWords, 4, kBox,
                                     "1 or box, 2 or sphere, 3 or cylinder, 4 or cone");
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
    const YAML::Node resource = child(node, "resource");
    if (resource.IsDefined() && !child(node, "vertices").IsDefined())
        scene_fail(where(resource, field + ".resource"),
                   "'" + text(resource, field + ".resource") + "': mesh files are not read; give the vertices and triangles",
                   OPX_ERROR_UNSUPPORTED);
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
        // A shape_msgs/MeshTriangle, or its three indices alone (robowflex).
        const bool bare = triangles[t].IsSequence();
        const std::string fi = bare ? f : f + ".vertex_indices";
        const YAML::Node indices = bare ? triangles[t] : sequence(triangles[t], "vertex_indices", f);
        if (indices.size() != 3) scene_fail(where(triangles[t], fi), "not 3 vertex indices");
        std::array<uint32_t, 3> face{};
        for (size_t k = 0; k < 3; ++k) {
            const int index = integer(indices[k], format("%s[%zu]", fi.c_str(), k), indices);
            if (index < 0 || static_cast<size_t>(index) >= points.size())
                scene_fail(where(indices[k], fi),
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
    const std::string frame = text(child(child(node, "header"), "frame_id"), field + ".header.frame_id");
    const YAML::Node operation = child(node, "operation");
    const char *choices = "0 or add, 1 or remove, 2 or append, 3 or move";
    const int op = operation.IsDefined() && !operation.IsNull()
                       ? word_or_integer(operation, field + ".operation", node, kOperationWords, 4, 0, choices)
                       : 0;
    if (op < 0 || op > 3) scene_fail(where(operation, field + ".operation"), format("%d is none of %s", op, choices));
    u.operation = static_cast<SceneOperation>(op);
    if (u.id.empty() && u.operation != SceneOperation::kRemove) scene_fail(where(node, field + ".id", node), "empty");
    const YAML::Node pose_node = child(node, "pose");
    const RawPose raw = raw_pose(pose_node, field + ".pose", "position", "orientation");
    u.has_pose = raw.given();
    if (u.has_pose) u.pose = scene_pose(raw.position, raw.quaternion, where(pose_node, field + ".pose"));
    if (u.operation == SceneOperation::kAdd || u.operation == SceneOperation::kAppend) shapes(node, field, u);
    if (u.operation == SceneOperation::kMove) {
        u.shape_poses = poses(node, "primitive_poses", field);
        for (const Pose &p : poses(node, "mesh_poses", field)) u.shape_poses.push_back(p);
    }
    place_in_frame(frame, u);
    return u;
}

// geometry_msgs/TransformStamped[]: child_frame_id's pose in its
// header.frame_id, which is the map frame or a fixed frame listed before.
// A document without them keeps the frames of the one before when it is
// a diff.
void YamlScene::fixed_frames(const YAML::Node &root, bool is_diff) {
    const YAML::Node list = sequence(root, "fixed_frame_transforms", "");
    if (list.size() == 0 && is_diff) return;
    frames_.clear();
    for (size_t i = 0; i < list.size(); ++i) {
        const std::string f = format("fixed_frame_transforms[%zu]", i);
        spend(list[i], f);
        if (!list[i].IsMap()) scene_fail(where(list[i], f), "not a map (a geometry_msgs/TransformStamped)");
        const std::string name = text(child(list[i], "child_frame_id"), f + ".child_frame_id");
        if (name.empty()) scene_fail(where(list[i], f + ".child_frame_id", list[i]), "empty");
        const std::string parent = text(child(child(list[i], "header"), "frame_id"), f + ".header.frame_id");
        const YAML::Node transform = child(list[i], "transform");
        const RawPose raw = raw_pose(transform, f + ".transform", "translation", "rotation");
        SceneObjectUpdate placed;
        placed.has_pose = true;
        placed.pose = scene_pose(raw.position, raw.quaternion, where(transform, f + ".transform", list[i]));
        place_in_frame(parent, placed);
        frames_[name] = placed.pose;  // a later transform of the same frame replaces it
    }
}

// An object whose header.frame_id names a fixed frame is placed by it:
// its pose, or (without one) its shapes' poses, are in that frame.
void YamlScene::place_in_frame(const std::string &frame, SceneObjectUpdate &u) const {
    const auto found = frame.empty() ? frames_.end() : frames_.find(frame);
    if (found == frames_.end()) return;
    const Pose &in_map = found->second;
    if (u.has_pose || (u.shapes.empty() && u.shape_poses.empty())) {
        u.pose = u.has_pose ? compose(in_map, u.pose) : in_map;
        u.has_pose = true;
        return;
    }
    for (ShapeDef &def : u.shapes) def.local = compose(in_map, def.local);
    for (Pose &p : u.shape_poses) p = compose(in_map, p);
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
    fixed_frames(root, is_diff);
    const std::string field = scene ? "world.collision_objects" : "collision_objects";
    const YAML::Node objects = sequence(scene ? world : root, "collision_objects", scene ? "world" : "");
    for (size_t i = 0; i < objects.size(); ++i) apply_update(world_, object(objects[i], format("%s[%zu]", field.c_str(), i)));
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
