// Argument checks shared by the shims: versioned structs, pointers, finite
// numbers and poses.  Each throws ApiError(OPX_ERROR_*) with a message that
// names the argument; the guard adds the function's name.
#pragma once

#include "capi/error.hpp"
#include "geometry/pose.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace octoprox::capi {

inline void require_pointer(const void *pointer, const char *argument) {
    if (pointer == nullptr) throw_invalid(format("%s is NULL", argument));
}

inline void require_finite(double value, const char *argument) {
    if (!std::isfinite(value)) throw_invalid(format("%s is %g, not a finite number", argument, value));
}

inline void require_struct_size(uint32_t struct_size, const char *argument) {
    if (struct_size < sizeof(uint32_t))
        throw ApiError(OPX_ERROR_VERSION,
                       format("%s->struct_size is %u; initialise the struct with its _INIT macro "
                              "or _init function",
                              argument, struct_size));
}

// A caller's versioned result struct: not NULL, its struct_size set.
// Shims check it before any work, so a bad one costs no query.
template <class T>
void require_out_struct(const T *out, const char *argument) {
    require_pointer(out, argument);
    require_struct_size(out->struct_size, argument);
}

// Reads a caller's versioned struct over the defaults already in `out`:
// only the fields the caller's version knows are taken.  in may be NULL
// (defaults kept).
template <class T>
void read_versioned(const T *in, T &out, const char *argument) {
    if (in == nullptr) return;
    require_struct_size(in->struct_size, argument);
    std::memcpy(&out, in, std::min<size_t>(in->struct_size, sizeof(T)));
    out.struct_size = sizeof(T);
}

// Writes a result into a caller's versioned struct, no further than its
// struct_size, which is kept.
template <class T>
void write_versioned(T *out, const T &value, const char *argument) {
    require_out_struct(out, argument);
    const uint32_t caller_size = out->struct_size;
    std::memcpy(out, &value, std::min<size_t>(caller_size, sizeof(T)));
    out->struct_size = caller_size;
}

// The body of every opx_x_init(ptr, size): defaults up to size bytes.
template <class T>
void init_versioned(T *out, size_t size, const T &defaults, const char *argument) {
    require_pointer(out, argument);
    if (size < sizeof(uint32_t))
        throw ApiError(OPX_ERROR_VERSION, format("size %zu is too small for %s", size, argument));
    const size_t n = std::min(size, sizeof(T));
    std::memcpy(out, &defaults, n);
    out->struct_size = static_cast<uint32_t>(n);
}

// The whole body of every opx_x_init(ptr, size) function.
template <class T>
opx_status init_struct(const char *function, T *out, size_t size, const T &defaults, const char *argument) noexcept {
    return guard(function, [&] {
        init_versioned(out, size, defaults, argument);
        return OPX_OK;
    });
}

// Joint positions beyond this (radians or metres) are refused: a mimic
// joint scales its master's value by up to 1e12, and the poses must stay
// far from overflow in every distance computation.
constexpr double kMaxJointPosition = 1e6;

inline bool joint_position_in_range(double value) { return std::fabs(value) <= kMaxJointPosition; }  // false for NaN

[[noreturn]] inline void reject_joint_position(double value, const char *argument) {
    throw_invalid(format("%s is %g; a joint position is a finite number within +-%g (rad or m)", argument, value,
                         kMaxJointPosition));
}

// A pose from the ABI, checked: finite, non-zero quaternion (normalised).
Pose read_pose(const opx_pose &pose, const char *argument);

// What read_pose accepts, without a message.
bool pose_is_valid(const opx_pose &pose);

// read_pose for an element of an array, whose argument name ("poses[12]")
// `name()` formats only when the pose is bad: a robot's 95 poses per
// configuration must not cost 95 formatted strings.
template <class Name>
Pose read_pose_lazily(const opx_pose &pose, Name &&name) {
    if (pose_is_valid(pose)) return pose_from_ros(pose.position, pose.orientation);
    return read_pose(pose, name().c_str());
}

// A list handed out (the opx_*_get_* functions with a capacity):
// *out_count gets its length whatever follows; a capacity below it is
// OPX_ERROR_BUFFER_TOO_SMALL (`what` names the length, e.g. "joint
// count"), and `out` (named `argument`) may be null for an empty list only.
template <class T>
void copy_list_out(const std::vector<T> &values, T *out, size_t capacity, size_t *out_count, const char *argument,
                   const char *what) {
    require_pointer(out_count, "out_count");
    *out_count = values.size();
    if (capacity < values.size())
        throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                       format("capacity %zu is smaller than the %s %zu", capacity, what, values.size()));
    if (!values.empty()) require_pointer(out, argument);
    std::copy(values.begin(), values.end(), out);
}

}  // namespace octoprox::capi
