#include "robot/link_pairs.hpp"

namespace octoprox {

// Rows are re-laid only when a row needs another word.
void LinkPairs::resize(size_t links) {
    const size_t words = (links + 63) / 64;
    if (words != words_) {
        std::vector<uint64_t> bits(links * words, 0);
        for (size_t a = 0; a < links_; ++a)
            for (size_t w = 0; w < words_; ++w) bits[a * words + w] = bits_[a * words_ + w];
        bits_.swap(bits);
        words_ = words;
    } else {
        bits_.resize(links * words, 0);
    }
    links_ = links;
}

void LinkPairs::set_enabled(uint32_t a, uint32_t b, bool enabled) {
    if (this->enabled(a, b) == enabled) return;
    flip(a, b), flip(b, a);
    disabled_ = enabled ? disabled_ - 1 : disabled_ + 1;
}

}  // namespace octoprox
