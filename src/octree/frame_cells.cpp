#include "octree/frame_cells.hpp"

#include "base/parallel.hpp"
#include "broadphase/morton.hpp"
#include "broadphase/radix_sort.hpp"

#include <algorithm>
#include <array>

namespace octoprox {
namespace {

constexpr int kBrickCodeBits = 3 * (16 - brick::kShift);
// Below this many bricks a frame's cells are read out on one thread.
constexpr size_t kBricksPerThread = 2048;

// A brick's bits in the marks are x + 8 y + 64 z; the map's order inside
// the brick is the Morton order of (x, y, z).
const std::array<uint16_t, brick::kBits> &morton_of_local() {
    static const std::array<uint16_t, brick::kBits> table = [] {
        std::array<uint16_t, brick::kBits> t{};
        for (uint32_t local = 0; local < brick::kBits; ++local)
            t[local] = static_cast<uint16_t>(morton_encode(local & 7, (local >> 3) & 7, local >> 6));
        return t;
    }();
    return table;
}

void to_morton_order(const uint64_t *linear, uint64_t out[brick::kWords]) {
    const auto &table = morton_of_local();
    std::fill(out, out + brick::kWords, 0);
    for (int w = 0; w < brick::kWords; ++w)
        for (uint64_t bits = linear[w]; bits != 0; bits &= bits - 1) {
            const uint32_t m = table[w * 64 + __builtin_ctzll(bits)];
            out[m >> 6] |= uint64_t{1} << (m & 63);
        }
}

bool is_empty(const uint64_t *words) {
    uint64_t any = 0;
    for (int w = 0; w < brick::kWords; ++w) any |= words[w];
    return any == 0;
}

// For each axis and coordinate 0..7 inside a brick, the Morton-ordered
// bits of the cells with that coordinate.
using PlaneMasks = std::array<std::array<std::array<uint64_t, brick::kWords>, 8>, 3>;

const PlaneMasks &plane_masks() {
    static const PlaneMasks masks = [] {
        PlaneMasks m{};
        for (uint32_t z = 0; z < 8; ++z)
            for (uint32_t y = 0; y < 8; ++y)
                for (uint32_t x = 0; x < 8; ++x) {
                    const uint64_t bit = morton_encode(x, y, z);
                    const uint32_t coordinate[3] = {x, y, z};
                    for (int axis = 0; axis < 3; ++axis)
                        m[axis][coordinate[axis]][bit >> 6] |= uint64_t{1} << (bit & 63);
                }
        return m;
    }();
    return masks;
}

bool any_in_plane(const uint64_t bits[brick::kWords], int axis, uint32_t coordinate) {
    const auto &mask = plane_masks()[axis][coordinate];
    uint64_t any = 0;
    for (int w = 0; w < brick::kWords; ++w) any |= bits[w] & mask[w];
    return any != 0;
}

// Grows the box by a brick's cells (Morton-ordered bits, at least one
// set), looking inside the brick only on an axis where it could move a
// face of the box.
void grow_by_brick(KeyBox &box, uint64_t brick_code, const uint64_t bits[brick::kWords]) {
    uint32_t corner[3];
    morton_decode(brick_code, corner[0], corner[1], corner[2]);
    uint32_t lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
        uint32_t first = 0, last = brick::kMask;
        const uint32_t base = corner[axis] << brick::kShift;
        if (box.empty || base < box.lo[axis])
            while (!any_in_plane(bits, axis, first)) ++first;
        if (box.empty || base + brick::kMask > box.hi[axis])
            while (!any_in_plane(bits, axis, last)) --last;
        lo[axis] = base + first;
        hi[axis] = base + last;
    }
    box.grow(lo);
    box.grow(hi);
}

// A brick's two kinds of marks, in brick order.
struct BrickMarks {
    BrickMarks(const FrameMarks &marks, size_t index) {
        marks.crossed_brick(index, crossed);
        marks.endpoint_brick(index, endpoint);
    }
    uint64_t crossed[brick::kWords], endpoint[brick::kWords];
};

// One thread's share of the cells: its bricks' cells written from `out`
// on, its counts and box.
struct EmitPart {
    uint64_t *out = nullptr;
    uint64_t hits = 0, misses = 0;
    KeyBox box;
};

// Emits one brick's cells in Morton order and grows the box by them.
void emit_brick(uint64_t brick_code, const uint64_t *crossed, const uint64_t *endpoint, EmitPart &part) {
    uint64_t hit[brick::kWords], any[brick::kWords];
    to_morton_order(endpoint, hit);
    to_morton_order(crossed, any);
    for (int w = 0; w < brick::kWords; ++w) {
        any[w] |= hit[w];
        for (uint64_t bits = any[w]; bits != 0; bits &= bits - 1) {
            const int b = __builtin_ctzll(bits);
            const uint64_t code = (brick_code << 9) | static_cast<uint64_t>(w * 64 + b);
            const bool is_hit = (hit[w] >> b) & 1;
            *part.out++ = is_hit ? code | FrameCells::kHitBit : code;
            ++(is_hit ? part.hits : part.misses);
        }
    }
    grow_by_brick(part.box, brick_code, any);
}

size_t cells_in_brick(const uint64_t *crossed, const uint64_t *endpoint) {
    size_t count = 0;
    for (int w = 0; w < brick::kWords; ++w) count += static_cast<size_t>(__builtin_popcountll(crossed[w] | endpoint[w]));
    return count;
}

// The bricks' cells, in the order of `codes`, into `out`: the bricks split
// in `threads` runs, each run's place in `out` known from its cell count.
void emit_bricks(const FrameMarks &marks, const std::vector<uint64_t> &codes, const std::vector<uint32_t> &bricks,
                 size_t threads, FrameCells &out) {
    std::vector<size_t> first_cell(codes.size() + 1, 0);
    for (size_t i = 0; i < codes.size(); ++i) {
        BrickMarks brick(marks, bricks[i]);
        first_cell[i + 1] = first_cell[i] + cells_in_brick(brick.crossed, brick.endpoint);
    }
    out.cells.resize(first_cell.back());
    std::vector<EmitPart> parts(threads);
    run_tasks(threads, [&](size_t t) {
        const size_t begin = codes.size() * t / threads, end = codes.size() * (t + 1) / threads;
        EmitPart &part = parts[t];
        part.out = out.cells.data() + first_cell[begin];
        for (size_t i = begin; i < end; ++i) {
            BrickMarks brick(marks, bricks[i]);
            emit_brick(codes[i], brick.crossed, brick.endpoint, part);
        }
    });
    for (const EmitPart &part : parts) {
        out.hits += part.hits;
        out.misses += part.misses;
        if (!part.box.empty) out.box.grow(part.box);
    }
}

// Cells found outside the marks join the sorted list: sorted, merged with
// it, and each cell kept once (an endpoint wins).
void merge_extra(FrameCells &out, std::vector<uint64_t> extra) {
    if (extra.empty()) return;
    for (const uint64_t cell : extra) {
        uint32_t key[3];
        morton_decode(FrameCells::code(cell), key[0], key[1], key[2]);
        out.box.grow(key);
    }
    extra.insert(extra.end(), out.cells.begin(), out.cells.end());
    std::sort(extra.begin(), extra.end(), [](uint64_t a, uint64_t b) {
        return FrameCells::code(a) != FrameCells::code(b) ? FrameCells::code(a) < FrameCells::code(b) : a > b;
    });
    out.cells.clear();
    out.hits = out.misses = 0;
    for (const uint64_t cell : extra) {
        if (!out.cells.empty() && FrameCells::code(out.cells.back()) == FrameCells::code(cell)) continue;
        out.cells.push_back(cell);
        ++(FrameCells::is_hit(cell) ? out.hits : out.misses);
    }
}

}  // namespace

