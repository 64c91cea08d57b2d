#include "oracle_index.hpp"

#include <algorithm>
#include <cmath>

namespace oracle {

CellIndex::CellIndex(std::vector<MapCell> cells, double bucket) : cells_(std::move(cells)), bucket_(bucket) {
    std::sort(cells_.begin(), cells_.end(), [](const MapCell &a, const MapCell &b) { return a.key < b.key; });
    for (uint32_t i = 0; i < cells_.size(); ++i) {
        const MapCell &c = cells_[i];
        if (c.size > 4.0 * bucket_) {
            large_.push_back(i);
            continue;
        }
        const Eigen::Array3i low = bucket_of(c.cell.center - Vec3::Constant(c.cell.half));
        const Eigen::Array3i high = bucket_of(c.cell.center + Vec3::Constant(c.cell.half));
        for (int x = low.x(); x <= high.x(); ++x)
            for (int y = low.y(); y <= high.y(); ++y)
                for (int z = low.z(); z <= high.z(); ++z) grid_[bucket_key(x, y, z)].push_back(i);
    }
}

const MapCell *CellIndex::find(const CellKey &key) const {
    const auto it = std::lower_bound(cells_.begin(), cells_.end(), key,
                                     [](const MapCell &c, const CellKey &k) { return c.key < k; });
    return it != cells_.end() && it->key == key ? &*it : nullptr;
}

void CellIndex::candidates(const Vec3 &low, const Vec3 &high, std::vector<uint32_t> &out) const {
    out = large_;
    const Eigen::Array3i from = bucket_of(low), to = bucket_of(high);
    for (int x = from.x(); x <= to.x(); ++x)
        for (int y = from.y(); y <= to.y(); ++y)
            for (int z = from.z(); z <= to.z(); ++z) {
                const auto it = grid_.find(bucket_key(x, y, z));
                if (it != grid_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
            }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

// Buckets are shifted by 2^20 so the three coordinates pack into 21 bits
// each.  (Callers pass bounds grown by a margin, so rounding at a bucket
// border cannot hide a touching cell.)
int64_t CellIndex::bucket_key(int64_t x, int64_t y, int64_t z) const {
    constexpr int64_t kShift = int64_t(1) << 20;
    return ((x + kShift) << 42) | ((y + kShift) << 21) | (z + kShift);
}

Eigen::Array3i CellIndex::bucket_of(const Vec3 &p) const {
    Eigen::Array3i b;
    for (int k = 0; k < 3; ++k) b[k] = int(std::floor(p[k] / bucket_));
    return b;
}

}  // namespace oracle
