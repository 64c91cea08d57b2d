#include "capi/error.hpp"

#include <cstdio>

namespace octoprox::capi {
namespace {
// One message per thread, so concurrent queries on other threads never
// overwrite the message a caller is about to read.  A fixed buffer, not a
// std::string: recording an error must work when the heap is exhausted.
constexpr std::size_t kMessageCapacity = 2048;
thread_local char last_error_message[kMessageCapacity];
}  // namespace

opx_status fail(opx_status status, const char *function, const char *message, const char *detail) noexcept {
    std::snprintf(last_error_message, kMessageCapacity, "%s: %s%s", function, message,
                  detail == nullptr ? "" : detail);
    return status;
}

}  // namespace octoprox::capi

extern "C" OPX_API const char *opx_last_error(void) {
    return octoprox::capi::last_error_message;
}

extern "C" OPX_API const char *opx_status_name(opx_status status) {
    switch (status) {
    case OPX_OK: return "OPX_OK";
    case OPX_ERROR_INVALID_ARGUMENT: return "OPX_ERROR_INVALID_ARGUMENT";
    case OPX_ERROR_OUT_OF_MEMORY: return "OPX_ERROR_OUT_OF_MEMORY";
    case OPX_ERROR_VERSION: return "OPX_ERROR_VERSION";
    case OPX_ERROR_BUFFER_TOO_SMALL: return "OPX_ERROR_BUFFER_TOO_SMALL";
    case OPX_ERROR_UNSUPPORTED: return "OPX_ERROR_UNSUPPORTED";
    case OPX_ERROR_IO: return "OPX_ERROR_IO";
    case OPX_ERROR_CORRUPT: return "OPX_ERROR_CORRUPT";
    case OPX_ERROR_INTERNAL: return "OPX_ERROR_INTERNAL";
    default: return "OPX_UNKNOWN_STATUS";
    }
}