FrameCells collect_cells(const FrameMarks &marks, std::vector<uint64_t> extra, size_t threads) {
    // The non-empty bricks, by the Morton code of their corner.
    std::vector<uint64_t> codes;
    std::vector<uint32_t> bricks;
    const uint32_t *n = marks.bricks_per_axis();
    const uint32_t *lo = marks.lowest_key();
    size_t index = 0;
    for (uint32_t z = 0; z < n[2]; ++z)
        for (uint32_t y = 0; y < n[1]; ++y)
            for (uint32_t x = 0; x < n[0]; ++x, ++index) {
                BrickMarks brick(marks, index);
                if (is_empty(brick.crossed) && is_empty(brick.endpoint)) continue;
                codes.push_back(morton_encode((lo[0] >> brick::kShift) + x, (lo[1] >> brick::kShift) + y,
                                              (lo[2] >> brick::kShift) + z));
                bricks.push_back(static_cast<uint32_t>(index));
            }
    RadixScratch scratch;
    RadixSortOptions options;
    options.key_bits = kBrickCodeBits;
    radix_sort(codes, bricks, scratch, options);

    FrameCells out;
    emit_bricks(marks, codes, bricks, task_count(threads, codes.size() / kBricksPerThread + 1), out);
    merge_extra(out, std::move(extra));
    return out;
}

void add_clear_cells(FrameCells &out, const std::vector<uint64_t> &clear) {
    if (clear.empty()) return;
    std::vector<uint64_t> sorted(clear);
    std::sort(sorted.begin(), sorted.end());
    std::vector<uint64_t, UninitializedAllocator<uint64_t>> merged;
    merged.reserve(out.cells.size() + sorted.size());
    size_t i = 0;
    for (const uint64_t code : sorted) {
        for (; i < out.cells.size() && FrameCells::code(out.cells[i]) < code; ++i) merged.push_back(out.cells[i]);
        const bool same = i < out.cells.size() && FrameCells::code(out.cells[i]) == code;
        if (same && FrameCells::is_hit(out.cells[i])) {
            merged.push_back(out.cells[i++]);
            continue;
        }
        if (same) --out.misses, ++i;
        merged.push_back(code | FrameCells::kClearBit);
        ++out.cleared;
        uint32_t key[3];
        morton_decode(code, key[0], key[1], key[2]);
        out.box.grow(key);
    }
    merged.insert(merged.end(), out.cells.begin() + static_cast<std::ptrdiff_t>(i), out.cells.end());
    out.cells.swap(merged);
}

FrameCells sorted_cells(std::vector<uint64_t> cells) {
    FrameCells out;
    merge_extra(out, std::move(cells));
    return out;
}

void clip_cells(FrameCells &cells, const CellRange &bounds) {
    size_t kept = 0;
    struct {
        uint64_t hits = 0, misses = 0, cleared = 0;
    } counts;
    KeyBox box;
    for (const uint64_t cell : cells.cells) {
        uint32_t key[3];
        morton_decode(FrameCells::code(cell), key[0], key[1], key[2]);
        if (!bounds.contains(key)) continue;
        cells.cells[kept++] = cell;
        box.grow(key);
        if (FrameCells::is_hit(cell)) ++counts.hits;
        else if (FrameCells::is_clear(cell)) ++counts.cleared;
        else ++counts.misses;
    }
    cells.cells.resize(kept);
    cells.hits = counts.hits;
    cells.misses = counts.misses;
    cells.cleared = counts.cleared;
    cells.box = box;
}

}  // namespace octoprox
