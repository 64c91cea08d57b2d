#include "fault_record.hpp"

#include <cstdio>
#include <cstring>

namespace fault {

void Record::add(const char *label, double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    words_.push_back(bits);
    labels_.push_back(label);
}

void Record::add(const char *label, uint64_t value) {
    words_.push_back(value);
    labels_.push_back(label);
}

void Record::add(const char *label, int64_t value) { add(label, static_cast<uint64_t>(value)); }

void Record::add(const char *label, const double *values, size_t count) {
    for (size_t i = 0; i < count; ++i) add(label, values[i]);
}

void Record::add_bytes(const char *label, const void *bytes, size_t count) {
    add(label, static_cast<uint64_t>(count));
    const auto *at = static_cast<const unsigned char *>(bytes);
    for (size_t i = 0; i < count; i += 8) {
        uint64_t word = 0;
        std::memcpy(&word, at + i, count - i < 8 ? count - i : 8);
        add(label, word);
    }
}

void Record::add_text(const char *label, const char *text) {
    add_bytes(label, text, text == nullptr ? 0 : std::strlen(text));
}

std::string Record::first_difference(const Record &other) const {
    const size_t common = words_.size() < other.words_.size() ? words_.size() : other.words_.size();
    char text[256];
    for (size_t i = 0; i < common; ++i) {
        if (words_[i] == other.words_[i]) continue;
        std::snprintf(text, sizeof text, "word %zu (%s): 0x%016llx here, 0x%016llx there", i, labels_[i],
                      static_cast<unsigned long long>(words_[i]),
                      static_cast<unsigned long long>(other.words_[i]));
        return text;
    }
    if (words_.size() == other.words_.size()) return "";
    std::snprintf(text, sizeof text, "%zu words here, %zu there (first extra: %s)", words_.size(),
                  other.words_.size(),
                  words_.size() > common ? labels_[common] : other.labels_[common]);
    return text;
}

}  // namespace fault
