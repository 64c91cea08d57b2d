// A plain spatial index over a map's cells, so the brute-force oracle only
// measures the cells near a shape: a hash of buckets (uniform grid) for the
// small cells, and a list of the large ones (unknown cubes can span
// kilometres) that every lookup returns.
#pragma once

#include "oracle_cells.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace oracle {

class CellIndex {
public:
    // bucket: edge of a grid bucket (metres); cells larger than 4 buckets go
    // to the list of large cells.
    CellIndex(std::vector<MapCell> cells, double bucket);

    const std::vector<MapCell> &cells() const { return cells_; }
    // The cell with this key, or nullptr.
    const MapCell *find(const CellKey &key) const;
    // Indices (into cells()) of every cell whose box may overlap [low, high]:
    // a superset, each index once, in increasing order.
    void candidates(const Vec3 &low, const Vec3 &high, std::vector<uint32_t> &out) const;

private:
    int64_t bucket_key(int64_t x, int64_t y, int64_t z) const;
    Eigen::Array3i bucket_of(const Vec3 &p) const;

    std::vector<MapCell> cells_;  // sorted by key
    double bucket_ = 1.0;
    std::unordered_map<int64_t, std::vector<uint32_t>> grid_;
    std::vector<uint32_t> large_;
};

}  // namespace oracle
