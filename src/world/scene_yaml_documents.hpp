// The documents of a planning scene YAML text, cut at its "---" markers,
// and yaml-cpp's errors as scene errors (file, line, what).
#pragma once

#include "world/scene_update.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace octoprox {

// A document of the text: from a "---" line (or the start) to the next.
struct YamlPiece {
    std::string text;
    int first_line = 0;  // 0-based, in the whole text
    bool has_content = false;  // more than markers, comments and blanks
};

// yaml-cpp 0.7's LoadAll can loop for ever, allocating, on malformed
// input (a line starting with ','), so each document is parsed alone with
// Load, the text cut at the "---" markers (which YAML does not allow at
// the start of a line inside content).
std::vector<YamlPiece> split_documents(const std::string &text);

[[noreturn]] void yaml_fail(const std::string &source, const YAML::Exception &error, int first_line, const char *what);

// yaml-cpp refuses lists and maps nested beyond its parser's limit (500
// levels in Debian's build) with the message "bad file"; say what it is.
[[noreturn]] void yaml_too_deep(const std::string &source, const YAML::DeepRecursion &error, int first_line);

}  // namespace octoprox
