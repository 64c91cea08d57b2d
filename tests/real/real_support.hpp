// Helpers of the real-data tests: finding the data, reading leaves, and
// comparing an OctoProx map with an OctoMap tree cell by cell.
#pragma once

#include <octoprox/octoprox.h>

#include <octomap/OcTree.h>

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

// cmocka needs these before its header.
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
extern "C" {
#include <cmocka.h>
}

namespace real {

// The shared data folder: $OPX_DATA_DIR, else the build's default.
std::string data_dir();
// data_dir()/relative, or exit_without_data when the file is absent.
std::string require_data_file(const char *relative);
// Whether OPX_REQUIRE_DATA=1 (CI sets it): absent data then fails a test.
bool data_required();
// Ends a test whose data is absent: prints "SKIP: ..." and exits 77
// (ctest's "skipped"), or with OPX_REQUIRE_DATA=1 prints "FAIL: ..." and
// exits 1.
[[noreturn]] void exit_without_data(const std::string &missing);

// A new empty directory under the system's temporary directory.
std::string make_temp_dir();
void remove_dir(const std::string &path);
std::vector<unsigned char> read_file_bytes(const std::string &path);

// Fails the running cmocka test with the library's message.
void check_ok(opx_status status, const char *what);

// A new empty map of `resolution` metres (fails the running test on error).
opx_octree *new_octree(double resolution);

// Every leaf of the classes in mask, depth first.
std::vector<opx_leaf> get_leaves(const opx_octree *tree, uint32_t mask = OPX_MASK_ALL_KNOWN);
// Leaves in a canonical order (depth, then centre), for comparing maps.
void sort_leaves(std::vector<opx_leaf> &leaves);
opx_octree_stats get_stats(const opx_octree *tree);

// Finest cells (depth 16) of a map: packed key -> float log-odds.  Larger
// (pruned) leaves are expanded into the finest cells they cover, so two
// maps compare equal whatever their pruning.
using FineCells = std::unordered_map<uint64_t, float>;
FineCells expand_octoprox(const opx_octree *tree);
FineCells expand_octomap(const octomap::OcTree &tree);

// Leaves as integer cubes (depth, minimum key), sorted: two maps with the
// same tree structure give equal vectors.  Cheap even for building maps.
struct LeafKey {
    uint32_t depth;
    uint64_t min_key;  // packed x | y << 16 | z << 32, at the finest depth
    float log_odds;
    bool operator<(const LeafKey &o) const { return depth != o.depth ? depth < o.depth : min_key < o.min_key; }
};
std::vector<LeafKey> leaf_keys_octoprox(const opx_octree *tree);
std::vector<LeafKey> leaf_keys_octomap(const octomap::OcTree &tree);

struct CellComparison {
    size_t common = 0;          // cells in both maps
    size_t only_octoprox = 0;   // cells OctoMap does not have
    size_t only_octomap = 0;    // cells OctoProx does not have
    size_t value_mismatch = 0;  // common cells with different log-odds
    size_t class_mismatch = 0;  // ... of which the occupied/free class differs
    bool identical() const { return only_octoprox == 0 && only_octomap == 0 && value_mismatch == 0; }
};
CellComparison compare_cells(const FineCells &octoprox, const FineCells &octomap_cells);
void print_comparison(const char *label, const CellComparison &c);

}  // namespace real
