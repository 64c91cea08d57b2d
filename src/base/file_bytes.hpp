// Whole files read into memory, with errors a user can act on.
#pragma once

#include <string>

namespace octoprox {

// The bytes of the regular file at path.  Throws ApiError(OPX_ERROR_IO)
// naming `what` and the path when it cannot be opened or read, or is a
// directory; std::bad_alloc when it does not fit in memory (never a
// "cannot read" that hides an exhausted heap).
std::string read_file_bytes(const char *path, const char *what);

}  // namespace octoprox
