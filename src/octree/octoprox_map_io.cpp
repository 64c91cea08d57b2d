#include "octree/octoprox_map_io.hpp"

#include "base/error.hpp"
#include "octree/octomap_io.hpp"
#include "octree/point_extent.hpp"

#include <cstdint>
#include <cstring>

namespace octoprox {
namespace {

constexpr const char kMagic[] = "# OctoProx map 1\n";

// Reads "<name> <count>\n" at `at`, advancing it.
size_t read_count_line(const std::string &bytes, size_t &at, const char *name) {
    const size_t end = bytes.find('\n', at);
    const std::string prefix = std::string(name) + " ";
    if (end == std::string::npos || bytes.compare(at, prefix.size(), prefix) != 0)
        throw_corrupt(format("OctoProx map: no \"%s\" line", name));
    const std::string digits = bytes.substr(at + prefix.size(), end - at - prefix.size());
    if (digits.empty() || digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
        throw_corrupt(format("OctoProx map: the \"%s\" line has no count", name));
    at = end + 1;
    return static_cast<size_t>(std::stoull(digits));
}

// 0, or valid with lo <= hi on every axis and no stray bits.
bool well_formed(uint32_t packed) {
    if (packed == 0) return true;
    if (!extent::valid(packed) || (packed & (1u << 30)) != 0) return false;
    for (int axis = 0; axis < 3; ++axis)
        if (extent::lo(packed, axis) > extent::hi(packed, axis)) return false;
    return true;
}

}  // namespace

bool is_octoprox_map(const std::string &bytes) { return bytes.compare(0, sizeof kMagic - 1, kMagic) == 0; }

std::unique_ptr<SensorOctree> read_octoprox_map_bytes(const std::string &bytes, OctreeParams params) {
    if (!is_octoprox_map(bytes)) throw_corrupt("not an OctoProx map (no \"# OctoProx map 1\" line)");
    size_t at = sizeof kMagic - 1;
    const size_t ot_size = read_count_line(bytes, at, "ot_bytes");
    if (ot_size > bytes.size() - at) throw_corrupt("OctoProx map: truncated in its .ot part");
    std::unique_ptr<SensorOctree> tree = read_map_file_bytes(bytes.substr(at, ot_size), params);
    at += ot_size;
    const size_t count = read_count_line(bytes, at, "extents");
    if (bytes.size() - at != count * sizeof(uint32_t))
        throw_corrupt(format("OctoProx map: %zu extents announced, %zu bytes follow", count, bytes.size() - at));
    std::vector<uint32_t> extents(count);
    for (size_t i = 0; i < count; ++i) {
        const unsigned char *b = reinterpret_cast<const unsigned char *>(bytes.data() + at + 4 * i);
        extents[i] = uint32_t{b[0]} | uint32_t{b[1]} << 8 | uint32_t{b[2]} << 16 | uint32_t{b[3]} << 24;
        if (!well_formed(extents[i])) throw_corrupt(format("OctoProx map: extent %zu is malformed", i));
    }
    if (!tree->set_leaf_extents(extents))
        throw_corrupt(format("OctoProx map: %zu extents for a map of another leaf count", count));
    return tree;
}

size_t octoprox_map_size_bound(const std::string &prefix) {
    if (!is_octoprox_map(prefix)) throw_corrupt("not an OctoProx map (no \"# OctoProx map 1\" line)");
    size_t at = sizeof kMagic - 1;
    const size_t ot_size = read_count_line(prefix, at, "ot_bytes");
    // An .ot node takes 5 bytes, and every extent is a leaf's: at most
    // ot_size / 5 of them, 4 bytes each, after the "extents" line.
    constexpr size_t kExtentsLine = sizeof "extents " + 18 + 1;
    if (ot_size > (SIZE_MAX - 1 - at - kExtentsLine) / 2) return SIZE_MAX - 1;
    return at + ot_size + kExtentsLine + sizeof(uint32_t) * (ot_size / 5);
}

std::string write_octoprox_map_bytes(const SensorOctree &tree) {
    const std::string ot = write_map_file_bytes(tree, MapFormat::kFull);
    const std::vector<uint32_t> extents = tree.leaf_extents();
    std::string out = kMagic;
    out += "ot_bytes " + std::to_string(ot.size()) + "\n";
    out += ot;
    out += "extents " + std::to_string(extents.size()) + "\n";
    for (const uint32_t e : extents) {
        const char b[4] = {char(e & 0xFF), char((e >> 8) & 0xFF), char((e >> 16) & 0xFF), char(e >> 24)};
        out.append(b, 4);
    }
    return out;
}

}  // namespace octoprox
