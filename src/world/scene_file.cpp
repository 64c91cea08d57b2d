#include "world/scene_file.hpp"

#include "base/error.hpp"
#include "base/file_bytes.hpp"
#include "world/scene_text.hpp"
#include "world/scene_yaml.hpp"

#include <algorithm>
#include <cctype>

namespace octoprox {
namespace {

bool ends_with(const std::string &path, const std::string &suffix) {
    if (path.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), path.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

}  // namespace

SceneFormat scene_format_of(const std::string &path) {
    if (ends_with(path, ".yaml") || ends_with(path, ".yml")) return SceneFormat::kYaml;
    if (ends_with(path, ".scene")) return SceneFormat::kText;
    throw_invalid(format("path '%s' ends in none of .yaml, .yml (MoveIt planning scene YAML) and .scene (MoveIt "
                         "scene text)",
                         path.c_str()));
}

void read_scene(const std::string &text, SceneFormat format, const std::string &source, World &world) {
    if (format == SceneFormat::kYaml) read_scene_yaml(text, source, world);
    else read_scene_text(text, source, world);
}

void load_scene_file(const std::string &path, World &world) {
    const SceneFormat format = scene_format_of(path);
    read_scene(read_file_bytes(path.c_str(), "scene file"), format, path, world);
}

}  // namespace octoprox
