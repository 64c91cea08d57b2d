// A record of answers as 64-bit words (doubles by their bits), so two runs
// compare bit for bit, with a label per word to say where they differ.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fault {

class Record {
public:
    void add(const char *label, double value);
    void add(const char *label, uint64_t value);
    void add(const char *label, int64_t value);
    void add(const char *label, int32_t value) { add(label, static_cast<int64_t>(value)); }
    void add(const char *label, uint32_t value) { add(label, static_cast<uint64_t>(value)); }
    void add(const char *label, const double *values, size_t count);
    void add_bytes(const char *label, const void *bytes, size_t count);
    void add_text(const char *label, const char *text);

    size_t size() const { return words_.size(); }
    bool operator==(const Record &other) const { return words_ == other.words_; }
    bool operator!=(const Record &other) const { return !(*this == other); }

    // "" when equal, else the first difference, e.g. "word 12 (distance):
    // 0x3fb999999999999a here, 0x3fb999999999999b there".
    std::string first_difference(const Record &other) const;

private:
    std::vector<uint64_t> words_;
    std::vector<const char *> labels_;
};

}  // namespace fault
