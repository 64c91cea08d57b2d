#include "robot/xml_text.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace octoprox {
namespace {

bool is_continuation(unsigned char byte) { return (byte & 0xC0) == 0x80; }

// Length of the valid UTF-8 sequence at s[i] (RFC 3629: no overlong forms,
// no surrogates, nothing above U+10FFFF), 0 when there is none.
size_t utf8_sequence_length(const std::string &s, size_t i) {
    const auto byte = [&](size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0; };
    const unsigned char lead = byte(0);
    if (lead >= 0x01 && lead <= 0x7F) return 1;
    size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) length = 2;
    else if (lead >= 0xE0 && lead <= 0xEF) length = 3, low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
    else if (lead >= 0xF0 && lead <= 0xF4) length = 4, low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
    else return 0;
    if (byte(1) < low || byte(1) > high) return 0;
    for (size_t k = 2; k < length; ++k)
        if (!is_continuation(byte(k))) return 0;
    return length;
}

// tinyxml skips EF BB BF, EF BF BE and EF BF BF as white space, but only
// once it has decided the text is UTF-8: where they stand would change how
// it splits the text, so only a leading byte order mark is allowed.
bool is_byte_order_mark_or_nonchar(const std::string &s, size_t i) {
    if (static_cast<unsigned char>(s[i]) != 0xEF || i + 2 >= s.size()) return false;
    const auto b1 = static_cast<unsigned char>(s[i + 1]), b2 = static_cast<unsigned char>(s[i + 2]);
    return (b1 == 0xBB && b2 == 0xBF) || (b1 == 0xBF && (b2 == 0xBE || b2 == 0xBF));
}

std::string byte_at(const std::string &text, size_t offset) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", offset < text.size() ? static_cast<unsigned char>(text[offset]) : 0u);
    return "byte offset " + std::to_string(offset) + " (" + hex + ")";
}

// The structure tinyxml 2.6 gives a text, followed step by step so that
// the nesting it reaches is known before it runs: the same node kinds in
// the same order (declaration, comment, CDATA, "<!" and other unknowns,
// elements), the same names, attribute values and ends.  Where tinyxml
// stops with an error this scan stops or goes on; it never skips what
// tinyxml would parse.  Iterative: depth costs no stack here.
class NestingScan {
public:
    // `text` is NUL terminated at text + size.
    NestingScan(const char *text, size_t size) : p_(text), end_(text + size) {}

