// Error reporting of the C ABI: the thread-local message, the exception
// types that deep code throws, and the guard that keeps every C++ exception
// from crossing the boundary.
#pragma once

#include <octoprox/common.h>

#include <new>
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

namespace capi {

// Records "function: message" (then detail, when given) as this thread's
// last error and returns status.  It never allocates and never throws, so
// an error raised while memory is short is still reported.
opx_status fail(opx_status status, const char *function, const char *message,
                const char *detail = nullptr) noexcept;

// printf-like formatting into a std::string, for error messages.
std::string format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

// Runs body (returning opx_status) and maps any exception to a status and a
// message naming the function.
template <class Body>
opx_status guard(const char *function, Body &&body) noexcept {
    try {
        return body();
    } catch (const ApiError &error) {
        return fail(error.status(), function, error.what());
    } catch (const std::bad_alloc &) {
        return fail(OPX_ERROR_OUT_OF_MEMORY, function, "out of memory");
    } catch (const std::exception &error) {
        return fail(OPX_ERROR_INTERNAL, function, "internal error: ", error.what());
    } catch (...) {
        return fail(OPX_ERROR_INTERNAL, function, "internal error: unknown exception");
    }
}

}  // namespace capi
}  // namespace octoprox
