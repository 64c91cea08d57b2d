#include "octree/frame_marks.hpp"

#include <algorithm>
#include <cstdlib>
#include <new>

namespace octoprox {
namespace {

constexpr uint32_t kMaxKey = 65535;  // OctoMap's 16-bit keys

}  // namespace

void KeyBox::grow(const KeyBox &other) {
    if (other.empty) return;
    grow(other.lo);
    grow(other.hi);
}

KeyBox KeyBox::padded(uint32_t cells) const {
    KeyBox out = *this;
    if (empty) return out;
    for (int axis = 0; axis < 3; ++axis) {
        out.lo[axis] = lo[axis] > cells ? lo[axis] - cells : 0;
        out.hi[axis] = std::min(kMaxKey, hi[axis] + cells);
    }
    return out;
}

uint64_t KeyBox::volume() const {
    if (empty) return 0;
    uint64_t cells = 1;
    for (int axis = 0; axis < 3; ++axis) cells *= uint64_t{hi[axis] - lo[axis]} + 1;
    return cells;
}

void FrameMarks::reset(const KeyBox &box, Layout layout) {
    for (int axis = 0; axis < 3; ++axis) {
        lo_[axis] = box.empty ? 0 : box.lo[axis] & ~brick::kMask;
        bricks_[axis] = box.empty ? 0 : ((box.hi[axis] - lo_[axis]) >> brick::kShift) + 1;
    }
    brick_stride_[0] = 1;
    brick_stride_[1] = bricks_[0];
    brick_stride_[2] = int64_t{bricks_[0]} * bricks_[1];
    words_ = brick_count() * brick::kWords;
    in_rows_ = layout == Layout::kRows || (layout == Layout::kBest && uint64_t{words_} * 64 <= kRowsMaxCells);
    for (int axis = 0; axis < 3; ++axis) cell_stride_[axis] = brick_stride_[axis] << (brick::kShift * axis);
    crossed_.reset();
    endpoint_.reset();
    crossed_ = cleared_words(words_);
}

void FrameMarks::add_endpoint_marks() { endpoint_ = cleared_words(words_); }

std::unique_ptr<uint64_t[], FrameMarks::FreeWords> FrameMarks::cleared_words(size_t words) {
    std::unique_ptr<uint64_t[], FreeWords> out(
        static_cast<uint64_t *>(std::calloc(std::max<size_t>(words, 1), sizeof(uint64_t))));
    if (out == nullptr) throw std::bad_alloc();
    return out;
}

void FrameMarks::FreeWords::operator()(uint64_t *words) const { std::free(words); }

void FrameMarks::brick_words(const uint64_t *marks, size_t brick_index, uint64_t out[brick::kWords]) const {
    if (!in_rows_) {
        std::copy(marks + brick_index * brick::kWords, marks + (brick_index + 1) * brick::kWords, out);
        return;
    }
    // In rows, a brick's 8 cells along x are 8 bits of one word: X is a
    // whole number of bricks.
    const size_t x = brick_index % bricks_[0], y = brick_index / bricks_[0] % bricks_[1];
    const size_t z = brick_index / brick_stride_[2];
    for (size_t dz = 0; dz < 8; ++dz) {
        uint64_t word = 0;
        for (size_t dy = 0; dy < 8; ++dy) {
            const size_t bit = 8 * x + cell_stride_[1] * (8 * y + dy) + cell_stride_[2] * (8 * z + dz);
            word |= (marks[bit / 64] >> (bit % 64) & 0xFF) << (8 * dy);
        }
        out[dz] = word;
    }
}

void FrameMarks::merge_crossed(const FrameMarks &other) {
    for (size_t i = 0; i < words_; ++i) crossed_[i] |= other.crossed_[i];
}

}  // namespace octoprox
