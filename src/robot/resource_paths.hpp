// Where the files a URDF names are: package://NAME/rest through a list of
// package directories, file:// URIs, absolute and relative paths.
#pragma once

#include <string>
#include <vector>

namespace octoprox {

struct ResourcePaths {
    // Entries "DIR" or "NAME=DIR" (see robot.h).
    std::vector<std::string> package_dirs;
    // Base of relative paths ("" = the current directory).
    std::string base_dir;
};

bool file_exists(const std::string &path);
// The folder of a file path ("" for a bare file name).
std::string parent_dir(const std::string &path);

// The path of an existing file for `uri`; throws ApiError(OPX_ERROR_IO)
// naming the URI and the places tried.
std::string resolve_resource(const ResourcePaths &paths, const std::string &uri);

}  // namespace octoprox
