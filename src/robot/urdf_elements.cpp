#include "robot/urdf_elements.hpp"

#include "base/error.hpp"
#include "robot/urdf_values.hpp"
#include "robot/xml_text.hpp"

#include <tinyxml.h>

#include <cstdio>
#include <limits>

namespace octoprox {
namespace {

[[noreturn]] void fail(const std::string &what) { throw_corrupt(what); }

std::string attribute(const TiXmlElement &element, const char *name) {
    const char *value = element.Attribute(name);
    return value == nullptr ? std::string() : std::string(value);
}

std::string xml_attribute(const char *name, const std::string &value) {
    return std::string(" ") + name + "=\"" + escape_xml(value) + "\"";
}

// A number of `element`, `fallback` when absent; required when fallback is null.
double number(const TiXmlElement &element, const char *name, const double *fallback, double limit,
              const std::string &what) {
    const char *text = element.Attribute(name);
    if (text == nullptr) {
        if (fallback == nullptr) fail(what + " has no " + name);
        return *fallback;
    }
    const double value = parse_number(text, what + " " + name);
    check_magnitude(value, limit, what + " " + name);
    return value;
}

Vec3Text vector3(const TiXmlElement &element, const char *name, const Vec3Text &fallback, const std::string &what) {
    const char *text = element.Attribute(name);
    if (text == nullptr) return fallback;
    const Vec3Text v = parse_vector3(text, what + " " + name);
    for (double x : v) check_magnitude(x, kMaxUrdfMagnitude, what + " " + name);
    return v;
}

// A length that must be > 0, as the library's shapes need.
std::string positive(double value, const std::string &what) {
    if (!(value > 0.0)) fail(what + " is " + describe_number(value) + ", not > 0");
    return format_number(value);
}

std::string positive_number(const TiXmlElement &shape, const char *name, const std::string &what) {
    return positive(number(shape, name, nullptr, kMaxUrdfMagnitude, what), what + " " + name);
}

// The first <origin>, as urdfdom reads it; "" when there is none.
std::string checked_origin(const TiXmlElement &parent, const std::string &where) {
    const TiXmlElement *origin = parent.FirstChildElement("origin");
    if (origin == nullptr) return "";
    if (origin->Attribute("quat_xyzw") != nullptr)
        throw ApiError(OPX_ERROR_UNSUPPORTED, where + ": <origin quat_xyzw> is not supported (give the rotation as rpy)");
    const Vec3Text zero{0.0, 0.0, 0.0};
    const Vec3Text xyz = vector3(*origin, "xyz", zero, where + " origin");
    const Vec3Text rpy = vector3(*origin, "rpy", zero, where + " origin");
    return "<origin" + xml_attribute("xyz", format_vector3(xyz)) + xml_attribute("rpy", format_vector3(rpy)) + "/>";
}

std::string checked_box(const TiXmlElement &shape, const std::string &what) {
    if (shape.Attribute("size") == nullptr) fail(what + " has no size");
    const Vec3Text size = vector3(shape, "size", {}, what);
    const char *axes[3] = {" size x", " size y", " size z"};
    for (int i = 0; i < 3; ++i) positive(size[i], what + axes[i]);
    return "<box" + xml_attribute("size", format_vector3(size)) + "/>";
}

std::string checked_mesh(const TiXmlElement &shape, const std::string &what) {
    const std::string filename = attribute(shape, "filename");
    if (filename.empty()) fail(what + " has no filename");
    if (!is_utf8(filename)) fail(what + " filename is not valid UTF-8 text");
    const Vec3Text scale = vector3(shape, "scale", {1.0, 1.0, 1.0}, what);
    if (scale[0] == 0.0 || scale[1] == 0.0 || scale[2] == 0.0) fail(what + " scale has a zero factor");
    return "<mesh" + xml_attribute("filename", filename) + xml_attribute("scale", format_vector3(scale)) + "/>";
}

// The first child of the first <geometry>, as urdfdom reads it.
std::string checked_geometry(const TiXmlElement &collision, const std::string &where) {
    const TiXmlElement *geometry = collision.FirstChildElement("geometry");
    if (geometry == nullptr) fail(where + " has no <geometry>");
    const TiXmlElement *shape = geometry->FirstChildElement();
    if (shape == nullptr) fail(where + ": its <geometry> is empty");
    const std::string kind = shape->Value();
    const std::string what = where + " " + kind;
    if (kind == "sphere") return "<sphere" + xml_attribute("radius", positive_number(*shape, "radius", what)) + "/>";
    if (kind == "cylinder")
        return "<cylinder" + xml_attribute("radius", positive_number(*shape, "radius", what)) +
               xml_attribute("length", positive_number(*shape, "length", what)) + "/>";
    if (kind == "box") return checked_box(*shape, what);
    if (kind == "mesh") return checked_mesh(*shape, what);
    throw ApiError(OPX_ERROR_UNSUPPORTED, where + ": geometry <" + kind.substr(0, 40) +
                                              "> is not supported (box, sphere, cylinder, mesh)");
}

// <axis xyz>, read by urdfdom for the joints that have one; an <axis>
// without xyz is a zero axis there, which the joint tree then rejects.
std::string checked_axis(const TiXmlElement &joint, const std::string &type, const std::string &where) {
    const TiXmlElement *axis = joint.FirstChildElement("axis");
    if (axis == nullptr || type == "fixed" || type == "floating") return "";
    const Vec3Text xyz = vector3(*axis, "xyz", {0.0, 0.0, 0.0}, where + " axis");
    return "<axis" + xml_attribute("xyz", format_vector3(xyz)) + "/>";
}

// <limit>: lower and upper default to 0, effort and velocity are required
// (as urdfdom has them); values are reported, not used, so only finite.
std::string checked_limit(const TiXmlElement &joint, const std::string &type, const std::string &where) {
    const TiXmlElement *limit = joint.FirstChildElement("limit");
    if (limit == nullptr) {
        if (type == "revolute" || type == "prismatic") fail(where + " is " + type + " and has no <limit>");
        return "";
    }
    const double zero = 0.0, any = std::numeric_limits<double>::max();
    std::string text = "<limit";
    for (const char *name : {"lower", "upper"})
        text += xml_attribute(name, format_number(number(*limit, name, &zero, any, where + " limit")));
    for (const char *name : {"effort", "velocity"})
        text += xml_attribute(name, format_number(number(*limit, name, nullptr, any, where + " limit")));
    return text + "/>";
}

std::string checked_mimic(const TiXmlElement &joint, const std::string &where) {
    const TiXmlElement *mimic = joint.FirstChildElement("mimic");
    if (mimic == nullptr) return "";
    const double one = 1.0, zero = 0.0;
    const double multiplier = number(*mimic, "multiplier", &one, kMaxUrdfMagnitude, where + " mimic");
    const double offset = number(*mimic, "offset", &zero, kMaxUrdfMagnitude, where + " mimic");
    return "<mimic" + xml_attribute("joint", attribute(*mimic, "joint")) +
           xml_attribute("multiplier", format_number(multiplier)) + xml_attribute("offset", format_number(offset)) +
           "/>";
}

}  // namespace

std::string escape_xml(const std::string &text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20) {
                char reference[8];
                std::snprintf(reference, sizeof reference, "&#x%02X;", static_cast<unsigned>(c));
                out += reference;
            } else {
                out += c;
            }
        }
    }
    return out;
}

