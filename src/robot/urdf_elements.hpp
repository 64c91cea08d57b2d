// The parts of a URDF this library reads (links with their collisions,
// joints), checked value by value and written back as the text urdfdom
// parses.  urdfdom so never sees what it would reject (it reports that on
// stderr only), nor the parts it reads and this library does not (visuals,
// inertials, materials, joint dynamics...), and every number it parses is
// finite, in range and in a form its parser reads in any locale.
#pragma once

#include <cstddef>
#include <string>

class TiXmlElement;

namespace octoprox {

// XML text for an attribute value or element content.
std::string escape_xml(const std::string &text);

// Appends <link name=...> with a <collision> for each of `link`'s, in
// order, and returns their number: <origin xyz rpy> and <geometry> with one <box size>, <sphere
// radius>, <cylinder radius length> or <mesh filename scale>.  Throws
// ApiError prefixed with `source`: OPX_ERROR_UNSUPPORTED for another
// geometry or an origin given by quat_xyzw, OPX_ERROR_CORRUPT for a
// missing, malformed or out of range value.
size_t write_checked_link(const TiXmlElement &link, const std::string &name, const std::string &source,
                        std::string &out);

// Appends <joint name type> with <parent link>, <child link>, <origin>,
// <axis> (moving and planar joints), <limit> (required for revolute and
// prismatic joints) and <mimic>.  The caller has checked the name, type
// and links; throws ApiError(OPX_ERROR_CORRUPT) prefixed with `source`
// for a missing, malformed or out of range value.
void write_checked_joint(const TiXmlElement &joint, const std::string &source, std::string &out);

}  // namespace octoprox
