#include "world/scene_yaml_documents.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace octoprox {
namespace {

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

}  // namespace

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

[[noreturn]] void yaml_too_deep(const std::string &source, const YAML::DeepRecursion &error, int first_line) {
    const SceneWhere at{&source, error.mark.is_null() ? 0 : first_line + error.mark.line + 1, ""};
    scene_fail(at, format("lists and maps nested %d levels deep or more (the YAML reader's limit)",
                          error.depth()));
}

}  // namespace octoprox
