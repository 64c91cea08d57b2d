#include "base/file_bytes.hpp"

#include "base/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

namespace octoprox {
namespace {

struct FileCloser {
    void operator()(std::FILE *file) const { std::fclose(file); }
};

[[noreturn]] void throw_io(const char *what, const char *path, const char *reason) {
    throw ApiError(OPX_ERROR_IO, format("%s '%.300s' cannot be read: %s", what, path, reason));
}

}  // namespace

std::string read_file_bytes(const char *path, const char *what) {
    // A directory opens on Linux and then fails or reads as nothing, which
    // would be reported as malformed content; say what it is.
    struct stat status;
    const bool known = ::stat(path, &status) == 0;
    if (known && S_ISDIR(status.st_mode)) throw_io(what, path, "it is a directory");
    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path, "rb"));
    if (!file) throw_io(what, path, std::strerror(errno));
    std::string bytes;
    if (known && S_ISREG(status.st_mode) && status.st_size > 0) bytes.reserve(static_cast<size_t>(status.st_size));
    char chunk[65536];
    size_t n;
    while ((n = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) bytes.append(chunk, n);
    if (std::ferror(file.get())) throw_io(what, path, std::strerror(errno));
    return bytes;
}

}  // namespace octoprox
