// Whole files read into memory, with errors a user can act on.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace octoprox {

// The bytes of the regular file at path.  Throws ApiError(OPX_ERROR_IO)
// naming `what` and the path when it cannot be opened or read, or is a
// directory; std::bad_alloc when it does not fit in memory (never a
// "cannot read" that hides an exhausted heap).
std::string read_file_bytes(const char *path, const char *what);

// The most bytes a whole file may hold, told by its first bytes (all of
// them when the file is shorter than the prefix read): SIZE_MAX for no
// bound.  Throws ApiError(CORRUPT) when those bytes are no valid start.
using LengthBound = std::function<size_t(const std::string &prefix)>;

// A file whose header tells its length (a map file), read header first:
// the first prefix_size bytes, then no more than `bound` allows.  A
// regular file longer than that is refused before its body is read; a
// device or a pipe is read in chunks up to one byte past the bound, and
// one whose header sets no bound is refused (it may never end).  Errors as
// read_file_bytes, and ApiError(CORRUPT) naming `what` and the path for a
// file longer than its bound.
std::string read_bounded_file_bytes(const char *path, const char *what, size_t prefix_size, const LengthBound &bound);

}  // namespace octoprox
