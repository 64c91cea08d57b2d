#include "real_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <tuple>

#include <unistd.h>

namespace real {
namespace {

constexpr int kTreeDepth = 16;
constexpr int64_t kKeyCenter = 1 << (kTreeDepth - 1);
// A pruned leaf this many finest cells wide or more would take too long
// to expand; no single sensor frame produces one.
constexpr uint64_t kMaxExpandedCells = 200000000;

uint64_t pack_key(uint64_t kx, uint64_t ky, uint64_t kz) { return kx | (ky << 16) | (kz << 32); }

// Adds the finest cells of a cube (minimum key, width in cells).
void add_cube(FineCells &cells, const int64_t min_key[3], int64_t width, float log_odds) {
    for (int64_t z = 0; z < width; ++z)
        for (int64_t y = 0; y < width; ++y)
            for (int64_t x = 0; x < width; ++x)
                cells[pack_key(min_key[0] + x, min_key[1] + y, min_key[2] + z)] = log_odds;
}

// The float log-odds the library stored, recovered from its probability
// (exact: the round trip through double is far below a float's spacing).
float log_odds_of(double probability) { return static_cast<float>(std::log(probability / (1.0 - probability))); }

double resolution_of(const opx_octree *tree) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    check_ok(opx_octree_get_options(tree, &options), "opx_octree_get_options");
    return options.resolution;
}

// The integer minimum corner of a leaf's cube, from its centre and size.
void leaf_min_key(const opx_leaf &leaf, double res, int64_t min_key[3]) {
    for (int axis = 0; axis < 3; ++axis)
        min_key[axis] = std::llround((leaf.center[axis] - 0.5 * leaf.size) / res) + kKeyCenter;
}

}  // namespace

std::string data_dir() {
    const char *env = std::getenv("OPX_DATA_DIR");
    if (env != nullptr && env[0] != '\0') return env;
    return OPX_DEFAULT_DATA_DIR;
}

std::string require_data_file(const char *relative) {
    const std::string path = data_dir() + "/" + relative;
    if (!std::filesystem::exists(path)) exit_without_data(path);
    return path;
}

bool data_required() {
    const char *env = std::getenv("OPX_REQUIRE_DATA");
    return env != nullptr && std::string(env) == "1";
}

void exit_without_data(const std::string &missing) {
    if (data_required()) {
        std::printf("FAIL: %s not found and OPX_REQUIRE_DATA=1: the shared data is required\n", missing.c_str());
        std::fflush(stdout);
        std::exit(1);
    }
    std::printf("SKIP: %s not found, set OPX_DATA_DIR to the shared data folder\n", missing.c_str());
    std::fflush(stdout);
    std::exit(77);
}

std::string make_temp_dir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "opx-real-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) fail_msg("mkdtemp(%s) failed", pattern.c_str());
    return pattern;
}

void remove_dir(const std::string &path) {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
}

std::vector<unsigned char> read_file_bytes(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail_msg("cannot open %s", path.c_str());
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void check_ok(opx_status status, const char *what) {
    if (status != OPX_OK) fail_msg("%s: %s: %s", what, opx_status_name(status), opx_last_error());
}

opx_octree *new_octree(double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_octree *tree = nullptr;
    check_ok(opx_octree_create(&options, &tree), "opx_octree_create");
    return tree;
}

std::vector<opx_leaf> get_leaves(const opx_octree *tree, uint32_t mask) {
    size_t count = 0;
    const opx_status sizing = opx_octree_get_leaves(tree, mask, nullptr, 0, &count);
    if (sizing != OPX_OK && sizing != OPX_ERROR_BUFFER_TOO_SMALL) check_ok(sizing, "opx_octree_get_leaves (count)");
    std::vector<opx_leaf> leaves(count);
    size_t written = 0;
    check_ok(opx_octree_get_leaves(tree, mask, leaves.data(), leaves.size(), &written), "opx_octree_get_leaves");
    assert_int_equal(written, count);
    return leaves;
}

void sort_leaves(std::vector<opx_leaf> &leaves) {
    std::sort(leaves.begin(), leaves.end(), [](const opx_leaf &a, const opx_leaf &b) {
        return std::tie(a.depth, a.center[0], a.center[1], a.center[2]) <
               std::tie(b.depth, b.center[0], b.center[1], b.center[2]);
    });
}

opx_octree_stats get_stats(const opx_octree *tree) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_ok(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
    return stats;
}

FineCells expand_octoprox(const opx_octree *tree) {
    const double res = resolution_of(tree);
    FineCells cells;
    uint64_t expanded = 0;
    for (const opx_leaf &leaf : get_leaves(tree)) {
        const int64_t width = int64_t{1} << (kTreeDepth - static_cast<int>(leaf.depth));
        expanded += static_cast<uint64_t>(width * width * width);
        if (expanded > kMaxExpandedCells) fail_msg("map too coarse to expand (%llu cells)", (unsigned long long)expanded);
        int64_t min_key[3];
        leaf_min_key(leaf, res, min_key);
        add_cube(cells, min_key, width, log_odds_of(leaf.probability));
    }
    return cells;
}

std::vector<LeafKey> leaf_keys_octoprox(const opx_octree *tree) {
    const double res = resolution_of(tree);
    std::vector<LeafKey> keys;
    for (const opx_leaf &leaf : get_leaves(tree)) {
        int64_t k[3];
        leaf_min_key(leaf, res, k);
        keys.push_back({leaf.depth, pack_key(k[0], k[1], k[2]), log_odds_of(leaf.probability)});
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

std::vector<LeafKey> leaf_keys_octomap(const octomap::OcTree &tree) {
    std::vector<LeafKey> keys;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
        const octomap::OcTreeKey k = it.getIndexKey();
        keys.push_back({it.getDepth(), pack_key(k[0], k[1], k[2]), it->getLogOdds()});
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

FineCells expand_octomap(const octomap::OcTree &tree) {
    FineCells cells;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
        const int64_t width = int64_t{1} << (kTreeDepth - static_cast<int>(it.getDepth()));
        const octomap::OcTreeKey key = it.getIndexKey();  // the cube's minimum corner
        const int64_t min_key[3] = {key[0], key[1], key[2]};
        add_cube(cells, min_key, width, it->getLogOdds());
    }
    return cells;
}

CellComparison compare_cells(const FineCells &octoprox, const FineCells &octomap_cells) {
    CellComparison c;
    for (const auto &[key, value] : octoprox) {
        const auto found = octomap_cells.find(key);
        if (found == octomap_cells.end()) {
            ++c.only_octoprox;
            continue;
        }
        ++c.common;
        if (found->second != value) {
            ++c.value_mismatch;
            if ((found->second >= 0.0f) != (value >= 0.0f)) ++c.class_mismatch;
        }
    }
    c.only_octomap = octomap_cells.size() - c.common;
    return c;
}

void print_comparison(const char *label, const CellComparison &c) {
    std::printf("%-34s common %zu, only octoprox %zu, only octomap %zu, log-odds differ %zu (class %zu)\n",
                label, c.common, c.only_octoprox, c.only_octomap, c.value_mismatch, c.class_mismatch);
}

}  // namespace real
