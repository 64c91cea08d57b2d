#include "world/scene_text.hpp"

#include "base/error.hpp"
#include "world/scene_shapes.hpp"

#include <cerrno>
#include <cstdlib>

namespace octoprox {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

std::string trimmed(const std::string &s) {
    size_t begin = 0, end = s.size();
    while (begin < end && is_space(s[begin])) ++begin;
    while (end > begin && is_space(s[end - 1])) --end;
    return s.substr(begin, end - begin);
}

// Whitespace-separated tokens with their line numbers.
class Scanner {
public:
    Scanner(const std::string &text, const std::string &source) : text_(text), source_(source) {}

    // The rest of the current line, trimmed; the scanner moves to the next.
    std::string rest_of_line() {
        const size_t end = std::min(text_.find('\n', at_), text_.size());
        std::string line = text_.substr(at_, end - at_);
        at_ = end;
        if (at_ < text_.size()) ++at_, ++line_;
        return trimmed(line);
    }
    bool at_end() {
        skip_space();
        return at_ >= text_.size();
    }
    // The next token; the end of the text is an error naming `field`.
    std::string token(const std::string &field) {
        if (at_end()) scene_fail(SceneWhere{&source_, line_, field}, "missing (the file ends early)");
        const size_t begin = at_;
        while (at_ < text_.size() && !is_space(text_[at_])) ++at_;
        token_line_ = line_;
        return text_.substr(begin, at_ - begin);
    }
    double number(const std::string &field) {
        const std::string t = token(field);
        char *end = nullptr;
        errno = 0;
        const double value = std::strtod(t.c_str(), &end);
        if (end == t.c_str() || *end != '\0') fail(field, "'" + t + "' is not a number");
        return value;
    }
    uint64_t count(const std::string &field) {
        const std::string t = token(field);
        char *end = nullptr;
        errno = 0;
        const unsigned long long value = std::strtoull(t.c_str(), &end, 10);
        if (t.empty() || t[0] == '-' || end == t.c_str() || *end != '\0' || errno == ERANGE || value > UINT32_MAX)
            fail(field, "'" + t + "' is not a count");
        return value;
    }
    Vec3 vector(const std::string &field) {
        const double x = number(field), y = number(field), z = number(field);
        return Vec3(x, y, z);
    }
    Pose pose(const std::string &field) {
        const Vec3 position = vector(field + " position");
        std::array<double, 4> q{};
        for (double &value : q) value = number(field + " orientation");
        return scene_pose(position, q, here(field));
    }
    // At the last token read.
    SceneWhere here(const std::string &field) const { return SceneWhere{&source_, token_line_, field}; }
    [[noreturn]] void fail(const std::string &field, const std::string &what,
                           opx_status status = OPX_ERROR_CORRUPT) const {
        scene_fail(here(field), what, status);
    }

private:
    void skip_space() {
        for (; at_ < text_.size() && is_space(text_[at_]); ++at_)
            if (text_[at_] == '\n') ++line_;
    }

    const std::string &text_;
    const std::string &source_;
    size_t at_ = 0;
    int line_ = 1, token_line_ = 1;
};

// As MoveIt: the line after the first "*" line holds a pose (spaces) in
// the newer format, a shape count in the older one.
bool has_object_poses(const std::string &text) {
    size_t at = text.find('\n');
    while (at != std::string::npos && at + 1 < text.size()) {
        const size_t begin = at + 1;
        at = text.find('\n', begin);
        if (text[begin] != '*') continue;
        if (at == std::string::npos) return false;
        const size_t next_end = std::min(text.find('\n', at + 1), text.size());
        return trimmed(text.substr(at + 1, next_end - at - 1)).find(' ') != std::string::npos;
    }
    return false;
}

ShapeDef read_mesh(Scanner &in, const std::string &field) {
    const uint64_t vertex_count = in.count(field + " vertex count");
    const uint64_t triangle_count = in.count(field + " triangle count");
    std::vector<Vec3> vertices;
    for (uint64_t i = 0; i < vertex_count; ++i) vertices.push_back(in.vector(field + format(" vertex %llu", static_cast<unsigned long long>(i))));
    std::vector<std::array<uint32_t, 3>> triangles;
    for (uint64_t t = 0; t < triangle_count; ++t) {
        std::array<uint32_t, 3> face{};
        for (uint32_t &index : face) index = static_cast<uint32_t>(in.count(field + format(" triangle %llu", static_cast<unsigned long long>(t))));
        triangles.push_back(face);
    }
    return scene_mesh(std::move(vertices), std::move(triangles), in.here(field));
}

ShapeDef read_shape(Scanner &in, const std::string &field) {
    const std::string kind = in.token(field + " kind");
    const SceneWhere at = in.here(field + " (" + kind + ")");
    if (kind == "box") {
        const Vec3 size = in.vector(field + " (box) size");
        return scene_box(size, in.here(field + " (box) size"));
    }
    if (kind == "sphere") return scene_sphere(in.number(field + " (sphere) radius"), in.here(field + " (sphere)"));
    if (kind == "cylinder") {
        const double radius = in.number(field + " (cylinder) radius"), length = in.number(field + " (cylinder) length");
        return scene_cylinder(radius, length, in.here(field + " (cylinder)"));
    }
    if (kind == "mesh") return read_mesh(in, field + " (mesh)");
    if (kind == "cone" || kind == "plane")
        scene_fail(at, kind + " shapes are not supported", OPX_ERROR_UNSUPPORTED);
    scene_fail(at, "'" + kind + "' is not a shape kind (box, sphere, cylinder, mesh)");
}

void read_object(Scanner &in, bool poses, World &world) {
    const std::string name = in.rest_of_line();
    if (name.find('\0') != std::string::npos) in.fail("object", "a '*' line whose name holds a NUL byte");
    SceneObjectUpdate u;
    u.id = name;
    u.where = in.here("object '" + name + "'");
    const std::string field = "object '" + name + "'";
    if (name.empty()) in.fail("object", "a '*' line without a name");
    if (poses) u.pose = in.pose(field + " pose"), u.has_pose = true;
    const uint64_t shapes = in.count(field + " shape count");
    for (uint64_t s = 0; s < shapes; ++s) {
        const std::string f = field + format(" shape %llu", static_cast<unsigned long long>(s));
        ShapeDef def = read_shape(in, f);
        def.local = in.pose(f + " pose");
        for (int c = 0; c < 4; ++c) in.number(f + " colour");
        u.shapes.push_back(std::move(def));
    }
    if (poses) {
        const uint64_t subframes = in.count(field + " subframe count");
        for (uint64_t i = 0; i < subframes; ++i) {
            in.token(field + " subframe name");
            in.pose(field + " subframe pose");
        }
    }
    // A count of 0 leaves the world as it is (as MoveIt).
    if (!u.shapes.empty()) apply_update(world, std::move(u));
}

}  // namespace

void read_scene_text(const std::string &text, const std::string &source, World &world) {
    Scanner in(text, source);
    in.rest_of_line();  // the scene's name
    const bool poses = has_object_poses(text);
    for (;;) {
        const std::string marker = in.token("'*' or '.'");
        if (marker == ".") return;
        if (marker != "*") in.fail("marker", "'" + marker + "' where a '* NAME' line or the closing '.' belongs");
        read_object(in, poses, world);
    }
}

}  // namespace octoprox
