#include "stl_reader.hpp"

#include <cstring>
#include <fstream>
#include <iterator>

namespace oracle {
namespace {

uint32_t read_u32(const unsigned char *p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

float read_f32(const unsigned char *p) {
    const uint32_t bits = read_u32(p);
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

}  // namespace

bool read_binary_stl(const std::string &path, StlMesh &mesh, std::string &error) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        error = "cannot open " + path;
        return false;
    }
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    constexpr size_t kHeader = 84, kRecord = 50;
    if (bytes.size() < kHeader) {
        error = path + ": shorter than an STL header";
        return false;
    }
    const uint32_t count = read_u32(&bytes[80]);
    if (bytes.size() != kHeader + size_t(count) * kRecord) {
        error = path + ": size does not match its triangle count (ASCII STL?)";
        return false;
    }
    mesh = StlMesh();
    for (uint32_t t = 0; t < count; ++t) {
        const unsigned char *record = &bytes[kHeader + size_t(t) * kRecord];
        const uint32_t first = uint32_t(mesh.vertices.size());
        for (int v = 0; v < 3; ++v) {
            const unsigned char *p = record + 12 + 12 * v;  // after the normal
            mesh.vertices.emplace_back(read_f32(p), read_f32(p + 4), read_f32(p + 8));
        }
        mesh.triangles.push_back({first, first + 1, first + 2});
    }
    return true;
}

}  // namespace oracle
