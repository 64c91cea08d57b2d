#include "octree/cube_entry.hpp"

#include "broadphase/morton.hpp"

#include <algorithm>

namespace octoprox {
namespace {

constexpr int32_t kMaxKey = 2 * kKeyCenter - 1;
// A box face this close to a cell face (in cells) may lie on either side of
// it after rounding: the cell beyond is taken too.
constexpr double kFaceSlack = 1e-6;

// A coordinate in cells from the map cube's low corner, moved by `slack`
// cells, clamped a little beyond the cube so that truncation is the floor
// and fits an integer.
double cells_from_corner(double coordinate, double cells_per_metre, double slack) {
    const double cells = coordinate * cells_per_metre + (kKeyCenter + slack);
    return std::min(std::max(cells, -2.0), 2.0 * kKeyCenter + 2.0);
}

int32_t floor_cells(double cells) { return static_cast<int32_t>(cells + 2.0) - 2; }

// morton_spread of every byte, computed at compile time: spreading a key
// is then two lookups instead of five shift-and-mask steps (find spreads
// up to six keys for every shape of every distance query).
struct ByteSpreads {
    uint64_t of[256] = {};
    constexpr ByteSpreads() {
        for (uint32_t byte = 0; byte < 256; ++byte)
            for (int bit = 0; bit < 8; ++bit) of[byte] |= static_cast<uint64_t>((byte >> bit) & 1u) << (3 * bit);
    }
};
constexpr ByteSpreads kByteSpreads;
static_assert(kByteSpreads.of[0xFF] == 0x249249u && kByteSpreads.of[0x81] == 0x200001u, "bit i lands in bit 3i");
static_assert(kTreeDepth <= 16, "keys of at most 16 bits");

// morton_spread for a key of at most 16 bits.
uint64_t spread_key(uint32_t key) { return kByteSpreads.of[key & 0xFFu] | (kByteSpreads.of[(key >> 8) & 0xFFu] << 24); }

// The deepest depth whose cubes are at least as wide as the range on every
// axis: the range then meets at most two of them a side.
int entry_depth(const KeyRange &range) {
    int32_t extent = 1;
    for (int axis = 0; axis < 3; ++axis) extent = std::max(extent, range.hi[axis] - range.lo[axis] + 1);
    if (extent == 1) return kTreeDepth;
    const int width_bits = 32 - __builtin_clz(static_cast<uint32_t>(extent - 1));  // 2^width_bits >= extent
    return std::max(kTreeDepth - width_bits, 0);
}

CellKey cube_key(const int32_t lo[3], int shift, int depth) {
    CellKey key;
    const int32_t keep = ~((int32_t{1} << (kTreeDepth - depth)) - 1);
    for (int axis = 0; axis < 3; ++axis) key.key[axis] = static_cast<uint16_t>((lo[axis] << shift) & keep);
    key.depth = depth;
    return key;
}

}  // namespace

CubeEntryFinder::CubeEntryFinder(const OctreeView &view)
    : view_(view), cells_per_metre_(1.0 / view.resolution()) {
    for (Path &path : paths_) path.nodes[0] = view.root();
}

bool CubeEntryFinder::key_range_of(const Aabb &box, KeyRange &range) const {
    for (int axis = 0; axis < 3; ++axis) {
        // Faces within kFaceSlack of a cell face take the cell beyond too.
        const int32_t first = floor_cells(cells_from_corner(box.lo[axis], cells_per_metre_, -kFaceSlack));
        const int32_t last = floor_cells(cells_from_corner(box.hi[axis], cells_per_metre_, kFaceSlack));
        range.lo[axis] = std::max(first, 0);
        range.hi[axis] = std::min(last, kMaxKey);
        if (range.lo[axis] > range.hi[axis]) return false;
    }
    return true;
}

inline OctreeView::NodeRef CubeEntryFinder::node_of(uint64_t code, int depth, int &reached) {
    Path &path = paths_[code >> (3 * (kTreeDepth - 1))];
    // Levels shared with the cached walk: those above its first differing
    // triple.  The | 1 spares a branch for equal codes: their last level
    // then counts as differing, and is walked again.
    const uint64_t differ = (code ^ path.code) | 1u;
    const int first_differing = kTreeDepth - 1 - (63 - __builtin_clzll(differ)) / 3;
    int level = std::min({path.depth, first_differing, depth});
    OctreeView::NodeRef node = path.nodes[level];
    path.code = code;
    for (; level < depth; ++level) {
        if (!view_.has_children(node)) break;
        // Unknown space is a leaf below every threshold here.
        node = view_.child_or_absent(node, static_cast<int>(code >> (3 * (kTreeDepth - 1 - level))) & 7);
        path.nodes[level + 1] = node;
    }
    path.depth = level;
    reached = level;
    return node;
}

// An inner cube whose obstacle cells all lie outside the reach's cells.
bool CubeEntryFinder::beyond_reach(OctreeView::NodeRef node, const int32_t cube[3], int shift,
                                   const KeyRange &range) const {
    if (!view_.has_children(node)) return false;
    const uint32_t packed = view_.packed_obstacle_bounds(node);
    if (packed == 0) return false;  // not known: the whole cube
    const int32_t cube_lo[3] = {cube[0] << shift, cube[1] << shift, cube[2] << shift};
    return !obstacle_cells_meet(packed, cube_lo, shift, range.lo, range.hi);
}

void CubeEntryFinder::find(const Aabb &reach, float threshold, bool use_boxes, CubeEntries &entries) {
    entries.count = 0;
    KeyRange range;
    if (paths_[0].nodes[0] == nullptr || !key_range_of(reach, range)) return;
    const int depth = entry_depth(range);
    const int shift = kTreeDepth - depth;
    int32_t first[3], last[3];
    for (int axis = 0; axis < 3; ++axis) first[axis] = range.lo[axis] >> shift, last[axis] = range.hi[axis] >> shift;
    uint64_t spread[3][2];  // each axis's one or two cube keys, spread for the Morton code
    for (int axis = 0; axis < 3; ++axis)
        for (int32_t k = first[axis]; k <= last[axis]; ++k)
            spread[axis][k - first[axis]] = spread_key(static_cast<uint32_t>(k << shift)) << axis;
    int32_t cube[3];
    for (cube[2] = first[2]; cube[2] <= last[2]; ++cube[2])
        for (cube[1] = first[1]; cube[1] <= last[1]; ++cube[1])
            for (cube[0] = first[0]; cube[0] <= last[0]; ++cube[0]) {
                const uint64_t code = spread[0][cube[0] - first[0]] | spread[1][cube[1] - first[1]] |
                                      spread[2][cube[2] - first[2]];
                int reached = depth;
                const OctreeView::NodeRef node = node_of(code, depth, reached);
                if (view_.log_odds(node) < threshold) continue;
                if (use_boxes && reached == depth && beyond_reach(node, cube, shift, range)) continue;
                bool seen = false;  // a leaf above `depth` holds more than one of the cubes
                for (int k = 0; k < entries.count && reached < depth; ++k) seen |= entries.cells[k].node == node;
                if (seen) continue;
                // Its children are read next, after every entry is bounded:
                // time enough for their lines to arrive.
                if (view_.has_children(node)) view_.prefetch_children(node, 0xFFu);
                const CellKey key = cube_key(cube, shift, reached);
                entries.cells[entries.count++] = OctreeCell{node, key, cell_box(key, view_.resolution())};
            }
}

}  // namespace octoprox