size_t write_checked_link(const TiXmlElement &link, const std::string &name, const std::string &source,
                        std::string &out) {
    out += "<link" + xml_attribute("name", name) + ">";
    size_t index = 0;
    for (const TiXmlElement *c = link.FirstChildElement("collision"); c != nullptr;
         c = c->NextSiblingElement("collision"), ++index) {
        const std::string where = source + ": link '" + name + "' collision " + std::to_string(index);
        const std::string origin = checked_origin(*c, where);
        out += "<collision>" + origin + "<geometry>" + checked_geometry(*c, where) + "</geometry></collision>";
    }
    out += "</link>";
    return index;
}

void write_checked_joint(const TiXmlElement &joint, const std::string &source, std::string &out) {
    const std::string name = attribute(joint, "name"), type = attribute(joint, "type");
    const std::string where = source + ": joint '" + name + "'";
    out += "<joint" + xml_attribute("name", name) + xml_attribute("type", type) + ">";
    out += "<parent" + xml_attribute("link", attribute(*joint.FirstChildElement("parent"), "link")) + "/>";
    out += "<child" + xml_attribute("link", attribute(*joint.FirstChildElement("child"), "link")) + "/>";
    out += checked_origin(joint, where);
    out += checked_axis(joint, type, where);
    out += checked_limit(joint, type, where);
    out += checked_mimic(joint, where);
    out += "</joint>";
}

}  // namespace octoprox
