#include "oracle_cells.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace oracle {
namespace {

constexpr int kTreeDepth = 16;

double size_at_depth(int depth, double resolution) {
    return std::ldexp(resolution, kTreeDepth - depth);
}

int depth_of_size(double size, double resolution) {
    return kTreeDepth - int(std::lround(std::log2(size / resolution)));
}

void fail(const char *what) {
    std::fprintf(stderr, "FAIL: %s: %s\n", what, opx_last_error());
    std::exit(1);
}

CellKey parent_of(const CellKey &key, int depth) {
    const int shift = key.depth - depth;
    return {depth, key.x >> shift, key.y >> shift, key.z >> shift};  // coordinates are >= 0
}

}  // namespace

CellKey key_of(const double center[3], double size, double resolution) {
    CellKey key;
    key.depth = depth_of_size(size, resolution);
    const double offset = std::ldexp(1.0, key.depth - 1);  // 2^(d-1); 0.5 at the root
    key.x = int64_t(std::floor(center[0] / size + offset));
    key.y = int64_t(std::floor(center[1] / size + offset));
    key.z = int64_t(std::floor(center[2] / size + offset));
    return key;
}

MapCell cell_of_key(const CellKey &key, double resolution) {
    MapCell cell;
    cell.key = key;
    cell.size = size_at_depth(key.depth, resolution);
    const double offset = std::ldexp(1.0, key.depth - 1);
    cell.cell.center = Vec3(double(key.x) + 0.5 - offset, double(key.y) + 0.5 - offset,
                            double(key.z) + 0.5 - offset) * cell.size;
    cell.cell.half = 0.5 * cell.size;
    return cell;
}

MapCell cell_of_leaf(const opx_leaf &leaf, double resolution) {
    // The geometry is the oracle's own (from the key); check_leaves compares
    // it with the reported one.
    MapCell cell = cell_of_key(key_of(leaf.center, leaf.size, resolution), resolution);
    cell.probability = leaf.probability;
    cell.log_odds = float_logit(leaf.probability);
    cell.cell_class = leaf.cell_class;
    return cell;
}

std::vector<opx_leaf> known_leaves(const opx_octree *tree) {
    size_t count = 0;
    opx_status status = opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, nullptr, 0, &count);
    if (status != OPX_OK && status != OPX_ERROR_BUFFER_TOO_SMALL) fail("opx_octree_get_leaves");
    std::vector<opx_leaf> leaves(count);
    if (count > 0 && opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, leaves.data(), count, &count) != OPX_OK)
        fail("opx_octree_get_leaves");
    leaves.resize(count);
    return leaves;
}

opx_octree_options octree_options(const opx_octree *tree) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    if (opx_octree_get_options(tree, &options) != OPX_OK) fail("opx_octree_get_options");
    return options;
}

float float_logit(double p) { return float(std::log(p / (1.0 - p))); }

double probability_of(float log_odds) { return 1.0 - 1.0 / (1.0 + std::exp(double(log_odds))); }

static bool check_leaf_geometry(const opx_leaf &leaf, double resolution) {
    const MapCell cell = cell_of_key(key_of(leaf.center, leaf.size, resolution), resolution);
    const Vec3 center(leaf.center[0], leaf.center[1], leaf.center[2]);
    return cell.size == leaf.size && int(leaf.depth) == cell.key.depth &&
           (cell.cell.center - center).cwiseAbs().maxCoeff() <= 1e-9 * leaf.size;
}

bool check_leaves(const std::vector<opx_leaf> &leaves, const opx_octree_options &options) {
    const float occupied = float_logit(options.occupied_threshold);
    const float free = float_logit(options.free_threshold);
    int failures = 0;
    for (const opx_leaf &leaf : leaves) {
        const float l = float_logit(leaf.probability);
        const int expected = l >= occupied ? OPX_CELL_OCCUPIED : l >= free ? OPX_CELL_UNCERTAIN : OPX_CELL_FREE;
        // The recovered float must be the nearest: its neighbours map farther
        // from p (the reported p may differ from ours in the last bit, as
        // 1/(1+exp(-l)) and 1-1/(1+exp(l)) round differently).
        const double error = std::abs(probability_of(l) - leaf.probability);
        const bool exact = error < std::abs(probability_of(std::nextafter(l, 1e30f)) - leaf.probability) &&
                           error < std::abs(probability_of(std::nextafter(l, -1e30f)) - leaf.probability);
        const bool geometry = check_leaf_geometry(leaf, options.resolution);
        if (exact && geometry && expected == leaf.cell_class) continue;
        if (++failures <= 5)
            std::printf("leaf (%.17g, %.17g, %.17g) size %.17g depth %u (geometry %s) p=%.17g: float "
                        "log-odds %.9g maps back to p=%.17g; class %d, expected %d\n",
                        leaf.center[0], leaf.center[1], leaf.center[2], leaf.size, leaf.depth,
                        geometry ? "ok" : "WRONG", leaf.probability, double(l), probability_of(l),
                        leaf.cell_class, expected);
    }
    return failures == 0;
}

double effective_threshold(double request_threshold, const opx_octree_options &options) {
    return request_threshold > 0.0 ? request_threshold : options.occupied_threshold;
}

std::vector<MapCell> unknown_cubes(const std::vector<opx_leaf> &leaves, double resolution) {
    if (leaves.empty()) return {cell_of_key(CellKey{}, resolution)};
    std::set<CellKey> known, inner;
    for (const opx_leaf &leaf : leaves) {
        const CellKey key = key_of(leaf.center, leaf.size, resolution);
        known.insert(key);
        for (int depth = 0; depth < key.depth; ++depth) inner.insert(parent_of(key, depth));
    }
    std::vector<MapCell> cubes;
    for (const CellKey &node : inner)
        for (int child = 0; child < 8; ++child) {
            const CellKey key{node.depth + 1, 2 * node.x + (child & 1), 2 * node.y + ((child >> 1) & 1),
                              2 * node.z + ((child >> 2) & 1)};
            if (!known.count(key) && !inner.count(key)) cubes.push_back(cell_of_key(key, resolution));
        }
    return cubes;
}

std::vector<MapCell> map_cells(const std::vector<opx_leaf> &leaves, double resolution, bool with_unknown) {
    std::vector<MapCell> cells;
    for (const opx_leaf &leaf : leaves) cells.push_back(cell_of_leaf(leaf, resolution));
    if (!with_unknown) return cells;
    for (const MapCell &cube : unknown_cubes(leaves, resolution)) cells.push_back(cube);
    return cells;
}

}  // namespace oracle
