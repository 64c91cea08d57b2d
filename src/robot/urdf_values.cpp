#include "robot/urdf_values.hpp"

#include "base/error.hpp"

#include <charconv>
#include <cmath>
#include <vector>

namespace octoprox {
namespace {

bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

size_t skip_digits(const std::string &s, size_t i) {
    while (i < s.size() && is_digit(s[i])) ++i;
    return i;
}

// End of the decimal number starting at `begin` (sign, digits, fraction,
// exponent), or `begin` when there is none.
size_t decimal_end(const std::string &s, size_t begin) {
    size_t i = begin;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const size_t integer_end = skip_digits(s, i);
    size_t end = integer_end;
    bool has_digits = integer_end > i;
    if (end < s.size() && s[end] == '.') {
        end = skip_digits(s, end + 1);
        has_digits = has_digits || end > integer_end + 1;
    }
    if (!has_digits) return begin;
    if (end < s.size() && (s[end] == 'e' || s[end] == 'E')) {
        size_t exponent = end + 1;
        if (exponent < s.size() && (s[exponent] == '+' || s[exponent] == '-')) ++exponent;
        const size_t exponent_end = skip_digits(s, exponent);
        if (exponent_end == exponent) return begin;
        end = exponent_end;
    }
    return end;
}

std::vector<std::string> split_words(const std::string &text) {
    std::vector<std::string> words;
    for (size_t i = 0; i < text.size();) {
        while (i < text.size() && is_space(text[i])) ++i;
        const size_t start = i;
        while (i < text.size() && !is_space(text[i])) ++i;
        if (i > start) words.push_back(text.substr(start, i - start));
    }
    return words;
}

}  // namespace

std::string quoted(const std::string &text) {
    constexpr size_t kShown = 40;
    if (text.size() <= kShown) return "'" + text + "'";
    size_t cut = kShown;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // whole characters
    return "'" + text.substr(0, cut) + "...'";
}

double parse_number(const std::string &text, const std::string &what) {
    size_t begin = 0, last = text.size();
    while (begin < last && is_space(text[begin])) ++begin;
    while (last > begin && is_space(text[last - 1])) --last;
    const std::string word = text.substr(begin, last - begin);
    const size_t end = decimal_end(word, 0);
    if (end == 0 || end != word.size()) throw_corrupt(what + " " + quoted(text) + " is not a number");
    const size_t digits = word[0] == '+' ? 1 : 0;  // from_chars takes no '+'
    double value = 0.0;
    const auto result = std::from_chars(word.data() + digits, word.data() + word.size(), value);
    if (result.ec != std::errc() || !std::isfinite(value))
        throw_corrupt(what + " " + quoted(text) + " is out of range");
    return value;
}

Vec3Text parse_vector3(const std::string &text, const std::string &what) {
    const std::vector<std::string> words = split_words(text);
    if (words.size() != 3)
        throw_corrupt(what + " " + quoted(text) + " has " + std::to_string(words.size()) + " numbers, not 3");
    return {parse_number(words[0], what), parse_number(words[1], what), parse_number(words[2], what)};
}

void check_magnitude(double value, double limit, const std::string &what) {
    if (std::fabs(value) > limit)
        throw_corrupt(what + " " + describe_number(value) + " is beyond +-" + describe_number(limit));
}

std::string format_number(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

std::string describe_number(double value) {
    char text[24];
    const auto fixed = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
    if (fixed.ec == std::errc()) return std::string(text, fixed.ptr);
    return format_number(value);
}

std::string format_vector3(const Vec3Text &v) {
    return format_number(v[0]) + " " + format_number(v[1]) + " " + format_number(v[2]);
}

}  // namespace octoprox
