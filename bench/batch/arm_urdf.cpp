#include "arm_urdf.hpp"

#include <cstdio>

namespace batch_bench {
namespace {

// Joint k (1..7) sits kOffset[k] above link k-1's frame; its axis
// alternates z (pan, roll) and y (lift, flex).
const double kOffset[kArmJoints + 1] = {0.0, 0.15, 0.12, 0.2, 0.12, 0.2, 0.12, 0.1};
const double kLimit = 2.9;  // rad, every joint
// Spheres per link (base and links 1..7): 50 in all.
const int kSpheresPerLink[kArmJoints + 1] = {4, 6, 6, 7, 6, 7, 6, 8};
const double kRadius = 0.055;

std::string format_text(const char *fmt, double a, double b = 0.0, double c = 0.0) {
    char text[512];
    std::snprintf(text, sizeof text, fmt, a, b, c);
    return text;
}

double link_length(int link) { return link < kArmJoints ? kOffset[link + 1] : 0.12; }

std::string joint(int k) {
    char text[512];
    std::snprintf(text, sizeof text,
                  " <joint name=\"joint%d\" type=\"revolute\"><parent link=\"link%d\"/><child link=\"link%d\"/>"
                  "<origin xyz=\"0 0 %g\"/><axis xyz=\"0 %d %d\"/>"
                  "<limit lower=\"%g\" upper=\"%g\" effort=\"1\" velocity=\"1\"/></joint>\n",
                  k, k - 1, k, kOffset[k], k % 2 == 0, k % 2 == 1, -kLimit, kLimit);
    return text;
}

// A cylinder along the link and a sphere at its far end (the joint).
std::string primitive_link(int link) {
    const double length = link_length(link);
    std::string text = " <link name=\"link" + std::to_string(link) + "\">";
    text += format_text("<collision><origin xyz=\"0 0 %g\"/><geometry><cylinder radius=\"0.05\" length=\"%g\"/>"
                        "</geometry></collision>",
                        0.5 * length, length);
    text += format_text("<collision><origin xyz=\"0 0 %g\"/><geometry><sphere radius=\"0.06\"/></geometry>"
                        "</collision>",
                        length);
    if (link == kArmJoints)
        text += "<collision><origin xyz=\"0 0 0.16\"/><geometry><box size=\"0.16 0.05 0.06\"/></geometry></collision>";
    return text + "</link>\n";
}

// Spheres spread evenly along the link.
std::string sphere_link(int link) {
    const double length = link_length(link);
    const int count = kSpheresPerLink[link];
    std::string text = " <link name=\"link" + std::to_string(link) + "\">";
    for (int s = 0; s < count; ++s)
        text += format_text("<collision><origin xyz=\"0 0 %g\"/><geometry><sphere radius=\"%g\"/></geometry>"
                            "</collision>",
                            length * (s + 0.5) / count, kRadius);
    return text + "</link>\n";
}

template <class Link>
std::string arm_urdf(const char *name, Link &&link) {
    std::string text = std::string("<?xml version=\"1.0\"?>\n<robot name=\"") + name + "\">\n";
    for (int l = 0; l <= kArmJoints; ++l) text += link(l);
    for (int k = 1; k <= kArmJoints; ++k) text += joint(k);
    return text + "</robot>\n";
}

}  // namespace

std::string primitive_arm_urdf() { return arm_urdf("arm7", primitive_link); }
std::string sphere_arm_urdf() { return arm_urdf("sphere_arm50", sphere_link); }

std::vector<std::pair<uint32_t, uint32_t>> adjacent_arm_links() {
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t link = 0; link < kArmJoints; ++link) pairs.emplace_back(link, link + 1);
    return pairs;
}

}  // namespace batch_bench
