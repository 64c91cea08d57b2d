#include "robot/resource_paths.hpp"

#include "base/error.hpp"

#include <sys/stat.h>

namespace octoprox {
namespace {

const std::string kPackage = "package://";
const std::string kFile = "file://";

bool starts_with(const std::string &s, const std::string &prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

std::string join(const std::string &dir, const std::string &rest) {
    if (dir.empty()) return rest;
    return dir.back() == '/' ? dir + rest : dir + "/" + rest;
}

std::string last_component(std::string dir) {
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    const size_t slash = dir.rfind('/');
    return slash == std::string::npos ? dir : dir.substr(slash + 1);
}

// "NAME=DIR" when the part before '=' is a plain package name (no '/').
bool split_mapping(const std::string &entry, std::string &name, std::string &dir) {
    const size_t eq = entry.find('=');
    if (eq == std::string::npos || eq == 0 || entry.find('/') < eq) return false;
    name = entry.substr(0, eq), dir = entry.substr(eq + 1);
    return true;
}

// Candidate paths for package://name/rest, in the documented order.
std::vector<std::string> package_candidates(const ResourcePaths &paths, const std::string &name,
                                            const std::string &rest) {
    std::vector<std::string> candidates;
    for (const std::string &entry : paths.package_dirs) {
        std::string mapped_name, dir;
        if (split_mapping(entry, mapped_name, dir)) {
            if (mapped_name == name) candidates.push_back(join(dir, rest));
            continue;
        }
        candidates.push_back(join(join(entry, name), rest));
        if (last_component(entry) == name) candidates.push_back(join(entry, rest));
    }
    return candidates;
}

std::string resolve_package(const ResourcePaths &paths, const std::string &uri) {
    const std::string body = uri.substr(kPackage.size());
    const size_t slash = body.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == body.size())
        throw ApiError(OPX_ERROR_IO, "mesh '" + uri + "' is not package://NAME/path");
    const std::string name = body.substr(0, slash), rest = body.substr(slash + 1);
    const std::vector<std::string> candidates = package_candidates(paths, name, rest);
    for (const std::string &path : candidates)
        if (file_exists(path)) return path;
    const std::string hint = "; a package folder named otherwise is mapped by an entry '" + name + "=DIR'";
    if (candidates.empty())
        throw ApiError(OPX_ERROR_IO, "mesh '" + uri + "': package '" + name +
                                         "' is unknown (options->package_dirs is empty" + hint + ")");
    std::string tried;
    for (const std::string &path : candidates) tried += (tried.empty() ? "" : ", ") + path;
    throw ApiError(OPX_ERROR_IO, "mesh '" + uri + "': package '" + name + "' has no such file (tried " + tried + hint + ")");
}

}  // namespace

bool file_exists(const std::string &path) {
    struct stat info;
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
}

std::string parent_dir(const std::string &path) {
    const size_t slash = path.rfind('/');
    if (slash == std::string::npos) return "";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string resolve_resource(const ResourcePaths &paths, const std::string &uri) {
    if (starts_with(uri, kPackage)) return resolve_package(paths, uri);
    const std::string path = starts_with(uri, kFile) ? uri.substr(kFile.size()) : uri;
    const std::string full = !path.empty() && path[0] == '/' ? path : join(paths.base_dir, path);
    if (!file_exists(full)) throw ApiError(OPX_ERROR_IO, "mesh '" + uri + "': file '" + full + "' cannot be read");
    return full;
}

}  // namespace octoprox
