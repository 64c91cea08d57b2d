#include "robot/mesh_vertices.hpp"

#include <cstring>
#include <unordered_map>

namespace octoprox {

namespace {

using PositionBits = std::array<uint64_t, 3>;

struct PositionHash {
    size_t operator()(const PositionBits &bits) const {
        return std::hash<uint64_t>()(bits[0] * 0x9E3779B97F4A7C15ull ^ bits[1] * 0xC2B2AE3D27D4EB4Full ^ bits[2]);
    }
};

// The bits of a position: equal positions give equal bits.
PositionBits position_bits(const Vec3 &v) {
    PositionBits bits;
    for (int i = 0; i < 3; ++i) {
        const double coordinate = v[i] == 0.0 ? 0.0 : v[i];  // -0 welds with +0
        std::memcpy(&bits[i], &coordinate, sizeof coordinate);
    }
    return bits;
}

}  // namespace

void keep_used_vertices(std::vector<Vec3> &vertices, std::vector<std::array<uint32_t, 3>> &triangles,
                        VertexWeld weld) {
    std::vector<uint32_t> remap(vertices.size(), UINT32_MAX);
    std::unordered_map<PositionBits, uint32_t, PositionHash> welded;
    std::vector<Vec3> used;
    for (auto &triangle : triangles) {
        for (uint32_t &index : triangle) {
            if (remap[index] == UINT32_MAX) {
                const Vec3 &v = vertices[index];
                auto slot = static_cast<uint32_t>(used.size());
                if (weld == VertexWeld::kSamePosition) slot = welded.emplace(position_bits(v), slot).first->second;
                if (slot == used.size()) used.push_back(v);
                remap[index] = slot;
            }
            index = remap[index];
        }
    }
    vertices = std::move(used);
}

}  // namespace octoprox
