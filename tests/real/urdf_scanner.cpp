#include "urdf_scanner.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace scan {

std::vector<Element> elements(const std::string &xml, const std::string &tag) {
    std::vector<Element> out;
    const std::string start = "<" + tag, end = "</" + tag + ">";
    for (size_t at = xml.find(start); at != std::string::npos; at = xml.find(start, at + 1)) {
        const char next = xml[at + start.size()];
        if (next != ' ' && next != '>' && next != '/' && next != '\n' && next != '\t') continue;
        const size_t close = xml.find('>', at);
        Element e;
        e.open = xml.substr(at, close - at + 1);
        if (xml[close - 1] != '/') {
            const size_t stop = xml.find(end, close);
            if (stop == std::string::npos) throw std::runtime_error("no " + end);
            e.body = xml.substr(close + 1, stop - close - 1);
        }
        out.push_back(e);
    }
    return out;
}

std::string attr(const std::string &open, const std::string &name, const std::string &fallback) {
    const std::string key = " " + name + "=\"";
    const size_t at = open.find(key);
    if (at == std::string::npos) return fallback;
    const size_t from = at + key.size();
    return open.substr(from, open.find('"', from) - from);
}

Eigen::Vector3d vec3(const std::string &text) {
    std::istringstream in(text);
    Eigen::Vector3d v;
    if (!(in >> v.x() >> v.y() >> v.z())) throw std::runtime_error("bad vector '" + text + "'");
    return v;
}

namespace {

Link read_link(const Element &e) {
    Link link;
    link.name = attr(e.open, "name");
    for (const Element &c : elements(e.body, "collision")) {
        for (const char *kind : {"box", "sphere", "cylinder", "mesh"}) {
            const std::vector<Element> found = elements(c.body, kind);
            if (!found.empty()) link.collisions.push_back({kind, attr(found[0].open, "filename")});
        }
    }
    return link;
}

Joint read_joint(const Element &e) {
    Joint j;
    j.name = attr(e.open, "name");
    j.type = attr(e.open, "type");
    j.parent = attr(elements(e.body, "parent").at(0).open, "link");
    j.child = attr(elements(e.body, "child").at(0).open, "link");
    for (const Element &o : elements(e.body, "origin")) {
        j.xyz = vec3(attr(o.open, "xyz", "0 0 0"));
        j.rpy = vec3(attr(o.open, "rpy", "0 0 0"));
    }
    for (const Element &a : elements(e.body, "axis")) j.axis = vec3(attr(a.open, "xyz", "1 0 0"));
    for (const Element &l : elements(e.body, "limit")) {
        j.has_limit = true;
        j.lower = std::stod(attr(l.open, "lower", "0"));
        j.upper = std::stod(attr(l.open, "upper", "0"));
    }
    for (const Element &m : elements(e.body, "mimic")) {
        j.mimic = attr(m.open, "joint");
        j.multiplier = std::stod(attr(m.open, "multiplier", "1"));
        j.offset = std::stod(attr(m.open, "offset", "0"));
    }
    return j;
}

}  // namespace

std::string without_comments(const std::string &xml) {
    std::string out;
    size_t at = 0;
    for (size_t open = xml.find("<!--"); open != std::string::npos; open = xml.find("<!--", at)) {
        out += xml.substr(at, open - at);
        at = xml.find("-->", open) + 3;
    }
    return out + xml.substr(at);
}

Robot read_robot(const std::string &text) {
    const std::string xml = without_comments(text);
    Robot robot;
    for (const Element &e : elements(xml, "link")) robot.links.push_back(read_link(e));
    for (const Element &e : elements(xml, "joint"))
        if (!attr(e.open, "type").empty()) robot.joints.push_back(read_joint(e));  // not a transmission's
    return robot;
}

Eigen::Matrix3d rpy_matrix(const Eigen::Vector3d &rpy) {
    const double cr = std::cos(rpy.x()), sr = std::sin(rpy.x());
    const double cp = std::cos(rpy.y()), sp = std::sin(rpy.y());
    const double cy = std::cos(rpy.z()), sy = std::sin(rpy.z());
    Eigen::Matrix3d rx, ry, rz;  // URDF: R = Rz(yaw) Ry(pitch) Rx(roll)
    rx << 1, 0, 0, 0, cr, -sr, 0, sr, cr;
    ry << cp, 0, sp, 0, 1, 0, -sp, 0, cp;
    rz << cy, -sy, 0, sy, cy, 0, 0, 0, 1;
    return rz * ry * rx;
}

Eigen::Matrix3d axis_angle_matrix(Eigen::Vector3d axis, double angle) {
    axis /= axis.norm();
    Eigen::Matrix3d k;  // Rodrigues: I + sin K + (1 - cos) K^2
    k << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
    return Eigen::Matrix3d::Identity() + std::sin(angle) * k + (1 - std::cos(angle)) * k * k;
}

Eigen::Matrix3d quaternion_matrix(const double q[4]) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    Eigen::Matrix3d r;
    r << 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
        2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
        2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y);
    return r;
}

std::map<std::string, Frame> forward_kinematics(const Robot &robot, const std::map<std::string, double> &values,
                                                const Frame &root) {
    std::map<std::string, const Joint *> parent_joint, by_name;
    for (const Joint &j : robot.joints) parent_joint[j.child] = &j, by_name[j.name] = &j;
    auto value_of = [&](const Joint &j) {
        if (j.type == "fixed") return 0.0;
        if (!j.mimic.empty()) return j.multiplier * values.at(j.mimic) + j.offset;
        return values.at(j.name);
    };
    std::map<std::string, Frame> frames;
    std::function<Frame(const std::string &)> frame_of = [&](const std::string &link) -> Frame {
        const auto known = frames.find(link);
        if (known != frames.end()) return known->second;
        const auto pj = parent_joint.find(link);
        if (pj == parent_joint.end()) return frames[link] = root;
        const Joint &j = *pj->second;
        const Frame parent = frame_of(j.parent);
        Frame f;
        f.rot = parent.rot * rpy_matrix(j.rpy);
        f.pos = parent.rot * j.xyz + parent.pos;
        const double q = value_of(j);
        if (j.type == "revolute" || j.type == "continuous") f.rot = f.rot * axis_angle_matrix(j.axis, q);
        if (j.type == "prismatic") f.pos += f.rot * (q * j.axis / j.axis.norm());
        return frames[link] = f;
    };
    for (const Link &l : robot.links) frame_of(l.name);
    return frames;
}

}  // namespace scan