    // The deepest nesting; `ambiguous()` tells when the scan stopped at a
    // construct tinyxml may split otherwise (see declaration()).
    size_t run() {
        if (starts_with("\xEF\xBB\xBF")) p_ += 3;
        for (;;) {
            skip_space();
            if (*p_ == '\0') break;
            if (*p_ != '<') {  // text: up to the next tag; none at the top level
                if (depth_ == 0) break;
                if (!move_to(p_, "<")) break;
                continue;
            }
            if (depth_ > 0 && p_[1] == '/') {  // an end tag closes the open element
                if (!skip_past(p_ + 2, ">")) break;
                --depth_;
                continue;
            }
            if (!node()) break;
        }
        return deepest_;
    }
    const char *ambiguous() const { return ambiguous_; }

private:
    static bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }
    static bool is_name_start(char c) {
        const auto u = static_cast<unsigned char>(c);
        return u >= 127 || std::isalpha(u) || c == '_';
    }
    static bool is_name_char(char c) {
        const auto u = static_cast<unsigned char>(c);
        return u >= 127 || std::isalnum(u) || c == '_' || c == '-' || c == '.' || c == ':';
    }
    static bool starts_with_ignoring_case(const char *p, const char *prefix) {
        for (; *prefix != '\0'; ++p, ++prefix)
            if (std::tolower(static_cast<unsigned char>(*p)) != *prefix) return false;
        return true;
    }

    void skip_space() {
        while (is_space(*p_)) ++p_;
    }
    bool starts_with(std::string_view prefix) const {
        return std::string_view(p_, end_ - p_).compare(0, prefix.size(), prefix) == 0;
    }
    // Moves to the first `token` at or after `from`; false when none.
    // (Searches are bounded by the known end: no strstr, which sanitizers
    // make scan the whole rest of the text at every call.)
    bool move_to(const char *from, std::string_view token) {
        const size_t found = std::string_view(from, end_ - from).find(token);
        if (found == std::string_view::npos) return false;
        p_ = from + found;
        return true;
    }
    // Moves just past the first `token` at or after `from`; false when none.
    bool skip_past(const char *from, std::string_view token) {
        if (!move_to(from, token)) return false;
        p_ += token.size();
        return true;
    }

    // At '<': one node, classified as tinyxml's Identify does.
    bool node() {
        if (starts_with_ignoring_case(p_, "<?xml")) return declaration();
        if (starts_with("<!--")) return skip_past(p_ + 4, "-->");
        if (starts_with("<![CDATA[")) return skip_past(p_ + 9, "]]>");
        if (is_name_start(p_[1])) return element_start();
        return skip_past(p_ + 1, ">");  // "<!DOCTYPE", "<?pi", stray "</": unknown
    }

    // "<name attributes" then "/>" (empty) or ">" (content follows).
    bool element_start() {
        ++p_;
        deepest_ = std::max(deepest_, ++depth_);
        while (is_name_char(*p_)) ++p_;
        for (;;) {
            skip_space();
            if (*p_ == '\0') return false;
            if (*p_ == '/') {
                if (p_[1] != '>') return false;
                p_ += 2, --depth_;
                return true;
            }
            if (*p_ == '>') return ++p_, true;
            if (!attribute()) return false;
        }
    }

    // name = "value" | 'value' | value (unquoted, up to space, '/' or '>').
    bool attribute() {
        if (!is_name_start(*p_)) return false;
        while (is_name_char(*p_)) ++p_;
        skip_space();
        if (*p_ != '=') return false;
        ++p_;
        skip_space();
        if (*p_ == '"' || *p_ == '\'') {
            return skip_past(p_ + 1, std::string_view(p_, 1)) && *p_ != '\0';
        }
        while (*p_ != '\0' && !is_space(*p_) && *p_ != '/' && *p_ != '>') {
            if (*p_ == '"' || *p_ == '\'') return false;
            ++p_;
        }
        return *p_ != '\0';
    }

    // "<?xml" up to the first '>' outside the values of version, encoding
    // and standalone; other words are skipped up to a space or '>'.
    // tinyxml matches those words with tolower(), which in a Turkish locale
    // does not take 'I' to 'i': a capital I in them is refused (the scan
    // stops as ambiguous) rather than guessed.
    bool declaration() {
        p_ += 5;
        while (*p_ != '\0') {
            if (*p_ == '>') return ++p_, true;
            skip_space();
            if (*p_ == '\0') return false;
            const char *keyword = declaration_keyword();
            if (keyword != nullptr) {
                if (std::string_view(p_, std::strlen(keyword)).find('I') != std::string_view::npos)
                    return ambiguous_ = p_, false;
                if (!attribute()) return false;
            } else {
                while (*p_ != '\0' && *p_ != '>' && !is_space(*p_)) ++p_;
            }
        }
        return false;
    }

    const char *declaration_keyword() const {
        for (const char *keyword : {"version", "encoding", "standalone"})
            if (starts_with_ignoring_case(p_, keyword)) return keyword;
        return nullptr;
    }

    const char *p_;
    const char *const end_;
    const char *ambiguous_ = nullptr;
    size_t depth_ = 0, deepest_ = 0;
};

}  // namespace

bool is_utf8(const std::string &text, size_t *bad_offset) {
    for (size_t i = 0; i < text.size();) {
        const size_t length = utf8_sequence_length(text, i);
        if (length == 0) {
            if (bad_offset != nullptr) *bad_offset = i;
            return false;
        }
        i += length;
    }
    return true;
}

size_t xml_nesting_depth(const std::string &text, const char **ambiguous) {
    NestingScan scan(text.c_str(), text.size());
    const size_t depth = scan.run();
    if (ambiguous != nullptr) *ambiguous = scan.ambiguous();
    return depth;
}

void check_xml_text(const std::string &text, const std::string &source) {
    size_t bad = 0;
    if (!is_utf8(text, &bad))
        throw_corrupt(source + ": " + byte_at(text, bad) +
                      (text[bad] == '\0' ? " is a NUL character" : " is not valid UTF-8") +
                      "; the text must be UTF-8 XML");
    for (size_t i = 1; i < text.size(); ++i)
        if (is_byte_order_mark_or_nonchar(text, i))
            throw_corrupt(source + ": " + byte_at(text, i) +
                          " starts U+FEFF, U+FFFE or U+FFFF, allowed only as a byte order mark at offset 0");
    if (is_byte_order_mark_or_nonchar(text, 0) && static_cast<unsigned char>(text[1]) != 0xBB)
        throw_corrupt(source + ": " + byte_at(text, 0) + " starts U+FFFE or U+FFFF, not a byte order mark");
    const char *ambiguous = nullptr;
    const size_t depth = xml_nesting_depth(text, &ambiguous);
    if (ambiguous != nullptr)
        throw_corrupt(source + ": " + byte_at(text, ambiguous - text.c_str()) +
                      ": an XML declaration spells a keyword with a capital I, which XML readers may split "
                      "differently by locale");
    if (depth > kMaxXmlDepth)
        throw_corrupt(source + ": its elements nest " + std::to_string(depth) + " deep; the limit is " +
                      std::to_string(kMaxXmlDepth));
}

}  // namespace octoprox
