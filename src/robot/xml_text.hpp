// What XML text must be before tinyxml reads it.  tinyxml steps over a
// UTF-8 sequence by the length its first byte announces, so a sequence cut
// by the end of the text makes it read past the terminating NUL; and it
// parses nested elements by recursion, one stack frame per level, so deep
// nesting overflows the stack.  Both are checked here on the raw text,
// before any parser sees it (urdfdom runs tinyxml too).
#pragma once

#include <cstddef>
#include <string>

namespace octoprox {

// Deeper element nesting is rejected; a URDF or SRDF nests about 6 deep.
constexpr size_t kMaxXmlDepth = 100;

// Throws ApiError(OPX_ERROR_CORRUPT) prefixed with `source` when `text`
// has a NUL byte, is not valid UTF-8 (RFC 3629), holds a byte order mark
// (U+FEFF) after its first byte or the non-characters U+FFFE, U+FFFF, or
// nests elements deeper than kMaxXmlDepth (as tinyxml would parse them),
// or has an XML declaration tinyxml may read differently by locale.
void check_xml_text(const std::string &text, const std::string &source);

// True when `text` is valid UTF-8 without NUL bytes; the offset of the
// first bad byte otherwise.
bool is_utf8(const std::string &text, size_t *bad_offset = nullptr);

// The deepest element nesting tinyxml reaches on `text` (valid UTF-8, no
// NUL) before it stops: an upper bound that may count elements
// after the point where tinyxml gives up, never fewer.  When the scan met
// a construct whose split tinyxml makes by locale, it stops there and sets
// *ambiguous to it (else to NULL): the depth is then no bound.
size_t xml_nesting_depth(const std::string &text, const char **ambiguous);

}  // namespace octoprox
