#include "world/scene_update.hpp"

#include "base/error.hpp"

namespace octoprox {

void scene_fail(const SceneWhere &where, const std::string &what, opx_status status) {
    std::string message = where.source != nullptr ? *where.source : std::string("scene");
    if (where.line > 0) message += format(": line %d", where.line);
    if (!where.field.empty()) message += ": " + where.field;
    throw ApiError(status, message + ": " + what);
}

Pose compose(const Pose &a, const Pose &b) {
    Pose out;
    out.rotation = a.rotation * b.rotation;
    out.translation = a.apply(b.translation);
    return out;
}

Pose inverse(const Pose &pose) {
    Pose out;
    out.rotation = pose.rotation.transpose();
    out.translation = -(out.rotation * pose.translation);
    return out;
}

namespace {

void require_shapes(const SceneObjectUpdate &u) {
    if (u.shapes.empty()) scene_fail(u.where, "object '" + u.id + "' has no shapes (primitives or meshes)");
}

void add_object(World &world, SceneObjectUpdate &u) {
    Pose pose = u.has_pose ? u.pose : Pose();
    if (!u.has_pose && u.shapes.size() == 1) {
        pose = u.shapes.front().local;
        u.shapes.front().local = Pose();
    }
    const uint32_t object = world.add_object(u.id, pose);
    for (ShapeDef &def : u.shapes) world.add_shape(object, std::move(def));
}

// The new shapes go where the message puts them, in the object's frame.
void append_to(World &world, uint32_t object, SceneObjectUpdate &u) {
    const Pose to_object = compose(inverse(world.object(object).pose), u.has_pose ? u.pose : Pose());
    for (ShapeDef &def : u.shapes) {
        def.local = compose(to_object, def.local);
        world.add_shape(object, std::move(def));
    }
}

void move_object(World &world, uint32_t object, const SceneObjectUpdate &u) {
    const size_t count = world.object(object).shapes.size();
    if (!u.shape_poses.empty() && u.shape_poses.size() != count)
        scene_fail(u.where, format("MOVE gives %zu shape poses; object '%s' has %zu shapes", u.shape_poses.size(),
                                   u.id.c_str(), count));
    world.set_object_pose(object, u.has_pose ? u.pose : Pose());
    for (size_t s = 0; s < u.shape_poses.size(); ++s)
        world.set_shape_pose(object, static_cast<uint32_t>(s), u.shape_poses[s]);
}

}  // namespace

void clear_world(World &world) {
    while (world.object_count() > 0) world.remove_object(static_cast<uint32_t>(world.object_count() - 1));
}

void apply_update(World &world, SceneObjectUpdate u) {
    // Names leave the library as C strings (opx_world_get_object_name):
    // one holding a NUL byte could not be read back or found.
    if (u.id.find('\0') != std::string::npos)
        scene_fail(u.where, "the object's name holds a NUL byte");
    const int64_t found = world.find_object(u.id);
    switch (u.operation) {
    case SceneOperation::kAdd:
        require_shapes(u);
        if (found >= 0) world.remove_object(static_cast<uint32_t>(found));
        return add_object(world, u);
    case SceneOperation::kAppend:
        require_shapes(u);
        if (found < 0) return add_object(world, u);
        return append_to(world, static_cast<uint32_t>(found), u);
    case SceneOperation::kRemove:
        if (u.id.empty()) return clear_world(world);
        if (found >= 0) world.remove_object(static_cast<uint32_t>(found));
        return;
    case SceneOperation::kMove:
        if (found < 0) scene_fail(u.where, "MOVE of object '" + u.id + "', which does not exist");
        return move_object(world, static_cast<uint32_t>(found), u);
    }
}

}  // namespace octoprox
