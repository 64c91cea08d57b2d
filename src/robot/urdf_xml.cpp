#include "robot/urdf_xml.hpp"

#include "base/error.hpp"
#include "robot/resource_paths.hpp"
#include "robot/urdf_elements.hpp"
#include "robot/urdf_tree.hpp"
#include "robot/xml_text.hpp"

#include <tinyxml.h>

#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>

namespace octoprox {
namespace {

const std::set<std::string> kJointTypes = {"revolute", "continuous", "prismatic", "floating", "planar", "fixed"};

[[noreturn]] void fail(const std::string &source, const std::string &what) { throw_corrupt(source + ": " + what); }

std::string attribute(const TiXmlElement *element, const char *name) {
    const char *value = element == nullptr ? nullptr : element->Attribute(name);
    return value == nullptr ? std::string() : std::string(value);
}

std::string where(const TiXmlElement *element) { return "line " + std::to_string(element->Row()); }

// tinyxml reads `text` only once check_xml_text has passed it.
void parse_checked(TiXmlDocument &doc, const std::string &text, const std::string &source) {
    check_xml_text(text, source);
    doc.Parse(text.c_str());
}

const TiXmlElement *parse_root(TiXmlDocument &doc, const std::string &source, const char *root_name) {
    if (doc.Error())
        fail(source, std::string("is not well-formed XML: ") + doc.ErrorDesc() + " (line " +
                         std::to_string(doc.ErrorRow()) + ", column " + std::to_string(doc.ErrorCol()) + ")");
    const TiXmlElement *root = doc.RootElement();
    if (root == nullptr || std::string(root->Value()) != root_name)
        fail(source, std::string("has no <") + root_name + "> root element");
    return root;
}

std::string trimmed(const std::string &text) {
    const char *space = " \t\n\r";
    const size_t begin = text.find_first_not_of(space);
    return begin == std::string::npos ? std::string() : text.substr(begin, text.find_last_not_of(space) + 1 - begin);
}

// URDF 1.0 is the only version urdfdom (and so this library) reads.
void check_version(const TiXmlElement *robot, const std::string &source) {
    const char *version = robot->Attribute("version");
    if (version == nullptr || trimmed(version) == "1.0") return;
    throw ApiError(OPX_ERROR_UNSUPPORTED,
                   source + ": <robot version=\"" + std::string(version).substr(0, 40) + "\"> is not supported (1.0)");
}

using NameIndex = std::unordered_map<std::string, uint32_t>;

// The index of the link named by <parent link=...> or <child link=...>.
uint32_t joint_link(const TiXmlElement *joint, const char *role, const std::string &name, const NameIndex &links,
                    const std::string &source) {
    const std::string link = attribute(joint->FirstChildElement(role), "link");
    if (link.empty()) fail(source, "joint '" + name + "' (" + where(joint) + ") has no <" + role + " link=...>");
    const auto found = links.find(link);
    if (found == links.end())
        fail(source, "joint '" + name + "' (" + where(joint) + "): " + role + " link '" + link + "' does not exist");
    return found->second;
}

TreeJoint check_joint(const TiXmlElement *joint, const NameIndex &links, const NameIndex &joints,
                      const std::string &source) {
    const std::string name = attribute(joint, "name");
    const std::string type = attribute(joint, "type");
    if (kJointTypes.count(type) == 0)
        fail(source, "joint '" + name + "' (" + where(joint) + ") has type '" + type.substr(0, 40) +
                         "', not one of revolute, continuous, prismatic, floating, planar, fixed");
    TreeJoint tree_joint{name, joint_link(joint, "parent", name, links, source),
                         joint_link(joint, "child", name, links, source)};
    const TiXmlElement *mimic = joint->FirstChildElement("mimic");
    if (mimic != nullptr && joints.count(attribute(mimic, "joint")) == 0)
        fail(source, "joint '" + name + "' (" + where(joint) + ") mimics joint '" + attribute(mimic, "joint") +
                         "', which does not exist");
    return tree_joint;
}

// Names of the children <tag name=...> of root, in order, each named
// (with valid UTF-8: urdfdom gets them back as text) and unique.
std::vector<std::string> child_names(const TiXmlElement *root, const char *tag, const std::string &source) {
    std::vector<std::string> names;
    for (const TiXmlElement *e = root->FirstChildElement(tag); e != nullptr; e = e->NextSiblingElement(tag)) {
        names.push_back(attribute(e, "name"));
        if (names.back().empty()) fail(source, std::string("a <") + tag + "> (" + where(e) + ") has no name");
        if (!is_utf8(names.back()))
            fail(source, std::string("a <") + tag + "> (" + where(e) + ") has a name that is not valid UTF-8");
    }
    if (std::set<std::string>(names.begin(), names.end()).size() != names.size())
        fail(source, std::string("two ") + tag + "s have the same name");
    return names;
}

NameIndex index_names(const std::vector<std::string> &names) {
    NameIndex index;
    for (uint32_t i = 0; i < names.size(); ++i) index.emplace(names[i], i);
    return index;
}

std::string robot_start(const TiXmlElement *robot) {
    const std::string name = attribute(robot, "name");
    return "<robot name=\"" + escape_xml(is_utf8(name) && !name.empty() ? name : "robot") + "\">";
}

}  // namespace

UrdfOutline read_urdf_outline(const std::string &xml, const std::string &source) {
    TiXmlDocument doc;
    parse_checked(doc, xml, source);
    const TiXmlElement *robot = parse_root(doc, source, "robot");
    check_version(robot, source);
    UrdfOutline outline;
    outline.links = child_names(robot, "link", source);
    outline.joints = child_names(robot, "joint", source);
    if (outline.links.empty()) fail(source, "has no <link>");
    const NameIndex links = index_names(outline.links), joints = index_names(outline.joints);
    std::vector<TreeJoint> tree;
    for (const TiXmlElement *j = robot->FirstChildElement("joint"); j != nullptr; j = j->NextSiblingElement("joint"))
        tree.push_back(check_joint(j, links, joints, source));
    check_kinematic_tree(outline.links, tree, source);
    std::string &out = outline.checked_xml;
    out = robot_start(robot);
    for (const TiXmlElement *e = robot->FirstChildElement("link"); e != nullptr; e = e->NextSiblingElement("link")) {
        const std::string &name = outline.links[outline.collision_counts.size()];
        outline.collision_counts.push_back(write_checked_link(*e, name, source, out));
    }
    for (const TiXmlElement *j = robot->FirstChildElement("joint"); j != nullptr; j = j->NextSiblingElement("joint"))
        write_checked_joint(*j, source, out);
    out += "</robot>";
    return outline;
}

std::vector<std::pair<std::string, std::string>> read_srdf_disabled_pairs(const std::string &path,
                                                                          const std::string &source) {
    std::ifstream file(path, std::ios::binary);
    if (!file_exists(path) || !file) throw ApiError(OPX_ERROR_IO, source + " cannot be read");
    std::ostringstream text;
    text << file.rdbuf();  // an empty file sets failbit: it is then empty text
    if (file.bad()) throw ApiError(OPX_ERROR_IO, source + " cannot be read");
    TiXmlDocument doc;
    parse_checked(doc, text.str(), source);
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
