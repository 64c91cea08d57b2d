// Which pairs of links self-collision queries check: every pair of two
// different links starts enabled; an SRDF's <disable_collisions> pairs and
// the caller (opx_linkset_set_pair_enabled) disable some.  A symmetric bit
// matrix: one lookup per pair, a few hundred bytes for a hundred links.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace octoprox {

class LinkPairs {
public:
    // Room for `links` links; pairs of new links start enabled.
    void resize(size_t links);
    size_t link_count() const { return links_; }

    // a != b, both below link_count().
    bool enabled(uint32_t a, uint32_t b) const { return (bits_[row(a) + (b >> 6)] >> (b & 63) & 1u) == 0; }
    void set_enabled(uint32_t a, uint32_t b, bool enabled);
    // Pairs of two different links that are disabled.
    size_t disabled_count() const { return disabled_; }

private:
    size_t row(uint32_t link) const { return static_cast<size_t>(link) * words_; }
    void flip(uint32_t a, uint32_t b) { bits_[row(a) + (b >> 6)] ^= uint64_t(1) << (b & 63); }

    size_t links_ = 0;
    size_t words_ = 0;             // 64-bit words per row
    std::vector<uint64_t> bits_;   // bit set: the pair is disabled
    size_t disabled_ = 0;
};

}  // namespace octoprox
