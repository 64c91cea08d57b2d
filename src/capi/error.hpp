// Error reporting of the C ABI: the thread-local message and the guard
// that keeps every C++ exception from crossing the boundary.
#pragma once

#include "base/error.hpp"

#include <octoprox/common.h>

#include <new>
#include <stdexcept>

namespace octoprox::capi {

// Records "function: message" (then detail, when given) as this thread's
// last error and returns status.  It never allocates and never throws, so
// an error raised while memory is short is still reported.
opx_status fail(opx_status status, const char *function, const char *message,
                const char *detail = nullptr) noexcept;

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

}  // namespace octoprox::capi
