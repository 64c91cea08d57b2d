#include "robot/urdf_xml.hpp"

#include "capi/error.hpp"

#include <tinyxml.h>

#include <set>

namespace octoprox {
namespace {

const std::set<std::string> kJointTypes = {"revolute", "continuous", "prismatic", "floating", "planar", "fixed"};

[[noreturn]] void fail(const std::string &source, const std::string &what) { throw_corrupt(source + ": " + what); }

std::string attribute(const TiXmlElement *element, const char *name) {
    const char *value = element == nullptr ? nullptr : element->Attribute(name);
    return value == nullptr ? std::string() : std::string(value);
}

std::string where(const TiXmlElement *element) { return "line " + std::to_string(element->Row()); }

const TiXmlElement *parse_root(TiXmlDocument &doc, const std::string &source, const char *root_name) {
    if (doc.Error())
        fail(source, std::string("is not well-formed XML: ") + doc.ErrorDesc() + " (line " +
                         std::to_string(doc.ErrorRow()) + ", column " + std::to_string(doc.ErrorCol()) + ")");
    const TiXmlElement *root = doc.RootElement();
    if (root == nullptr || std::string(root->Value()) != root_name)
        fail(source, std::string("has no <") + root_name + "> root element");
    return root;
}

// The link named by <parent link=...> or <child link=...> of a joint.
std::string joint_link(const TiXmlElement *joint, const char *role, const std::string &name,
                       const std::set<std::string> &links, const std::string &source) {
    const std::string link = attribute(joint->FirstChildElement(role), "link");
    if (link.empty()) fail(source, "joint '" + name + "' (" + where(joint) + ") has no <" + role + " link=...>");
    if (links.count(link) == 0)
        fail(source, "joint '" + name + "' (" + where(joint) + "): " + role + " link '" + link + "' does not exist");
    return link;
}

void check_joint(const TiXmlElement *joint, const std::set<std::string> &links,
                 const std::set<std::string> &joints, const std::string &source) {
    const std::string name = attribute(joint, "name");
    const std::string type = attribute(joint, "type");
    if (kJointTypes.count(type) == 0)
        fail(source, "joint '" + name + "' (" + where(joint) + ") has type '" + type +
                         "', not one of revolute, continuous, prismatic, floating, planar, fixed");
    joint_link(joint, "parent", name, links, source);
    joint_link(joint, "child", name, links, source);
    const TiXmlElement *mimic = joint->FirstChildElement("mimic");
    if (mimic != nullptr && joints.count(attribute(mimic, "joint")) == 0)
        fail(source, "joint '" + name + "' (" + where(joint) + ") mimics joint '" + attribute(mimic, "joint") +
                         "', which does not exist");
}

// Names of the children <tag name=...> of root, in order; each must have a name.
std::vector<std::string> child_names(const TiXmlElement *root, const char *tag, const std::string &source) {
    std::vector<std::string> names;
    for (const TiXmlElement *e = root->FirstChildElement(tag); e != nullptr; e = e->NextSiblingElement(tag)) {
        names.push_back(attribute(e, "name"));
        if (names.back().empty()) fail(source, std::string("a <") + tag + "> (" + where(e) + ") has no name");
    }
    return names;
}

std::vector<std::string> collision_geometry(const TiXmlElement *link) {
    std::vector<std::string> kinds;
    for (const TiXmlElement *c = link->FirstChildElement("collision"); c != nullptr;
         c = c->NextSiblingElement("collision")) {
        const TiXmlElement *geometry = c->FirstChildElement("geometry");
        const TiXmlElement *shape = geometry == nullptr ? nullptr : geometry->FirstChildElement();
        kinds.push_back(shape == nullptr ? std::string() : std::string(shape->Value()));
    }
    return kinds;
}

}  // namespace

UrdfOutline read_urdf_outline(const std::string &xml, const std::string &source) {
    TiXmlDocument doc;
    doc.Parse(xml.c_str());
    const TiXmlElement *robot = parse_root(doc, source, "robot");
    UrdfOutline outline;
    outline.links = child_names(robot, "link", source);
    outline.joints = child_names(robot, "joint", source);
    for (const TiXmlElement *l = robot->FirstChildElement("link"); l != nullptr; l = l->NextSiblingElement("link"))
        outline.collision_geometry.push_back(collision_geometry(l));
    const std::set<std::string> links(outline.links.begin(), outline.links.end());
    const std::set<std::string> joints(outline.joints.begin(), outline.joints.end());
    if (links.size() != outline.links.size()) fail(source, "two links have the same name");
    if (joints.size() != outline.joints.size()) fail(source, "two joints have the same name");
    if (links.empty()) fail(source, "has no <link>");
    for (const TiXmlElement *j = robot->FirstChildElement("joint"); j != nullptr; j = j->NextSiblingElement("joint"))
        check_joint(j, links, joints, source);
    return outline;
}

std::vector<std::pair<std::string, std::string>> read_srdf_disabled_pairs(const std::string &path,
                                                                          const std::string &source) {
    TiXmlDocument doc;
    if (!doc.LoadFile(path.c_str()) && doc.ErrorId() == TiXmlBase::TIXML_ERROR_OPENING_FILE)
        throw ApiError(OPX_ERROR_IO, source + " cannot be read");
    const TiXmlElement *robot = parse_root(doc, source, "robot");
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const TiXmlElement *e = robot->FirstChildElement("disable_collisions"); e != nullptr;
         e = e->NextSiblingElement("disable_collisions")) {
        const std::string a = attribute(e, "link1"), b = attribute(e, "link2");
        if (a.empty() || b.empty()) fail(source, "<disable_collisions> at " + where(e) + " lacks link1 or link2");
        pairs.emplace_back(a, b);
    }
    return pairs;
}

}  // namespace octoprox
