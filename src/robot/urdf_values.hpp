// The numbers of a URDF as this library reads them: decimal text in any
// locale, finite, within bounds that keep forward kinematics finite, and
// written back in a form every reader parses to the same double.
#pragma once

#include "base/bounds.hpp"

#include <array>
#include <string>

namespace octoprox {

// Largest magnitude of a length (origin, box size, radius, mesh scale),
// an angle (rpy), an axis component, or a mimic multiplier or offset: the
// library's bound on lengths (base/bounds.hpp), small enough that a
// thousand joints of it stay finite.
constexpr double kMaxUrdfMagnitude = kMaxMetres;

using Vec3Text = std::array<double, 3>;

// `text` as one number: white space around, an optional sign, digits with
// an optional fraction and exponent (no "inf", "nan", hex or commas).
// Throws ApiError(OPX_ERROR_CORRUPT) "`what` 'text' is not a number"
// (or "is out of range" when not finite as a double).
double parse_number(const std::string &text, const std::string &what);

// Three numbers separated by white space.
Vec3Text parse_vector3(const std::string &text, const std::string &what);

// Throws ApiError(OPX_ERROR_CORRUPT) when |value| > limit, naming `what`.
void check_magnitude(double value, double limit, const std::string &what);

// `text` in single quotes for a message, cut to its first 40 bytes.
std::string quoted(const std::string &text);

// The shortest text that reads back as `value`, independent of the locale.
std::string format_number(double value);
std::string format_vector3(const Vec3Text &v);

// `value` for a message: plain digits when short ("2000000"), else the
// shortest form ("1e+300").
std::string describe_number(double value);

}  // namespace octoprox
