#include "robot/mesh_closure.hpp"

#include <algorithm>

namespace octoprox {

bool mesh_is_closed(const std::vector<std::array<uint32_t, 3>> &triangles) {
    if (triangles.empty()) return false;
    // Every edge once per triangle, as (smaller, larger) index: a closed
    // mesh lists each exactly twice.
    std::vector<uint64_t> edges;
    edges.reserve(3 * triangles.size());
    for (const auto &t : triangles)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            if (a == b) return false;  // a degenerate triangle bounds nothing
            edges.push_back((uint64_t{std::min(a, b)} << 32) | std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i != 2) return false;
        i = j;
    }
    return true;
}

}  // namespace octoprox
