// Scene files into a World: the format from the extension (.yaml and .yml:
// MoveIt's planning scene YAML; .scene: MoveIt's scene text), or given.
#pragma once

#include "world/world.hpp"

#include <string>

namespace octoprox {

enum class SceneFormat { kYaml, kText };

// Throws ApiError(invalid argument) when the extension is none of them.
SceneFormat scene_format_of(const std::string &path);

// Adds the scene's objects to `world` (its updates applied in order);
// errors name `source`.
void read_scene(const std::string &text, SceneFormat format, const std::string &source, World &world);

// Reads the file at `path` (I/O errors: OPX_ERROR_IO) in the format of its
// extension.
void load_scene_file(const std::string &path, World &world);

}  // namespace octoprox
