#include "base/file_bytes.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sys/stat.h>

namespace octoprox {
namespace {

struct FileCloser {
    void operator()(std::FILE *file) const { std::fclose(file); }
};

struct OpenFile {
    std::unique_ptr<std::FILE, FileCloser> file;
    bool regular = false;
    size_t size = 0;  // of a regular file
};

[[noreturn]] void throw_io(const char *what, const char *path, const char *reason) {
    throw ApiError(OPX_ERROR_IO, format("%s '%.300s' cannot be read: %s", what, path, reason));
}

OpenFile open_for_reading(const char *path, const char *what) {
    // A directory opens on Linux and then fails or reads as nothing, which
    // would be reported as malformed content; say what it is.
    struct stat status;
    const bool known = ::stat(path, &status) == 0;
    if (known && S_ISDIR(status.st_mode)) throw_io(what, path, "it is a directory");
    OpenFile out;
    out.file.reset(std::fopen(path, "rb"));
    if (!out.file) throw_io(what, path, std::strerror(errno));
    out.regular = known && S_ISREG(status.st_mode);
    if (out.regular && status.st_size > 0) out.size = static_cast<size_t>(status.st_size);
    return out;
}

// Appends up to `limit` more bytes of the file, fewer at its end.
void append_up_to(const OpenFile &in, std::string &bytes, size_t limit, const char *what, const char *path) {
    char chunk[65536];
    while (limit > 0) {
        const size_t n = std::fread(chunk, 1, std::min(limit, sizeof chunk), in.file.get());
        bytes.append(chunk, n);
        limit -= n;
        if (n == 0) break;
    }
    if (std::ferror(in.file.get())) throw_io(what, path, std::strerror(errno));
}

[[noreturn]] void throw_too_long(const char *what, const char *path, size_t most) {
    throw_corrupt(format("%s '%.300s' is longer than the %zu bytes its header allows", what, path, most));
}

}  // namespace

std::string read_file_bytes(const char *path, const char *what) {
    const OpenFile in = open_for_reading(path, what);
    std::string bytes;
    bytes.reserve(in.size);
    append_up_to(in, bytes, SIZE_MAX, what, path);
    return bytes;
}

std::string read_bounded_file_bytes(const char *path, const char *what, size_t prefix_size, const LengthBound &bound) {
    const OpenFile in = open_for_reading(path, what);
    std::string bytes;
    bytes.reserve(std::min(in.size, prefix_size));
    append_up_to(in, bytes, prefix_size, what, path);
    const size_t most = bound(bytes);
    if (most == SIZE_MAX && !in.regular)
        throw_corrupt(format("%s '%.300s' is no regular file and its header gives no length: it may never end",
                             what, path));
    if (bytes.size() > most || (in.regular && in.size > most)) throw_too_long(what, path, most);
    bytes.reserve(in.size);
    append_up_to(in, bytes, most == SIZE_MAX ? SIZE_MAX : most + 1 - bytes.size(), what, path);
    if (bytes.size() > most) throw_too_long(what, path, most);
    return bytes;
}

}  // namespace octoprox
