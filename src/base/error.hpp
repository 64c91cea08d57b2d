// The library's error type: code below the C ABI throws ApiError with a
// status code and a message; the C shims' guard (capi/error.hpp) turns it
// into the status and the thread's last error.
#pragma once

#include <octoprox/common.h>

#include <stdexcept>
#include <string>

namespace octoprox {

// Thrown by code below the C ABI to report an error with a status code.
// The shim's guard prefixes the message with the public function's name.
class ApiError : public std::runtime_error {
public:
    ApiError(opx_status status, const std::string &message)
        : std::runtime_error(message), status_(status) {}
    opx_status status() const { return status_; }

private:
    opx_status status_;
};

[[noreturn]] inline void throw_invalid(const std::string &message) {
    throw ApiError(OPX_ERROR_INVALID_ARGUMENT, message);
}
[[noreturn]] inline void throw_corrupt(const std::string &message) {
    throw ApiError(OPX_ERROR_CORRUPT, message);
}

// printf-like formatting into a std::string, for error messages.
std::string format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace octoprox
